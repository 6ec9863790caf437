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
#include "draco_ext/uv_seam_bit_model.h"

#include <algorithm>
#include <array>

#include "draco/core/macros.h"
#include "draco_ext/uv_fixed_point.h"

namespace draco {

namespace {

// Counts are halved when their sum exceeds these limits.
constexpr int kCountLimits[2] = {20, 2000};
// Mixer learning rate: weights move by input * error / 2^kLearningShift.
constexpr int kLearningShift = 10;
constexpr int kMaxStretch = 2047;
constexpr int32_t kMaxWeight = 1 << 22;

std::array<int16_t, 4096> MakeStretchTable() {
  std::array<int16_t, 4096> table;
  int next = 0;
  for (int x = -kMaxStretch; x <= kMaxStretch; ++x) {
    const int p = UvSeamSquash(x);
    for (int i = next; i <= p; ++i) {
      table[i] = static_cast<int16_t>(x);
    }
    next = p + 1;
  }
  for (int i = next; i < 4096; ++i) {
    table[i] = kMaxStretch;
  }
  return table;
}

// (n1 + 0.3) / (n0 + n1 + 0.6) in 1/4096, within [1, 4095].
int EstimateFromCounts(const uint16_t n[2]) {
  const int p = ((10 * n[1] + 3) << 12) / (10 * (n[0] + n[1]) + 6);
  return std::min(std::max(p, 1), 4095);
}

// UvSeamStretch(EstimateFromCounts(n)) for fast counters, from a table.
int StretchedFastEstimate(const uint16_t n[2]) {
  constexpr int kSide = kCountLimits[0] + 2;  // Counts stay below this.
  static const std::vector<int16_t> table = [] {
    std::vector<int16_t> values(kSide * kSide);
    for (uint16_t n0 = 0; n0 < kSide; ++n0) {
      for (uint16_t n1 = 0; n1 < kSide; ++n1) {
        const uint16_t counts[2] = {n0, n1};
        values[n0 * kSide + n1] =
            static_cast<int16_t>(UvSeamStretch(EstimateFromCounts(counts)));
      }
    }
    return values;
  }();
  DRACO_DCHECK(n[0] < kSide && n[1] < kSide);
  return table[n[0] * kSide + n[1]];
}

}  // namespace

int UvSeamSquash(int x) {
  static constexpr int kTable[33] = {
      1,    2,    3,    6,    10,   16,   27,   45,   73,   120,  194,
      310,  488,  747,  1101, 1546, 2047, 2549, 2994, 3348, 3607, 3785,
      3901, 3975, 4022, 4050, 4068, 4079, 4085, 4089, 4092, 4093, 4094};
  if (x > kMaxStretch) {
    return 4095;
  }
  if (x < -kMaxStretch) {
    return 1;
  }
  const int shifted = x + 2048;  // In [1, 4095]: no shifts of negatives.
  const int index = shifted >> 7;
  const int weight = shifted & 127;
  return (kTable[index] * (128 - weight) + kTable[index + 1] * weight + 64) >>
         7;
}

int UvSeamStretch(int probability) {
  static const std::array<int16_t, 4096> table = MakeStretchTable();
  DRACO_DCHECK(probability >= 0 && probability < 4096);
  return table[probability];
}

UvSeamBitModel::UvSeamBitModel(const std::vector<int> &num_contexts)
    : active_(num_contexts.size(), nullptr),
      inputs_(num_contexts.size() * kNumRates, 0),
      weights_(num_contexts.size() * kNumRates,
               static_cast<int32_t>(65536 / (num_contexts.size() * kNumRates))) {
  for (const int count : num_contexts) {
    tables_.emplace_back(count);
  }
}

uint32_t UvSeamBitModel::Predict(const int *contexts) {
  int64_t dot = 0;
  for (int model = 0; model < num_models(); ++model) {
    DRACO_DCHECK(contexts[model] >= 0 &&
                 contexts[model] < static_cast<int>(tables_[model].size()));
    active_[model] = &tables_[model][contexts[model]];
    for (int rate = 0; rate < kNumRates; ++rate) {
      const int input = model * kNumRates + rate;
      inputs_[input] = rate == 0 ? StretchedFastEstimate(active_[model]->n[0])
                                 : UvSeamStretch(EstimateFromCounts(
                                       active_[model]->n[rate]));
      dot += int64_t{weights_[input]} * inputs_[input];
    }
  }
  const int64_t x = ShiftRightTowardZero(dot, 16);
  probability_ = UvSeamSquash(static_cast<int>(
      std::min<int64_t>(std::max<int64_t>(x, -kMaxStretch - 1),
                        kMaxStretch + 1)));
  return static_cast<uint32_t>(probability_);
}

void UvSeamBitModel::Update(bool bit) {
  const int error = (bit ? 4096 : 0) - probability_;
  for (size_t input = 0; input < inputs_.size(); ++input) {
    const int64_t step =
        ShiftRightTowardZero(int64_t{inputs_[input]} * error, kLearningShift);
    weights_[input] = static_cast<int32_t>(std::min<int64_t>(
        std::max<int64_t>(weights_[input] + step, -kMaxWeight), kMaxWeight));
  }
  for (Cell *const cell : active_) {
    for (int rate = 0; rate < kNumRates; ++rate) {
      uint16_t *const n = cell->n[rate];
      ++n[bit];
      if (n[0] + n[1] > kCountLimits[rate]) {
        n[0] = (n[0] + 1) >> 1;
        n[1] = (n[1] + 1) >> 1;
      }
    }
  }
}

}  // namespace draco
