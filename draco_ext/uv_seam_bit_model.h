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

#include <cstdint>
#include <vector>

namespace draco {

// PAQ's squash: 4096 / (1 + e^-(x / 256)) for |x| < 2048, interpolated from
// a table, in [1, 4095].
int UvSeamSquash(int x);
// Inverse of UvSeamSquash() for probabilities in [0, 4095].
int UvSeamStretch(int probability);

class UvSeamBitModel {
 public:
  // |num_contexts|[i] is the number of contexts of model i.
  explicit UvSeamBitModel(const std::vector<int> &num_contexts);

  // P(next bit == 1) in 1/4096, within [1, 4095], for the context of each
  // model (|contexts|[i] < |num_contexts|[i]). Must be followed by Update().
  uint32_t Predict(const int *contexts);
  // Learns the bit that followed the last Predict().
  void Update(bool bit);

 private:
  static constexpr int kNumRates = 2;  // Fast and slow counters.
  // Bit counts n[rate][bit] of one context.
  struct Cell {
    uint16_t n[kNumRates][2] = {{0, 0}, {0, 0}};
  };

  int num_models() const { return static_cast<int>(tables_.size()); }

  std::vector<std::vector<Cell>> tables_;  // Per model, per context.
  std::vector<Cell *> active_;             // Cell of each model.
  std::vector<int> inputs_;                // Stretched estimates.
  std::vector<int32_t> weights_;           // 16.16 fixed point.
  int probability_ = 2048;                 // Last prediction.
};

}  // namespace draco

#endif  // DRACO_EXT_UV_SEAM_BIT_MODEL_H_
