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
// descent on coding cost. Models with many contexts keep them in a hashed
// table of 2^14 cells (128 KB), so memory does not grow with the context
// space.
#ifndef DRACO_EXT_SEAMS_UV_SEAM_BIT_MODEL_H_
#define DRACO_EXT_SEAMS_UV_SEAM_BIT_MODEL_H_

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "draco/core/macros.h"

namespace draco {

// PAQ's squash: 4096 / (1 + e^-(x / 256)) for |x| < 2048, interpolated from
// a table, in [1, 4095].
inline int UvSeamSquash(int x) {
  static constexpr int kTable[33] = {
      1,    2,    3,    6,    10,   16,   27,   45,   73,   120,  194,
      310,  488,  747,  1101, 1546, 2047, 2549, 2994, 3348, 3607, 3785,
      3901, 3975, 4022, 4050, 4068, 4079, 4085, 4089, 4092, 4093, 4094};
  if (x > 2047) {
    return 4095;
  }
  if (x < -2047) {
    return 1;
  }
  const int shifted = x + 2048;  // In [1, 4095]: no shifts of negatives.
  const int index = shifted >> 7;
  const int weight = shifted & 127;
  return (kTable[index] * (128 - weight) + kTable[index + 1] * weight + 64) >>
         7;
}
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

// The estimate of counts n0, n1: (n1 + 0.3) / (n0 + n1 + 0.6) in 1/4096,
// within [1, 4095].
inline int UvSeamEstimate(const uint16_t n[2]) {
  const int p = ((10 * n[1] + 3) << 12) / (10 * (n[0] + n[1]) + 6);
  return std::min(std::max(p, 1), 4095);
}

// UvSeamStretch() of every probability in [0, 4095].
const int16_t *UvSeamStretchTable();
// UvSeamStretch(UvSeamEstimate()) of fast counts n0, n1 at
// [n0 * kUvSeamFastSide + n1], where counts stay below kUvSeamFastSide.
constexpr int kUvSeamFastSide = UvSeamCounts::kLimits[0] + 2;
const int16_t *UvSeamFastStretchTable();

// Models with more contexts than 2^kUvSeamMaxTableBits use a hashed table of
// that size (Fibonacci hashing; collisions merge statistics, identically in
// encoder and decoder).
constexpr int kUvSeamMaxTableBits = 14;

template <int kNumModels>
class UvSeamBitModel {
 public:
  // |num_contexts|[i] is the number of contexts of model i.
  explicit UvSeamBitModel(const std::array<int, kNumModels> &num_contexts) {
    for (int model = 0; model < kNumModels; ++model) {
      const bool hashed = num_contexts[model] > (1 << kUvSeamMaxTableBits);
      hashed_[model] = hashed;
      tables_[model].resize(hashed ? 1 << kUvSeamMaxTableBits
                                   : num_contexts[model]);
    }
    weights_.fill(65536 / kNumInputs);
  }

  // P(next bit == 1) in 1/4096, within [1, 4095], for the context of each
  // model (|contexts|[i] < |num_contexts|[i]). Must be followed by Update().
  uint32_t Predict(const std::array<int, kNumModels> &contexts) {
    int64_t dot = 0;
    for (int model = 0; model < kNumModels; ++model) {
      const uint32_t context = static_cast<uint32_t>(contexts[model]);
      const uint32_t slot =
          hashed_[model] ? (context * 0x9E3779B1u) >> (32 - kUvSeamMaxTableBits)
                         : context;
      DRACO_DCHECK(slot < tables_[model].size());
      UvSeamCounts &counts = tables_[model][slot];
      active_[model] = &counts;
      int *const inputs = &inputs_[model * UvSeamCounts::kNumRates];
      inputs[0] =
          fast_table_[counts.n[0][0] * kUvSeamFastSide + counts.n[0][1]];
      inputs[1] = stretch_table_[UvSeamEstimate(counts.n[1])];
    }
    for (int input = 0; input < kNumInputs; ++input) {
      dot += int64_t{weights_[input]} * inputs_[input];
    }
    const int64_t x = dot / 65536;  // Rounds toward zero, like the step below.
    probability_ = UvSeamSquash(
        static_cast<int>(std::min<int64_t>(std::max<int64_t>(x, -2048), 2048)));
    return static_cast<uint32_t>(probability_);
  }

  // Learns the bit that followed the last Predict().
  void Update(bool bit) {
    const int error = (bit ? 4096 : 0) - probability_;
    for (int input = 0; input < kNumInputs; ++input) {
      const int64_t step =
          int64_t{inputs_[input]} * error / (int64_t{1} << kLearningShift);
      weights_[input] = static_cast<int32_t>(std::min<int64_t>(
          std::max<int64_t>(weights_[input] + step, -kMaxWeight), kMaxWeight));
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

  const int16_t *const stretch_table_ = UvSeamStretchTable();
  const int16_t *const fast_table_ = UvSeamFastStretchTable();
  std::array<std::vector<UvSeamCounts>, kNumModels> tables_;
  std::array<bool, kNumModels> hashed_;
  std::array<UvSeamCounts *, kNumModels> active_ = {};
  std::array<int, kNumInputs> inputs_ = {};  // Stretched estimates.
  std::array<int32_t, kNumInputs> weights_;  // 16.16 fixed point.
  int probability_ = 2048;                   // Last prediction.
};

}  // namespace draco

#endif  // DRACO_EXT_SEAMS_UV_SEAM_BIT_MODEL_H_
