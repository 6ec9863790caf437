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
#include "draco_ext/common/fixed_point.h"

#include <random>

#include "gtest/gtest.h"

namespace draco {
namespace {

TEST(UvFixedPointTest, RoundedDivideRoundsHalvesAwayFromZero) {
  EXPECT_EQ(RoundedDivide(5, 2), 3);
  EXPECT_EQ(RoundedDivide(-5, 2), -3);
  EXPECT_EQ(RoundedDivide(4, 3), 1);
  EXPECT_EQ(RoundedDivide(-4, 3), -1);
  EXPECT_EQ(RoundedDivide(5, 3), 2);
  EXPECT_EQ(RoundedDivide(-5, 3), -2);
  EXPECT_EQ(RoundedDivide(0, 7), 0);
}

TEST(UvFixedPointTest, RoundedDivideMatchesExactRationalRounding) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int64_t> num(-(int64_t{1} << 50),
                                             int64_t{1} << 50);
  std::uniform_int_distribution<int64_t> den(1, int64_t{1} << 30);
  for (int i = 0; i < 100000; ++i) {
    const int64_t n = num(rng), d = den(rng);
    const int64_t q = RoundedDivide(n, d);
    // |n - q d| <= d / 2, with ties resolved away from zero.
    const int64_t twice_error = 2 * (n - q * d);
    ASSERT_LE(twice_error, d);
    ASSERT_GE(twice_error, -d);
    if (twice_error == d) {
      ASSERT_LT(n, 0);
    }
    if (twice_error == -d) {
      ASSERT_GT(n, 0);
    }
  }
}

TEST(UvFixedPointTest, FloorDivideIsTheExactFloor) {
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int> bits(1, 61);
  for (int i = 0; i < 200000; ++i) {
    const uint64_t num = rng() >> (64 - bits(rng));
    const uint64_t den = std::max<uint64_t>(1, rng() >> (64 - bits(rng)));
    ASSERT_EQ(FloorDivide(num, den), num / den) << num << " / " << den;
  }
  const uint64_t max = (uint64_t{1} << 62) - 1;
  EXPECT_EQ(FloorDivide(max, 1), max);
  EXPECT_EQ(FloorDivide(max, 3), max / 3);
  EXPECT_EQ(FloorDivide(max, max), 1u);
  EXPECT_EQ(FloorDivide(0, 7), 0u);
}

TEST(UvFixedPointTest, RoundedShiftRoundsHalvesAwayFromZero) {
  for (int64_t x = -1000; x <= 1000; ++x) {
    EXPECT_EQ(RoundedShift(x, 3), RoundedDivide(x, 8)) << x;
  }
}

TEST(UvFixedPointTest, IntSqrtFloorIsTheExactFloor) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<uint64_t> value(0, (uint64_t{1} << 62) - 1);
  for (int i = 0; i < 100000; ++i) {
    const uint64_t v = i < 1000 ? static_cast<uint64_t>(i) : value(rng);
    const uint64_t root = IntSqrtFloor(v);
    ASSERT_LE(root * root, v) << v;
    ASSERT_GT((root + 1) * (root + 1), v) << v;
  }
}

TEST(UvFixedPointTest, BitLengthCountsSignificantBits) {
  EXPECT_EQ(BitLength(0), 0);
  EXPECT_EQ(BitLength(1), 1);
  EXPECT_EQ(BitLength(16383), 14);
  EXPECT_EQ(BitLength(16384), 15);
  EXPECT_EQ(BitLength(~uint64_t{0}), 64);
}

}  // namespace
}  // namespace draco
