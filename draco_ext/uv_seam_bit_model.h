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
// Adaptive probability of the next crease bit, in integer arithmetic only so
// that encoder and decoder agree on every platform (Draco's own adaptive
// coder, AdaptiveRAnsBitEncoder, uses double).
//
// Several context models each look the bit up in their own table, where two
// bit counters per context estimate P(1) with the Krichevsky-Trofimov-like
// rule (n1 + 0.3) / (n + 0.6): one counter forgets fast (counts halved
// above 20 bits), one slowly (above 2000), because seam density changes
// across a mesh. A logistic mixer (M. Mahoney, "Adaptive weighing of context
// models for lossless data compression", 2005; PAQ's integer squash and
// stretch) combines all estimates with weights trained online by gradient
// descent on coding cost.
#ifndef DRACO_EXT_UV_SEAM_BIT_MODEL_H_
#define DRACO_EXT_UV_SEAM_BIT_MODEL_H_

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "draco/core/macros.h"
#include "draco_ext/uv_fixed_point.h"

namespace draco {

// PAQ's squash: 4096 / (1 + e^-(x / 256)) for |x| < 2048, interpolated from
// a table, in [1, 4095].
int UvSeamSquash(int x);
// Inverse of UvSeamSquash() for probabilities in [0, 4095].
int UvSeamStretch(int probability);

// Bit counts of one context: n[rate][bit], fast rate first.
struct UvSeamCounts {
  static constexpr int kNumRates = 2;
  static constexpr int kLimits[kNumRates] = {20, 2000};  // Halving limits.
  uint16_t n[kNumRates][2] = {{0, 0}, {0, 0}};

  void Add(bool bit) {
    for (int rate = 0; rate < kNumRates; ++rate) {
      ++n[rate][bit];
      if (n[rate][0] + n[rate][1] > kLimits[rate]) {
        n[rate][0] = (n[rate][0] + 1) >> 1;
        n[rate][1] = (n[rate][1] + 1) >> 1;
      }
    }
  }
};

// UvSeamStretch() of the estimate of fast counts n0, n1 at
// [n0 * kUvSeamFastSide + n1], where counts stay below kUvSeamFastSide.
constexpr int kUvSeamFastSide = UvSeamCounts::kLimits[0] + 2;
const int16_t *UvSeamFastStretchTable();
// UvSeamStretch() of the estimate of slow counts.
int UvSeamSlowStretch(const uint16_t n[2]);

template <int kNumModels>
class UvSeamBitModel {
 public:
  // |num_contexts|[i] is the number of contexts of model i.
  explicit UvSeamBitModel(const std::array<int, kNumModels> &num_contexts) {
    for (int model = 0; model < kNumModels; ++model) {
      tables_[model].resize(num_contexts[model]);
    }
    weights_.fill(65536 / kNumInputs);
  }

  // P(next bit == 1) in 1/4096, within [1, 4095], for the context of each
  // model (|contexts|[i] < |num_contexts|[i]). Must be followed by Update().
  uint32_t Predict(const std::array<int, kNumModels> &contexts) {
    int64_t dot = 0;
    for (int model = 0; model < kNumModels; ++model) {
      DRACO_DCHECK(contexts[model] >= 0 &&
                   contexts[model] < static_cast<int>(tables_[model].size()));
      const UvSeamCounts &counts = tables_[model][contexts[model]];
      active_[model] = &tables_[model][contexts[model]];
      int *const inputs = &inputs_[model * UvSeamCounts::kNumRates];
      inputs[0] =
          fast_table_[counts.n[0][0] * kUvSeamFastSide + counts.n[0][1]];
      inputs[1] = UvSeamSlowStretch(counts.n[1]);
    }
    for (int input = 0; input < kNumInputs; ++input) {
      dot += int64_t{weights_[input]} * inputs_[input];
    }
    const int64_t x = ShiftRightTowardZero(dot, 16);
    probability_ = UvSeamSquash(static_cast<int>(
        std::min<int64_t>(std::max<int64_t>(x, -2048), 2048)));
    return static_cast<uint32_t>(probability_);
  }

  // Learns the bit that followed the last Predict().
  void Update(bool bit) {
    const int error = (bit ? 4096 : 0) - probability_;
    for (int input = 0; input < kNumInputs; ++input) {
      const int64_t step = ShiftRightTowardZero(
          int64_t{inputs_[input]} * error, kLearningShift);
      weights_[input] = static_cast<int32_t>(std::min<int64_t>(
          std::max<int64_t>(weights_[input] + step, -kMaxWeight),
          kMaxWeight));
    }
    for (UvSeamCounts *const counts : active_) {
      counts->Add(bit);
    }
  }

 private:
  static constexpr int kNumInputs = kNumModels * UvSeamCounts::kNumRates;
  // Mixer learning rate: weights move by input * error / 2^kLearningShift.
  static constexpr int kLearningShift = 10;
  static constexpr int32_t kMaxWeight = 1 << 22;  // 64 in 16.16.

  const int16_t *const fast_table_ = UvSeamFastStretchTable();
  std::array<std::vector<UvSeamCounts>, kNumModels> tables_;
  std::array<UvSeamCounts *, kNumModels> active_ = {};
  std::array<int, kNumInputs> inputs_ = {};     // Stretched estimates.
  std::array<int32_t, kNumInputs> weights_;     // 16.16 fixed point.
  int probability_ = 2048;                      // Last prediction.
};

}  // namespace draco

#endif  // DRACO_EXT_UV_SEAM_BIT_MODEL_H_
