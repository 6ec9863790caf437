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
// Fixed-point 3D vectors for the geometric tangent prediction: unit vectors
// with kTangentUnitBits fractional bits, Draco's octahedral normal decoding
// in integers, and corner angles. Integer operations only (fixed_point.h),
// so every compiler, CPU and WebAssembly computes the same bits; every
// function takes any int64 input whose components stay below 2^62 in
// magnitude and shifts it down before multiplying, so hostile data only
// weakens a prediction.
//
// Based on:
//   [Mikkelsen 2008] M. Mikkelsen: Simulation of wrinkled surfaces
//     revisited. MSc thesis, University of Copenhagen (MikkTSpace: per-corner
//     tangents weighted by the corner angle).
//   [Cigolle et al. 2014] Z. H. Cigolle, S. Donow, D. Evangelakos, M. Mara,
//     M. McGuire, Q. Meyer: A survey of efficient representations for
//     independent unit vectors. JCGT 3(2) (the octahedral map, as Draco's
//     normal_compression_utils.h implements it).
#ifndef PREDICTION_SCHEMES_TANGENT_TANGENT_GEOMETRY_H_
#define PREDICTION_SCHEMES_TANGENT_TANGENT_GEOMETRY_H_

#include <algorithm>
#include <array>
#include <cstdint>

#include "draco_ext/common/fixed_point.h"

