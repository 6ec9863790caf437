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
#include "prediction_schemes/weighted/uv_stencil_geometry.h"

#include <random>

#include "gtest/gtest.h"

namespace draco {
namespace {

typedef UvStencilUv Uv;

// Positions must be non-negative: every test point is offset by 2^20.
UvStencilPos Pos(int64_t x, int64_t y, int64_t z) {
  constexpr int64_t kOffset = int64_t{1} << 20;
  return {static_cast<int32_t>(x + kOffset), static_cast<int32_t>(y + kOffset),
          static_cast<int32_t>(z + kOffset)};
}

// A 2x2 integer matrix and offset: uv = m * (a, b) + t.
struct AffineMap {
  int64_t m[2][2];
  Uv t;
  Uv Apply(int64_t a, int64_t b) const {
    return Uv(m[0][0] * a + m[0][1] * b + t[0],
              m[1][0] * a + m[1][1] * b + t[1]);
  }
};

Uv RoundQ16(const Uv &q16) {
  return Uv(RoundedDivide(q16[0], kUvStencilOne),
            RoundedDivide(q16[1], kUvStencilOne));
}

int64_t MaxAbsError(const Uv &a, const Uv &b) {
  return std::max(std::abs(a[0] - b[0]), std::abs(a[1] - b[1]));
}

// Planar stencils in a tilted plane spanned by integer vectors, with texture
// coordinates an integer affine function of the in-plane coordinates: the
// weighted parallelogram must reproduce the tip up to rounding.
TEST(UvStencilGeometryTest, AffinePredictionIsExactForAffineMapsOfAPlane) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-40, 40);
  std::uniform_int_distribution<int> coef(-30, 30);
  const int64_t origin[3] = {1000, -2000, 500}, u[3] = {3, 1, 2},
                v[3] = {-1, 4, 1};
  int tested = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    int64_t ab[4][2];
    for (auto &p : ab) {
      p[0] = coord(rng);
      p[1] = coord(rng);
    }
    // Adjacent triangles (L, R, B) and (L, R, O): O and B on opposite sides.
    const auto side = [&](int k) {
      return (ab[1][0] - ab[0][0]) * (ab[k][1] - ab[0][1]) -
             (ab[1][1] - ab[0][1]) * (ab[k][0] - ab[0][0]);
    };
    if (side(2) * side(3) >= 0) {
      continue;
    }
    const AffineMap map{{{coef(rng), coef(rng)}, {coef(rng), coef(rng)}},
                        Uv(5000, 7000)};
    UvStencilPos pos[4];
    Uv uv[4];
    for (int i = 0; i < 4; ++i) {
      pos[i] = Pos(origin[0] + u[0] * ab[i][0] + v[0] * ab[i][1],
                   origin[1] + u[1] * ab[i][0] + v[1] * ab[i][1],
                   origin[2] + u[2] * ab[i][0] + v[2] * ab[i][1]);
      uv[i] = map.Apply(ab[i][0], ab[i][1]);
    }
    // pos: L, R, O, B.
    UvStencilFrame frame;
    if (!ComputeUvStencilFrame(pos[0], pos[1], pos[2], pos[3], true, &frame) ||
        !frame.has_opposite) {
      continue;
    }
    ++tested;
    const Uv predicted =
        RoundQ16(PredictAffineQ16(frame, uv[0], uv[1] - uv[0], uv[3] - uv[0]));
    // The map scales unit steps by up to 60, so Q16 rounding of the frame
    // coefficients may shift the result by one quantum.
    EXPECT_LE(MaxAbsError(predicted, uv[2]), 1) << "trial " << trial;
  }
  EXPECT_GT(tested, 500);
}

