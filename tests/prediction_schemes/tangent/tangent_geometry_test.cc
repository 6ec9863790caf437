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
#include "prediction_schemes/tangent/tangent_geometry.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "draco/compression/attributes/normal_compression_utils.h"
#include "draco/core/draco_test_base.h"

namespace draco {
namespace {

double Length(const TangentVec3 &v) {
  return std::sqrt(static_cast<double>(v[0]) * v[0] +
                   static_cast<double>(v[1]) * v[1] +
                   static_cast<double>(v[2]) * v[2]);
}

// Random vectors of every magnitude, 2^0 to 2^61.
TangentVec3 RandomVector(std::mt19937_64 *random) {
  const int bits = static_cast<int>((*random)() % 62);
  const int64_t limit = int64_t{1} << bits;
  TangentVec3 v;
  for (int64_t &c : v) {
    c = static_cast<int64_t>((*random)() % (2 * static_cast<uint64_t>(limit) + 1)) -
        limit;
  }
  return v;
}

TEST(TangentGeometryTest, NormalizeGivesUnitVectorsAlongTheInput) {
  std::mt19937_64 random(7);
  for (int i = 0; i < 20000; ++i) {
    const TangentVec3 v = RandomVector(&random);
    TangentVec3 unit;
    if (v == TangentVec3{0, 0, 0}) {
      EXPECT_FALSE(NormalizeToUnit(v, &unit));
      continue;
    }
    ASSERT_TRUE(NormalizeToUnit(v, &unit));
    EXPECT_NEAR(Length(unit), static_cast<double>(kTangentUnit),
                kTangentUnit * 4e-6);
    const double length = Length(v);
    for (int c = 0; c < 3; ++c) {
      // Within 2^-18 of the exact direction (the input is shifted below
      // 2^20 first).
      EXPECT_NEAR(unit[c] / static_cast<double>(kTangentUnit), v[c] / length,
                  4e-6);
    }
  }
}

TEST(TangentGeometryTest, NormalizeRejectsOnlyTheZeroVector) {
  TangentVec3 unit;
  EXPECT_FALSE(NormalizeToUnit({0, 0, 0}, &unit));
  EXPECT_TRUE(NormalizeToUnit({0, 0, 1}, &unit));
  EXPECT_EQ(unit, (TangentVec3{0, 0, kTangentUnit}));
  const int64_t big = (int64_t{1} << 62) - 1;
  EXPECT_TRUE(NormalizeToUnit({-big, big, -big}, &unit));
}

// Draco's own float decoding of every octahedral coordinate pair points
// where the exact integer vector points.
TEST(TangentGeometryTest, OctahedralVectorsAreDracosNormals) {
  for (const int bits : {2, 4, 7, 10}) {
    OctahedronToolBox toolbox;
    ASSERT_TRUE(toolbox.SetQuantizationBits(bits));
    const int32_t max_value = (1 << bits) - 2;
    for (int32_t s = 0; s <= max_value; ++s) {
      for (int32_t t = 0; t <= max_value; ++t) {
        float expected[3];
        toolbox.QuantizedOctahedralCoordsToUnitVector(s, t, expected);
        const TangentVec3 v = OctahedralToVector(s, t, bits);
        const double length = Length(v);
        ASSERT_GT(length, 0);
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(v[c] / length, expected[c], 1e-5)
              << "bits " << bits << " s " << s << " t " << t;
        }
      }
    }
  }
}

TEST(TangentGeometryTest, OctahedralCoordinatesOutsideTheMapAreClamped) {
  EXPECT_EQ(OctahedralToVector(-5, 3000, 10), OctahedralToVector(0, 1022, 10));
  EXPECT_EQ(OctahedralToVector(std::numeric_limits<int32_t>::max(),
                               std::numeric_limits<int32_t>::min(), 30),
            OctahedralToVector((1 << 30) - 2, 0, 30));
  EXPECT_EQ(OctahedralToVector(1, 1, 1), (TangentVec3{0, 0, 0}));
  EXPECT_EQ(OctahedralToVector(1, 1, 31), (TangentVec3{0, 0, 0}));
}

TEST(TangentGeometryTest, ProjectionIsPerpendicularToTheNormal) {
  std::mt19937_64 random(11);
  for (int i = 0; i < 20000; ++i) {
    const TangentVec3 v = RandomVector(&random);
    const TangentVec3 n = OctahedralToVector(
        static_cast<int32_t>(random() % 1023),
        static_cast<int32_t>(random() % 1023), 10);
    const TangentVec3 p = ProjectOntoPlane(v, n);
    TangentVec3 unit_p, unit_n;
    if (!NormalizeToUnit(p, &unit_p) || !NormalizeToUnit(n, &unit_n)) {
      continue;
    }
    EXPECT_LT(std::fabs(static_cast<double>(Dot(unit_p, unit_n))) /
                  (static_cast<double>(kTangentUnit) * kTangentUnit),
              1e-5);
  }
}

TEST(TangentGeometryTest, DiamondAngleIsExactAtMultiplesOfAQuarterPi) {
  constexpr int32_t kPi = 1 << kTangentAngleBits;
  EXPECT_EQ(DiamondAngle(0, 5), 0);
  EXPECT_EQ(DiamondAngle(7, 7), kPi / 4);
  EXPECT_EQ(DiamondAngle(9, 0), kPi / 2);
  EXPECT_EQ(DiamondAngle(7, -7), 3 * kPi / 4);
  EXPECT_EQ(DiamondAngle(0, -5), kPi);
  EXPECT_EQ(DiamondAngle(0, 0), 0);
}

TEST(TangentGeometryTest, DiamondAngleGrowsWithTheAngleWithinATolerance) {
  constexpr double kUnitsPerRadian = (1 << kTangentAngleBits) / M_PI;
  int32_t previous = -1;
  for (int degrees = 0; degrees <= 180; ++degrees) {
    const double angle = degrees * M_PI / 180;
    const uint64_t y =
        static_cast<uint64_t>(std::llround(std::sin(angle) * (1 << 30)));
    const int64_t x = std::llround(std::cos(angle) * (1 << 30));
    const int32_t diamond = DiamondAngle(y, x);
    EXPECT_GE(diamond, previous);
    EXPECT_NEAR(diamond / kUnitsPerRadian, angle, 0.075) << degrees;
    previous = diamond;
  }
}

// A triangle's three corner angles add up to pi, whatever its size, shape
// and position.
TEST(TangentGeometryTest, CornerAnglesAddUpToPi) {
  std::mt19937_64 random(3);
  constexpr int32_t kPi = 1 << kTangentAngleBits;
  for (int i = 0; i < 20000; ++i) {
    const int bits = 1 + static_cast<int>(random() % 29);
    const int64_t limit = int64_t{1} << bits;
    TangentVec3 e1, e2;
    for (int c = 0; c < 3; ++c) {
      e1[c] = static_cast<int64_t>(random() % (2 * limit)) - limit;
      e2[c] = static_cast<int64_t>(random() % (2 * limit)) - limit;
    }
    const TangentVec3 normal = Cross(e1, e2);
    const std::array<int32_t, 3> angles = CornerAngles(e1, e2, normal);
    if (normal == TangentVec3{0, 0, 0}) {
      EXPECT_EQ(angles, (std::array<int32_t, 3>{0, 0, 0}));
      continue;
    }
    const int32_t sum = angles[0] + angles[1] + angles[2];
    if (sum == 0) {
      continue;  // A needle whose area rounds away.
    }
    // Each diamond angle is within 0.072 radian of the truth.
    EXPECT_NEAR(sum, kPi, 3 * 0.072 * kPi / M_PI + 3);
  }
}

}  // namespace
}  // namespace draco