namespace draco {

// Unit vectors have this many fractional bits.
constexpr int kTangentUnitBits = 24;
constexpr int64_t kTangentUnit = int64_t{1} << kTangentUnitBits;
// Corner angles are in units of pi / 2^kTangentAngleBits (at most pi).
constexpr int kTangentAngleBits = 12;

using TangentVec3 = std::array<int64_t, 3>;

// A number with the bit length of the largest component's magnitude.
inline uint64_t MaxAbsBits(const TangentVec3 &v) {
  return AbsAsUnsigned(v[0]) | AbsAsUnsigned(v[1]) | AbsAsUnsigned(v[2]);
}

// How far values whose magnitudes OR to |bits_of| must be shifted right to
// stay below 2^|bits|.
inline int ShiftBelow(uint64_t bits_of, int bits) {
  return std::max(0, BitLength(bits_of) - bits);
}

inline TangentVec3 ShiftRight(const TangentVec3 &v, int shift) {
  if (shift == 0) {
    return v;
  }
  return {ShiftRightTowardZero(v[0], shift), ShiftRightTowardZero(v[1], shift),
          ShiftRightTowardZero(v[2], shift)};
}

inline TangentVec3 Subtract(const TangentVec3 &a, const TangentVec3 &b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

// For components below 2^30.
inline TangentVec3 Cross(const TangentVec3 &a, const TangentVec3 &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
          a[0] * b[1] - a[1] * b[0]};
}

// For components below 2^30.
inline int64_t Dot(const TangentVec3 &a, const TangentVec3 &b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// |v| scaled by a power of two so that its largest component has exactly
// |bits| bits (shifted right toward zero, or multiplied); the zero vector
// stays zero.
inline TangentVec3 ScaleToBits(const TangentVec3 &v, int bits) {
  const int length = BitLength(MaxAbsBits(v));
  if (length >= bits) {
    return ShiftRight(v, length - bits);
  }
  const int64_t factor = int64_t{1} << (bits - length);
  return {v[0] * factor, v[1] * factor, v[2] * factor};
}

// The unit vector (kTangentUnit long) along |v|; false for the zero vector.
// |v| is scaled to 20 bits first, which keeps its direction within 2^-18,
// so that one division gives all three components.
inline bool NormalizeToUnit(const TangentVec3 &v, TangentVec3 *unit) {
  const TangentVec3 w = ScaleToBits(v, 20);
  const uint64_t squared = static_cast<uint64_t>(Dot(w, w));
  if (squared == 0) {
    return false;
  }
  // |w[i]| <= length, so |w[i]| * reciprocal <= 2^62.
  const int64_t length = static_cast<int64_t>(IntSqrtFloor(squared));
  const int64_t reciprocal = (int64_t{1} << 62) / length;
  for (int i = 0; i < 3; ++i) {
    (*unit)[i] = RoundedShift(w[i] * reciprocal, 62 - kTangentUnitBits);
  }
  return true;
}

// The normal that Draco's octahedral coordinates (|s|, |t|) with
// |quantization_bits| encode, exactly, scaled by the map's max_value (so
// not unit length): OctahedronToolBox::
// QuantizedOctahedralCoordsToUnitVector() before its normalisation.
// Coordinates outside the map are clamped; the zero vector for bits outside
// Draco's range [2, 30].
inline TangentVec3 OctahedralToVector(int32_t s, int32_t t,
                                      int quantization_bits) {
  if (quantization_bits < 2 || quantization_bits > 30) {
    return {0, 0, 0};
  }
  const int64_t max_value = (int64_t{1} << quantization_bits) - 2;
  int64_t y = 2 * std::clamp<int64_t>(s, 0, max_value) - max_value;
  int64_t z = 2 * std::clamp<int64_t>(t, 0, max_value) - max_value;
  const int64_t x = max_value - (y < 0 ? -y : y) - (z < 0 ? -z : z);
  const int64_t x_offset = x < 0 ? -x : 0;
  y += y < 0 ? x_offset : -x_offset;
  z += z < 0 ? x_offset : -x_offset;
  return {x, y, z};
}

// |v| projected onto the plane of normal |n| and scaled by |n|^2:
// v |n|^2 - (v . n) n, exact for components of |v| below 2^30 and of |n|
// below 2^15 (shifted there first).
inline TangentVec3 ProjectOntoPlane(const TangentVec3 &v,
                                    const TangentVec3 &n) {
  const TangentVec3 a = ShiftRight(v, ShiftBelow(MaxAbsBits(v), 30));
  const TangentVec3 m = ShiftRight(n, ShiftBelow(MaxAbsBits(n), 15));
  const int64_t along = Dot(a, m);  // Below 3 * 2^45.
  const int64_t squared = Dot(m, m);  // Below 3 * 2^30.
  return {a[0] * squared - along * m[0], a[1] * squared - along * m[1],
          a[2] * squared - along * m[2]};
}

// A corner's angle from |y| >= 0, the length of the cross product of its
// two edges, and |x|, their dot product: the "diamond angle"
// (pi / 2) (1 - x / (|x| + y)) in units of pi / 2^kTangentAngleBits, which
// grows with the angle from 0 to pi and is exact at 0, pi / 4, pi / 2, 3 pi
// / 4 and pi, within 0.072 radian elsewhere: one division where an arctangent
// takes a polynomial and its quadrants. Inputs below 2^40.
inline int32_t DiamondAngle(uint64_t y, int64_t x) {
  constexpr int64_t kHalf = int64_t{1} << (kTangentAngleBits - 1);
  const int64_t sum = static_cast<int64_t>(AbsAsUnsigned(x) + y);
  if (sum == 0) {
    return 0;
  }
  return static_cast<int32_t>(kHalf - x * kHalf / sum);
}

// The corner angles (DiamondAngle()) of the triangle with edges |e1| =
// p1 - p0 and |e2| = p2 - p0 (components below 2^30) and normal |normal| =
// e1 x e2; zeros for a triangle without area.
inline std::array<int32_t, 3> CornerAngles(const TangentVec3 &e1,
                                           const TangentVec3 &e2,
                                           const TangentVec3 &normal) {
  const TangentVec3 e3 = Subtract(e2, e1);
  // The dot products (below 3 * 2^62) and the normal, scaled together so
  // that the larger has 30 bits: precise for small triangles, and the
  // normal's length and the dots below 2^32.
  const TangentVec3 dots = {Dot(e1, e2), -Dot(e1, e3), Dot(e2, e3)};
  const int length = BitLength(MaxAbsBits(dots) | MaxAbsBits(normal));
  const int shift = length - 30;
  TangentVec3 n = normal, x = dots;
  if (shift > 0) {
    n = ShiftRight(normal, shift);
    x = ShiftRight(dots, shift);
  } else if (shift < 0) {
    const int64_t factor = int64_t{1} << -shift;
    for (int i = 0; i < 3; ++i) {
      n[i] = normal[i] * factor;
      x[i] = dots[i] * factor;
    }
  }
  const uint64_t twice_area = IntSqrtFloor(static_cast<uint64_t>(Dot(n, n)));
  if (twice_area == 0) {
    return {0, 0, 0};
  }
  return {DiamondAngle(twice_area, x[0]), DiamondAngle(twice_area, x[1]),
          DiamondAngle(twice_area, x[2])};
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_TANGENT_TANGENT_GEOMETRY_H_