// Two triangles folded by 90 degrees along the x axis: unfolding makes the
// stencil flat again, so a map that is affine on the developed surface is
// reproduced (the paper's "isometric fold").
TEST(UvStencilGeometryTest, AffinePredictionIsExactAcrossAFold) {
  const UvStencilPos l = Pos(0, 0, 0), r = Pos(120, 0, 0), b = Pos(40, 90, 0),
                     o = Pos(70, 0, 60);
  // Developed coordinates: B at (40, 90), O at (70, -60).
  const AffineMap map{{{2, -1}, {1, 3}}, Uv(100, 200)};
  UvStencilFrame frame;
  ASSERT_TRUE(ComputeUvStencilFrame(l, r, o, b, true, &frame));
  ASSERT_TRUE(frame.has_opposite);
  const Uv uv_l = map.Apply(0, 0);
  const Uv predicted = RoundQ16(PredictAffineQ16(
      frame, uv_l, map.Apply(120, 0) - uv_l, map.Apply(40, 90) - uv_l));
  EXPECT_EQ(predicted, map.Apply(70, -60));
}

// Without B, a similarity (rotation, uniform scale, translation) is exact
// when the orientation is right, and mirrored when it is not.
TEST(UvStencilGeometryTest, SimilarityPredictionIsExactForConformalMaps) {
  const UvStencilPos l = Pos(10, 20, 30), r = Pos(110, 20, 30),
                     o = Pos(50, 20, 110);
  // In-plane coordinates (x - 10, z - 30): O at (40, 80). UV = 3 * rot(30deg)
  // is not integral, so use a rotation by 90 degrees and scale 2.
  const AffineMap map{{{0, -2}, {2, 0}}, Uv(500, 500)};
  UvStencilFrame frame;
  ASSERT_TRUE(ComputeUvStencilFrame(l, r, o, Pos(0, 0, 0), false, &frame));
  EXPECT_FALSE(frame.has_opposite);
  const Uv uv_l = map.Apply(0, 0), uv_r = map.Apply(100, 0);
  const Uv expected = map.Apply(40, 80);
  // Triangle (O, L, R) in UV has positive area for this map and points.
  EXPECT_EQ(RoundQ16(PredictSimilarityQ16(frame, uv_l, uv_r - uv_l, 1)),
            expected);
  EXPECT_NE(RoundQ16(PredictSimilarityQ16(frame, uv_l, uv_r - uv_l, -1)),
            expected);
}

TEST(UvStencilGeometryTest, RejectsADegenerateEdge) {
  const UvStencilPos p = Pos(5, 5, 5);
  UvStencilFrame frame;
  EXPECT_FALSE(ComputeUvStencilFrame(p, p, Pos(9, 1, 2), Pos(1, 2, 3), true,
                                     &frame));
}

TEST(UvStencilGeometryTest, OppositeVertexOnTheEdgeLineIsNotUsed) {
  UvStencilFrame frame;
  ASSERT_TRUE(ComputeUvStencilFrame(Pos(0, 0, 0), Pos(10, 0, 0), Pos(3, 4, 0),
                                    Pos(25, 0, 0), true, &frame));
  EXPECT_FALSE(frame.has_opposite);
}

TEST(UvStencilGeometryTest, RejectsExtremeStencils) {
  // The tip is 1000 edge lengths away: its coefficient exceeds 64.
  UvStencilFrame frame;
  EXPECT_FALSE(ComputeUvStencilFrame(Pos(0, 0, 0), Pos(1, 0, 0),
                                     Pos(1000, 3, 0), Pos(0, -1, 0), true,
                                     &frame));
}

// The integer square root behind both heights is floor(sqrt(v)) for every
// radicand the frame can produce (below 2^62), around perfect squares too,
// where the double estimate is most likely off by one.
TEST(UvStencilGeometryTest, SquareRootIsExact) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 20000; ++trial) {
    const int bits = 1 + static_cast<int>(rng() % 62);
    const int64_t root = static_cast<int64_t>(rng() >> (64 - (bits + 1) / 2));
    for (const int64_t delta : {int64_t{-1}, int64_t{0}, int64_t{1}}) {
      const int64_t value = root * root + delta;
      if (value < 0 || value >= (int64_t{1} << 62)) {
        continue;
      }
      const int64_t r = uv_stencil_internal::SquareRoot(value);
      ASSERT_LE(r * r, value) << value;
      ASSERT_GT((r + 1) * (r + 1), value) << value;
    }
  }
}

