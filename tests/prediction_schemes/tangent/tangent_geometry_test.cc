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

TEST(TangentGeometryTest, ToUnitLengthGivesUnitVectorsAlongTheInput) {
  std::mt19937_64 random(7);
  for (int i = 0; i < 20000; ++i) {
    // Components below 2^31, as the predictor's.
    const int bits = static_cast<int>(random() % 31);
    const int64_t limit = int64_t{1} << bits;
    TangentVec3 v;
    for (int64_t &c : v) {
      c = static_cast<int64_t>(random() % (2 * static_cast<uint64_t>(limit) +
                                           1)) -
          limit;
    }
    const uint64_t squared = SquaredLength(v);
    if (squared == 0) {
      continue;
    }
    const TangentVec3 unit = ToUnitLength(v, squared);
    const double length = Length(v);
    // Up to 1 / floor(|v|) too long (the length is rounded down), never
    // shorter.
    EXPECT_GE(Length(unit), kTangentUnit * (1 - 4e-7));
    EXPECT_LE(Length(unit),
              kTangentUnit * (1 + 1 / std::floor(length) + 4e-7));
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(unit[c] / Length(unit), v[c] / length, 4e-7);
    }
  }
}

TEST(TangentGeometryTest, SquaredLengthHoldsTheLargestVectors) {
  const int64_t big = (int64_t{1} << 31) - 1;
  EXPECT_EQ(SquaredLength({-big, big, -big}),
            3 * static_cast<uint64_t>(big) * static_cast<uint64_t>(big));
  const TangentVec3 unit = ToUnitLength({-big, big, -big},
                                        SquaredLength({-big, big, -big}));
  EXPECT_NEAR(static_cast<double>(unit[0]), -kTangentUnit / std::sqrt(3.0),
              2);
  EXPECT_EQ(ToUnitLength({0, 0, 1}, 1), (TangentVec3{0, 0, kTangentUnit}));
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

// Vectors below 2^30 projected onto the planes of 12-bit octahedral
// normals (as the predictor shifts them) are perpendicular to the normal
// within the projection's rounding.
TEST(TangentGeometryTest, ProjectionIsPerpendicularToTheNormal) {
  std::mt19937_64 random(11);
  for (int i = 0; i < 20000; ++i) {
    TangentVec3 v;
    for (int64_t &c : v) {
      c = static_cast<int64_t>(random() % (int64_t{1} << 31)) -
          (int64_t{1} << 30) + 1;
    }
    const TangentVec3 n = OctahedralToVector(
        static_cast<int32_t>(random() % 4095),
        static_cast<int32_t>(random() % 4095), 12);
    const TangentVec3 p = ProjectOntoPlane(v, n);
    for (const int64_t c : p) {
      EXPECT_LT(AbsAsUnsigned(c), uint64_t{1} << 31);
    }
    if (Length(p) < 1 << 20) {
      continue;  // Nearly along the normal: the rounding dominates.
    }
    EXPECT_LT(std::fabs(static_cast<double>(Dot(p, n))) /
                  (Length(p) * Length(n)),
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
// and position (edges below 2^15, as the predictor's).
TEST(TangentGeometryTest, CornerAnglesAddUpToPi) {
  std::mt19937_64 random(3);
  constexpr int32_t kPi = 1 << kTangentAngleBits;
  for (int i = 0; i < 20000; ++i) {
    const int bits = 1 + static_cast<int>(random() % 14);
    const int64_t limit = int64_t{1} << bits;
    TangentVec3 e1, e2;
    for (int c = 0; c < 3; ++c) {
      e1[c] = static_cast<int64_t>(random() % (2 * limit)) - limit;
      e2[c] = static_cast<int64_t>(random() % (2 * limit)) - limit;
    }
    const uint64_t twice_area = IntSqrtFloor(SquaredLength(Cross(e1, e2)));
    if (twice_area == 0) {
      continue;
    }
    const std::array<int32_t, 3> angles = CornerAngles(e1, e2, twice_area);
    const int32_t sum = angles[0] + angles[1] + angles[2];
    // Each diamond angle is within 0.072 radian of the truth, and the
    // area's rounding adds 1 / twice_area of pi at most per corner.
    EXPECT_NEAR(sum, kPi,
                3 * 0.072 * kPi / M_PI + 3 + 3.0 * kPi / twice_area);
  }
}

}  // namespace
}  // namespace draco
