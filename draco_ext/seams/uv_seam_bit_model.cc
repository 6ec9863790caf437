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
#include "draco_ext/seams/uv_seam_bit_model.h"

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

std::vector<int16_t> MakeFastTable() {
  std::vector<int16_t> values(kUvSeamFastSide * kUvSeamFastSide);
  for (uint16_t n0 = 0; n0 < kUvSeamFastSide; ++n0) {
    for (uint16_t n1 = 0; n1 < kUvSeamFastSide; ++n1) {
      const uint16_t counts[2] = {n0, n1};
      values[n0 * kUvSeamFastSide + n1] =
          static_cast<int16_t>(UvSeamStretch(UvSeamEstimate(counts)));
    }
  }
  return values;
}

}  // namespace

const int16_t *UvSeamStretchTable() {
  static const std::array<int16_t, 4096> table = MakeStretchTable();
  return table.data();
}

int UvSeamStretch(int probability) {
  DRACO_DCHECK(probability >= 0 && probability < 4096);
  return UvSeamStretchTable()[probability];
}

const int16_t *UvSeamFastStretchTable() {
  static const std::vector<int16_t> table = MakeFastTable();
  return table.data();
}

}  // namespace draco