// The frame depends on the stencil's shape, not its size: the same stencil
// scaled by 2^k gives the same coordinates up to rounding, also above 14-bit
// positions, where the edge vectors are scaled down before their products.
TEST(UvStencilGeometryTest, FrameIsScaleInvariant) {
  std::mt19937 rng(13);
  std::uniform_int_distribution<int> coord(0, 200);
  int compared = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    int64_t p[4][3];
    for (auto &v : p) {
      for (auto &c : v) {
        c = coord(rng);
      }
    }
    const auto frame_at = [&](int k, UvStencilFrame *frame) {
      UvStencilPos q[4];
      for (int i = 0; i < 4; ++i) {
        for (int c = 0; c < 3; ++c) {
          q[i][c] = static_cast<int32_t>(p[i][c] << k);
        }
      }
      return ComputeUvStencilFrame(q[0], q[1], q[2], q[3], true, frame);
    };
    UvStencilFrame small;
    if (!frame_at(0, &small) || !small.has_opposite ||
        std::abs(small.s) > 4 * kUvStencilOne || small.h < kUvStencilOne / 16 ||
        small.h > 4 * kUvStencilOne || small.height_ratio > 4 * kUvStencilOne) {
      continue;
    }
    ++compared;
    for (int k = 1; k <= 22; ++k) {
      UvStencilFrame large;
      ASSERT_TRUE(frame_at(k, &large)) << "trial " << trial << " k " << k;
      ASSERT_TRUE(large.has_opposite);
      // Exact while no scaling is needed; within 2^-6 of the edge length
      // once the vectors lose their low bits (the coordinates span 8 bits).
      const int tolerance = k <= 6 ? 1 : kUvStencilOne / 64;
      EXPECT_NEAR(large.s, small.s, tolerance) << trial << " " << k;
      EXPECT_NEAR(large.sb, small.sb, tolerance) << trial << " " << k;
      EXPECT_NEAR(large.h, small.h, tolerance) << trial << " " << k;
      EXPECT_NEAR(large.height_ratio, small.height_ratio,
                  small.height_ratio / 64 + tolerance)
          << trial << " " << k;
    }
  }
  EXPECT_GT(compared, 500);
}

// Largest supported inputs: 30-bit positions and UV differences just below
// 2^20. Every bounded stencil must produce predictions within the int64
// headroom the header documents (UBSan builds would flag any overflow).
TEST(UvStencilGeometryTest, ExtremeInputsStayWithinTheDocumentedBounds) {
  std::mt19937_64 rng(11);
  const int32_t max_pos = (int32_t{1} << 30) - 1;
  const int64_t max_uv = (int64_t{1} << kUvStencilMaxUvQuantizationBits) - 1;
  std::uniform_int_distribution<int32_t> pos_coord(0, max_pos);
  std::uniform_int_distribution<int64_t> uv_coord(0, max_uv);
  for (int trial = 0; trial < 5000; ++trial) {
    UvStencilPos p[4];
    for (auto &v : p) {
      v = {pos_coord(rng), pos_coord(rng), pos_coord(rng)};
    }
    UvStencilFrame frame;
    if (!ComputeUvStencilFrame(p[0], p[1], p[2], p[3], true, &frame)) {
      continue;
    }
    const Uv uv_l(uv_coord(rng), uv_coord(rng));
    const Uv uv_r(uv_coord(rng), uv_coord(rng));
    const Uv uv_b(uv_coord(rng), uv_coord(rng));
    const Uv similarity = PredictSimilarityQ16(frame, uv_l, uv_r - uv_l, 1);
    EXPECT_LT(std::abs(similarity[0]), int64_t{1} << 48);
    if (frame.has_opposite) {
      const Uv affine = PredictAffineQ16(frame, uv_l, uv_r - uv_l, uv_b - uv_l);
      EXPECT_LT(std::abs(affine[0]), int64_t{1} << 56);
      EXPECT_LT(std::abs(affine[1]), int64_t{1} << 56);
    }
  }
}

}  // namespace
}  // namespace draco
