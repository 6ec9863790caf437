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
// Integer geometry of one texture coordinate prediction stencil.
//
// Based on:
//   [Váša & Brunnett 2014] L. Váša, G. Brunnett: Efficient encoding of
//     texture coordinates guided by mesh geometry. Computer Graphics Forum
//     33(5) (SGP 2014), sections 3-4.
//   [Váša & Brunnett 2013] L. Váša, G. Brunnett: Exploiting connectivity to
//     improve the tangential part of geometry prediction. IEEE TVCG 19(9),
//     the weighted parallelogram.
//
// A stencil is the UV triangle (L, R, O) whose tip O is predicted from the
// decoded UVs of L and R, and optionally of B, the tip of the decoded UV
// triangle (L, R, B) across edge LR (Fig. 4 of [Váša & Brunnett 2014]). The
// 3D positions of all four vertices are known to the decoder.
//
// Unfolding the 3D triangles (L, R, B) and (L, R, O) into one plane across LR
// gives the tip O and the opposite vertex B the frame coordinates
//   s  = (e.d) / |e|^2,   h  = |e x d| / |e|^2   (O, on one side of LR)
//   sb = (e.b) / |e|^2,   hb = |e x b| / |e|^2   (B, on the other side)
// with e = R - L, d = O - L, b = B - L. Everything below is integer or
// fixed point (Q16) on quantised positions and texture coordinates, so that
// every build computes bit-identical predictions.
#ifndef PREDICTION_SCHEMES_WEIGHTED_UV_STENCIL_GEOMETRY_H_
#define PREDICTION_SCHEMES_WEIGHTED_UV_STENCIL_GEOMETRY_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "draco/core/vector_d.h"
#include "draco_ext/common/fixed_point.h"

namespace draco {

// Quantised positions, shifted to be non-negative and below 2^30.
typedef std::array<int32_t, 3> UvStencilPos;
typedef VectorD<int64_t, 2> UvStencilUv;

// Fixed-point format of stencil coefficients and of predictions.
constexpr int64_t kUvStencilOne = int64_t{1} << 16;
// Stencils whose coefficients exceed this magnitude (256.0) are rejected:
// they come from (nearly) degenerate triangles and would predict far away.
constexpr int64_t kUvStencilMaxCoefficient = int64_t{256} * kUvStencilOne;
// Squared edge lengths below this bound make every product below fit in 62
// bits; longer stencils (only above 14-bit positions) are scaled down first.
constexpr int64_t kUvStencilMaxSquaredLength = int64_t{1} << 30;
// Largest texture coordinate quantisation the arithmetic supports: UV
// differences stay below 2^20, all intermediate products below 2^62.
constexpr int kUvStencilMaxUvQuantizationBits = 20;
// Predictions are clamped to [-2^21, 2^22] texture units (Q16: |p| < 2^38),
// far outside any valid value, so that sums of up to 2^10 of them and their
// products with 14-bit weights stay below 2^63.
constexpr int64_t kUvStencilMinPredictionQ16 = -(int64_t{1} << 37);
constexpr int64_t kUvStencilMaxPredictionQ16 = int64_t{1} << 38;

// True when both components of a UV difference are within the supported
// range (below 2^kUvStencilMaxUvQuantizationBits in magnitude).
inline bool IsSupportedUvDifference(const UvStencilUv &d) {
  constexpr int64_t kLimit = int64_t{1} << kUvStencilMaxUvQuantizationBits;
  return d[0] < kLimit && d[0] > -kLimit && d[1] < kLimit && d[1] > -kLimit;
}

// The tip's unfolded coordinates: s and h of the tip O, sb and the height
// ratio h / hb of the opposite vertex B, all in Q16.
// Their magnitudes are at most 2^24 (coefficients are bounded by
// kUvStencilMaxCoefficient), and every product below widens them to 64 bits.
struct UvStencilFrame {
  int32_t s = 0;
  int32_t h = 0;
  int32_t sb = 0;
  int32_t height_ratio = 0;
  bool has_opposite = false;
};

namespace uv_stencil_internal {

// floor(x / 2^bits) for |x| < 2^62 and 0 < bits < 62: a shift of x + 2^62,
// which is non-negative, so no negative value is shifted.
inline int64_t FloorShift(int64_t x, int bits) {
  constexpr uint64_t kOffset = uint64_t{1} << 62;
  return static_cast<int64_t>((static_cast<uint64_t>(x) + kOffset) >> bits) -
         static_cast<int64_t>(kOffset >> bits);
}

// Edge vectors e = R - L, d = O - L, b = B - L and their dot products. When
// a squared length reaches kUvStencilMaxSquaredLength (only for positions
// of more than 14 bits), the vectors are divided (rounding down) by the
// power of two that leaves their largest component at most 2^14.
// Afterwards ee, dd, bb < 2^30, so ee * dd and ed^2 < 2^60.
struct EdgeVectors {
  int64_t e[3], d[3], b[3];
  int64_t ee, dd, bb, ed, eb;

