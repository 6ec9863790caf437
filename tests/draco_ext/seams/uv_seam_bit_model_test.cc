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

#include <array>
#include <cstdint>

#include "gtest/gtest.h"

namespace draco {
namespace {

TEST(UvSeamBitModelTest, SquashAndStretchAreMonotoneInverses) {
  for (int x = -2047; x <= 2047; ++x) {
    EXPECT_LE(UvSeamSquash(x - 1), UvSeamSquash(x));
    EXPECT_EQ(UvSeamSquash(UvSeamStretch(UvSeamSquash(x))), UvSeamSquash(x))
        << x;
  }
  EXPECT_EQ(UvSeamSquash(0), 2047);
  for (int p = 1; p < 4096; ++p) {
    EXPECT_LE(UvSeamStretch(p - 1), UvSeamStretch(p));
  }
}

TEST(UvSeamBitModelTest, LearnsASkewedContextAndKeepsContextsApart) {
  UvSeamBitModel<1> model({2});
  for (int i = 0; i < 500; ++i) {
    const std::array<int, 1> rare = {0};
    model.Predict(rare);
    model.Update(i % 50 == 0);
    const std::array<int, 1> common = {1};
    model.Predict(common);
    model.Update(i % 2 == 0);
  }
  const std::array<int, 1> rare = {0};
  const uint32_t p_rare = model.Predict(rare);
  model.Update(false);
  const std::array<int, 1> common = {1};
  const uint32_t p_common = model.Predict(common);
  model.Update(false);
  EXPECT_LT(p_rare, 4096 / 20);
  EXPECT_GT(p_common, 4096 / 3);
  EXPECT_LT(p_common, 2 * 4096 / 3);
}

}  // namespace
}  // namespace draco
