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

namespace draco {

namespace {

constexpr int kMaxStretch = 2047;

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

const std::array<int16_t, 4096> &StretchTable() {
  static const std::array<int16_t, 4096> table = MakeStretchTable();
  return table;
}

// (n1 + 0.3) / (n0 + n1 + 0.6) in 1/4096, within [1, 4095].
int EstimateFromCounts(const uint16_t n[2]) {
  const int p = ((10 * n[1] + 3) << 12) / (10 * (n[0] + n[1]) + 6);
  return std::min(std::max(p, 1), 4095);
}

std::vector<int16_t> MakeFastTable() {
  std::vector<int16_t> values(kUvSeamFastSide * kUvSeamFastSide);
  for (uint16_t n0 = 0; n0 < kUvSeamFastSide; ++n0) {
    for (uint16_t n1 = 0; n1 < kUvSeamFastSide; ++n1) {
      const uint16_t counts[2] = {n0, n1};
      values[n0 * kUvSeamFastSide + n1] =
          static_cast<int16_t>(UvSeamStretch(EstimateFromCounts(counts)));
    }
  }
  return values;
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
  DRACO_DCHECK(probability >= 0 && probability < 4096);
  return StretchTable()[probability];
}

constexpr int UvSeamCounts::kLimits[];

const int16_t *UvSeamFastStretchTable() {
  static const std::vector<int16_t> table = MakeFastTable();
  return table.data();
}

int UvSeamSlowStretch(const uint16_t n[2]) {
  return UvSeamStretch(EstimateFromCounts(n));
}

}  // namespace draco