  EdgeVectors(const UvStencilPos &l, const UvStencilPos &r,
              const UvStencilPos &o, const UvStencilPos &bp) {
    // Positions below 2^30: differences below 2^30, squares summed below
    // 2^62.
    for (int i = 0; i < 3; ++i) {
      e[i] = int64_t{r[i]} - l[i];
      d[i] = int64_t{o[i]} - l[i];
      b[i] = int64_t{bp[i]} - l[i];
    }
    SquaredLengths();
    if ((ee | dd | bb) >= kUvStencilMaxSquaredLength) {
      ScaleDown();
    }
    ed = Dot(e, d);
    eb = Dot(e, b);
  }

 private:
  static int64_t Dot(const int64_t *a, const int64_t *b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
  void SquaredLengths() {
    ee = Dot(e, e);
    dd = Dot(d, d);
    bb = Dot(b, b);
  }
  void ScaleDown() {
    uint64_t spread = 0;
    for (int i = 0; i < 3; ++i) {
      spread |= AbsAsUnsigned(e[i]) | AbsAsUnsigned(d[i]) | AbsAsUnsigned(b[i]);
    }
    // |x| < 2^(14 + shift), so floor(x / 2^shift) is within [-2^14, 2^14).
    const int shift = BitLength(spread) - 14;
    for (int i = 0; i < 3; ++i) {
      e[i] = FloorShift(e[i], shift);
      d[i] = FloorShift(d[i], shift);
      b[i] = FloorShift(b[i], shift);
    }
    SquaredLengths();
  }
};

// floor(sqrt(value)) for 0 <= value < 2^62, exact on every platform: the
// double square root is only an estimate, which integer comparisons
// correct (signed conversions: cheaper than IntSqrtFloor()'s unsigned ones).
inline int64_t SquareRoot(int64_t value) {
  int64_t root = static_cast<int64_t>(std::sqrt(static_cast<double>(value)));
  while (root * root > value) {
    --root;
  }
  while ((root + 1) * (root + 1) <= value) {
    ++root;
  }
  return root;
}

// round(x * 2^16 / den) with halves away from zero if its magnitude is at
// most kUvStencilMaxCoefficient, else false; |x| < 2^46, den > 0. Integer
// division truncates toward zero.
inline bool BoundedCoefficient(int64_t x, int64_t den, int32_t *out) {
  const int64_t num = x * kUvStencilOne;
  const int64_t half = den >> 1;
  const int64_t q = (num + (num < 0 ? -half : half)) / den;
  if (AbsAsUnsigned(q) > static_cast<uint64_t>(kUvStencilMaxCoefficient)) {
    return false;
  }
  *out = static_cast<int32_t>(q);
  return true;
}

// BoundedCoefficient() for x >= 0.
inline bool BoundedRatio(int64_t x, int64_t den, int32_t *out) {
  const uint64_t q = (static_cast<uint64_t>(x) * kUvStencilOne +
                      static_cast<uint64_t>(den >> 1)) /
                     static_cast<uint64_t>(den);
  if (q > static_cast<uint64_t>(kUvStencilMaxCoefficient)) {
    return false;
  }
  *out = static_cast<int32_t>(q);
  return true;
}

}  // namespace uv_stencil_internal

// Computes the unfolded frame of tip |o| over edge (|l|, |r|), with the
// opposite vertex |b| when |has_b|. Returns false when the edge is
// degenerate or a coefficient is out of bounds; has_opposite is false when B
// is missing, collinear with LR or out of bounds.
//
// |e x d| and |e x b| are square roots of Lagrange's identity
// |e x d|^2 = |e|^2 |d|^2 - (e.d)^2, exact in 64 bits (< 2^60). Both
// radicands are scaled by one power of four t so that the larger has about
// 60 bits; the roots hd, hb then carry about 30 significant bits whatever
// the stencil's size, and the t cancels in h / hb = hd / hb. Four rounded
// integer divisions give the Q16 coordinates.
inline bool ComputeUvStencilFrame(const UvStencilPos &l, const UvStencilPos &r,
                                  const UvStencilPos &o, const UvStencilPos &b,
                                  bool has_b, UvStencilFrame *frame) {
  using namespace uv_stencil_internal;
  const EdgeVectors v(l, r, o, has_b ? b : l);
  if (v.ee == 0) {
    return false;
  }
  const int64_t cd = v.ee * v.dd - v.ed * v.ed;
  const int64_t cb = has_b ? v.ee * v.bb - v.eb * v.eb : 0;
  // cd, cb < 2^60: t >= 0 and the scaled radicands stay below 2^61.
  const int t = (61 - BitLength(static_cast<uint64_t>(cd | cb))) / 2;
  const int64_t hd = SquareRoot(cd << (2 * t));
  // |ed|, hd < 2^31: numerators below 2^47; ee << t < 2^60.
  if (!BoundedCoefficient(v.ed, v.ee, &frame->s) ||
      !BoundedRatio(hd, v.ee << t, &frame->h)) {
    return false;
  }
  frame->has_opposite = false;
  if (cb > 0) {
    const int64_t hb = SquareRoot(cb << (2 * t));
    frame->has_opposite = BoundedCoefficient(v.eb, v.ee, &frame->sb) &&
                          BoundedRatio(hd, hb, &frame->height_ratio);
  }
  return true;
}

// round(x / 2^bits) with halves rounded up, for |x| < 2^61 and
// 0 < bits < 62.
inline int64_t RoundedShiftUp(int64_t x, int bits) {
  return uv_stencil_internal::FloorShift(x + (int64_t{1} << (bits - 1)), bits);
}

// Eq. (3) of [Váša & Brunnett 2014], the weighted parallelogram
//   v'O = w1 vL + w2 vR + (1 - w1 - w2) vB,
// with the weights of eq. (4) computed from the exact inner angles of the
// two 3D triangles. Those weights are O's barycentric coordinates with
// respect to (L, R, B) in the unfolded plane:
//   w3 = 1 - w1 - w2 = -h / hb,   w2 = s - w3 * sb,   w1 = 1 - w2 - w3,
// so the prediction is the unfolded pair of triangles mapped by the affine
// map that takes (L, R, B) to their UVs:
//   v'O = vL + s (vR - vL) - (h / hb) ((vB - vL) - sb (vR - vL)).
// Exact for every affine parameterisation of a flat region. Requires
// |frame.has_opposite|. Returns Q16 texture coordinates.
// |f| = vR - vL and |g| = vB - vL.
inline UvStencilUv PredictAffineQ16(const UvStencilFrame &frame,
                                    const UvStencilUv &uv_l,
                                    const UvStencilUv &f,
                                    const UvStencilUv &g) {
  UvStencilUv prediction;
  for (int i = 0; i < 2; ++i) {
    // |f|, |g| < 2^20 and coefficients <= 2^24 (Q16 of 256.0):
    //   g_q16 = g * 2^16 - sb * f < 2^45, reduced to Q8 (< 2^37) so that
    //   height_ratio * g_q8 < 2^61; the result stays below 2^54.
    const int64_t g_q16 = g[i] * kUvStencilOne - frame.sb * f[i];
    const int64_t g_q8 = RoundedShiftUp(g_q16, 8);
    const int64_t across_q16 = RoundedShiftUp(frame.height_ratio * g_q8, 8);
    prediction[i] = uv_l[i] * kUvStencilOne + frame.s * f[i] - across_q16;
  }
  return prediction;
}

// The conformal special case without B: the triangle (L, R, O) is mapped by
// a similarity, rotated by +90 degrees (|orientation| > 0) or -90 degrees,
//   v'O = vL + s (vR - vL) + orientation * h * rot90(vR - vL).
// |orientation| is the sign of the UV triangle (O, L, R)'s signed area,
// which for an orientation preserving chart is that of its neighbours.
// Returns Q16 texture coordinates.
// |f| = vR - vL.
inline UvStencilUv PredictSimilarityQ16(const UvStencilFrame &frame,
                                        const UvStencilUv &uv_l,
                                        const UvStencilUv &f,
                                        int orientation) {
  const UvStencilUv rot_f(-f[1], f[0]);
  const int64_t h = orientation > 0 ? frame.h : -frame.h;
  UvStencilUv prediction;
  for (int i = 0; i < 2; ++i) {
    prediction[i] = uv_l[i] * kUvStencilOne + frame.s * f[i] + h * rot_f[i];
  }
  return prediction;
}

// The classic parallelogram vL + vR - vB [Touma & Gotsman 1998], Q16.
inline UvStencilUv PredictParallelogramQ16(const UvStencilUv &uv_l,
                                           const UvStencilUv &uv_r,
                                           const UvStencilUv &uv_b) {
  return (uv_l + uv_r - uv_b) * kUvStencilOne;
}

// The midpoint of LR, for stencils without usable 3D geometry, Q16.
inline UvStencilUv PredictMidpointQ16(const UvStencilUv &uv_l,
                                      const UvStencilUv &uv_r) {
  return (uv_l + uv_r) * (kUvStencilOne / 2);
}

// The mean of |count| (<= 32) Q16 predictions summed in |sum|, rounded to
// texture units.
inline UvStencilUv UvMeanOfQ16(const UvStencilUv &sum, int count) {
  if (count == 1) {
    return UvStencilUv(RoundedShift(sum[0], 16), RoundedShift(sum[1], 16));
  }
  return UvStencilUv(
      RoundedShift(DivideBySmallCount(sum[0], count), 16),
      RoundedShift(DivideBySmallCount(sum[1], count), 16));
}

// Weight of a stencil by how well its weighted parallelogram |affine| and
// its similarity prediction agree (Q16 predictions):
//   w = 2^30 / (2^16 + |affine - similarity|^2),
// the distance in 1/256 texture units and capped at 2^24, so w <= 2^14. The
// division uses a 256-entry reciprocal table on the divisor's top 9 bits
// (relative error below 2^-8), which is plenty for a weight.
inline int64_t UvAgreementWeight(const UvStencilUv &affine,
                                 const UvStencilUv &similarity) {
  struct ReciprocalTable {
    ReciprocalTable() {
      for (int m = 0; m < 256; ++m) {
        value[m] = ((int64_t{1} << 38) + (256 + m) / 2) / (256 + m);
      }
    }
    int64_t value[256];
  };
  static const ReciprocalTable table;
  int64_t divisor = int64_t{1} << 16;
  for (int i = 0; i < 2; ++i) {
    const int64_t d =
        std::min<int64_t>(AbsAsUnsigned(affine[i] - similarity[i]) / 256,
                          int64_t{1} << 24);
    divisor += d * d;
  }
  // divisor = m * 2^k, m in [256, 512): 2^30 / divisor ~ 2^38 / m / 2^(k+8).
  const int k = BitLength(static_cast<uint64_t>(divisor)) - 9;
  const int64_t m = divisor >> k;
  return table.value[m - 256] >> (k + 8);
}

// Clamps a Q16 prediction to the range documented above.
inline UvStencilUv ClampPredictionQ16(UvStencilUv prediction) {
  for (int i = 0; i < 2; ++i) {
    prediction[i] =
        std::max(kUvStencilMinPredictionQ16,
                 std::min(kUvStencilMaxPredictionQ16, prediction[i]));
  }
  return prediction;
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_WEIGHTED_UV_STENCIL_GEOMETRY_H_
