// Copyright 2026 The draco-uv Authors.
//
// Licensed under the Apache License, Version 2.0 (the "License");
// you may not use this file except in compliance with the License.
// You may obtain a copy of the License at
//
//      http://www.apache.org/licenses/LICENSE-2.0
//
// Unless required by applicable law or agreed to in writing, software
// distributed under the License is distributed on an "AS IS" BASIS,
// WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
// See the License for the specific language governing permissions and
// limitations under the License.
//
#include "prediction_schemes/tangent/geometric_tangent_chooser.h"

#include <algorithm>

#include "draco/core/varint_encoding.h"

namespace draco {

bool GeometricTangentChooser::Choose(
    const TangentConnectivity &connectivity,
    const GeometricTangentEncoderSettings &settings,
    GeometricTangentPredictor *predictor, const int32_t *values,
    int num_entries) {
  std::vector<GeometricTangentPrediction> predictions(num_entries);
  has_best_ = false;
  for (int k = 0; k < kNumGeometricTangentKinds; ++k) {
    const auto kind = static_cast<GeometricTangentKind>(k);
    if ((settings.kinds & GeometricTangentKindBit(kind)) == 0) {
      continue;
    }
    predictor->ComputeSums(connectivity, kind, settings.normal_bits);
    for (int entry = 0; entry < num_entries; ++entry) {
      predictions[entry] = predictor->Predict(connectivity, entry);
    }
    GeometricTangentConfig config;
    config.kind = kind;
    config.normal_bits = settings.normal_bits;
    config.coding = FitParameters(settings.grid, predictions, values);
    if (!TryConfig(connectivity, config, predictions, values)) {
      return false;
    }
  }
  return has_best_;
}

// The handedness follows the majority; the gain is eq. (2),
// 256 s^2 / (s^2 + 1/12) with s^2 the variance of the turn that b1's coded
// value shows beyond the 1/12 its rounding adds, in integer arithmetic so
// that every build chooses the same.
TangentCodingParameters GeometricTangentChooser::FitParameters(
    const TangentGrid &grid,
    const std::vector<GeometricTangentPrediction> &predictions,
    const int32_t *values) {
  TangentCodingParameters params;
  params.grid = grid;
  int64_t agree = 0, disagree = 0;
  uint64_t sum_squares = 0, count = 0;
  TangentComponentPredictor components(params);
  for (size_t entry = 0; entry < predictions.size(); ++entry) {
    const GeometricTangentPrediction &prediction = predictions[entry];
    if (!prediction.valid) {
      continue;
    }
    const int32_t *const v = values + kTangentNumComponents * entry;
    const bool positive = params.grid.UnitComponent(3, v[3]) > 0;
    (positive == (prediction.handedness > 0) ? agree : disagree) += 1;
    components.Begin(prediction);
    const int b1 = components.Axis(0);
    // In units of 2^-8 of a step, capped at 256 steps.
    const int64_t moved = std::clamp<int64_t>(
        RoundedShiftHalfUp((int64_t{v[b1]} << TangentGrid::kFractionBits) -
                         components.Coordinate(b1),
                     8),
        -(1 << 16), 1 << 16);
    sum_squares += static_cast<uint64_t>(moved * moved);
    ++count;
  }
  params.flip_handedness = disagree > agree;
  constexpr uint64_t kRoundingVariance = (1u << 16) / 12;
  const uint64_t variance = count > 0 ? sum_squares / count : 0;
  const uint64_t turn =
      variance > kRoundingVariance ? variance - kRoundingVariance : 0;
  params.shift_gain =
      static_cast<int32_t>(256 * turn / (turn + kRoundingVariance));
  return params;
}

std::array<uint8_t, 2> GeometricTangentChooser::NeighbourThresholds(
    const std::vector<int8_t> &sums) {
  std::array<uint64_t, 16> histogram = {};
  uint64_t total = 0;
  for (const int8_t sum : sums) {
    if (sum >= 0) {
      ++histogram[std::min<int>(sum, 15)];
      ++total;
    }
  }
  std::array<uint8_t, 2> thresholds = {0, 2};
  uint64_t seen = 0;
  int found = 0;
  for (int s = 0; s < 16 && found < 2; ++s) {
    seen += histogram[s];
    // The smallest sums with at least a third and two thirds at or below.
    while (found < 2 && 3 * seen >= (found + 1) * total) {
      thresholds[found++] = static_cast<uint8_t>(s);
    }
  }
  return thresholds;
}

bool GeometricTangentChooser::TryConfig(
    const TangentConnectivity &connectivity,
    const GeometricTangentConfig &config,
    const std::vector<GeometricTangentPrediction> &predictions,
    const int32_t *values) {
  const auto predict = [&](int entry) { return predictions[entry]; };
  // The encoder's coders only read the values.
  int32_t *const read_only = const_cast<int32_t *>(values);
  // A first pass for the neighbour sums, whose terciles become the
  // thresholds of the neighbour classes.
  GeometricTangentConfig tuned = config;
  std::vector<int8_t> sums(predictions.size(), -1);
  NullCoder null_coder;
  if (!CodeGeometricTangents(connectivity, config.coding, predict,
                             &null_coder, read_only, &sums)) {
    return false;
  }
  tuned.coding.neighbour_thresholds = NeighbourThresholds(sums);
  // Then the handedness and the copies as tokens or as exceptions,
  // whichever is smaller.
  Coder coder(static_cast<int>(predictions.size()) * kTangentNumComponents);
  if (!CodeGeometricTangents(connectivity, tuned.coding, predict, &coder,
                             read_only)) {
    return false;
  }
  for (int i = 0; i < kNumExceptionChoices; ++i) {
    tuned.handedness_exceptions = (i & 1) != 0;
    tuned.copy_exceptions = (i & 2) != 0;
    EncoderBuffer streams;
    if (!coder.Encode(i, &streams)) {
      return false;
    }
    if (!has_best_ || streams.size() < best_streams_.size()) {
      best_streams_.assign(streams.data(), streams.data() + streams.size());
      best_config_ = tuned;
      has_best_ = true;
    }
  }
  return true;
}

}  // namespace draco
