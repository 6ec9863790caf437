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
// so every compiler, CPU and WebAssembly computes the same bits. Each
// function states the magnitudes it takes; the predictor brings its inputs
// there (once per mesh for the parents' values, per entry for the sums),
// so hostile data only weakens a prediction.
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

// For products below 2^62.
inline TangentVec3 Cross(const TangentVec3 &a, const TangentVec3 &b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
          a[0] * b[1] - a[1] * b[0]};
}

// For products and their sum below 2^63.
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

// |v|'s squared length, for components below 2^31 (so below 3 * 2^62).
inline uint64_t SquaredLength(const TangentVec3 &v) {
  return static_cast<uint64_t>(v[0] * v[0]) +
         static_cast<uint64_t>(v[1] * v[1]) +
         static_cast<uint64_t>(v[2] * v[2]);
}

// |v| scaled to kTangentUnit length (rounded), given its squared length
// |squared| > 0; components below 2^31. The length's rounding makes the
// result up to 1 / floor(|v|) too long; the direction is exact within
// 2^-24.
inline TangentVec3 ToUnitLength(const TangentVec3 &v, uint64_t squared) {
  // At least 1 and at least every |v[i]|, so |v[i]| * reciprocal <= 2^61.
  const int64_t length = static_cast<int64_t>(IntSqrtFloor(squared));
  const int64_t reciprocal = (int64_t{1} << 61) / length;
  constexpr int kShift = 61 - kTangentUnitBits;
  return {RoundedShiftHalfUp(v[0] * reciprocal, kShift),
          RoundedShiftHalfUp(v[1] * reciprocal, kShift),
          RoundedShiftHalfUp(v[2] * reciprocal, kShift)};
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

// |v| projected onto the plane of normal |n|: v - c n with c = (v . n) /
// |n|^2 in units of 2^-8, for components of |v| below 2^30 and of |n| below
// 2^12; the result's components stay below 2^31 and within |n| / 2^8 of
// the exact projection. |v| itself where |n| is zero.
inline TangentVec3 ProjectOntoPlane(const TangentVec3 &v,
                                    const TangentVec3 &n) {
  const int64_t squared = Dot(n, n);  // Below 3 * 2^24.
  if (squared == 0) {
    return v;
  }
  const int64_t along = Dot(v, n) * 256 / squared;  // Below 2^31 * 2^8.
  return {v[0] - along * n[0] / 256, v[1] - along * n[1] / 256,
          v[2] - along * n[2] / 256};
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
// p1 - p0 and |e2| = p2 - p0, components below 2^15, and |twice_area| > 0,
// the length of e1 x e2 (rounded down).
inline std::array<int32_t, 3> CornerAngles(const TangentVec3 &e1,
                                           const TangentVec3 &e2,
                                           uint64_t twice_area) {
  const TangentVec3 e3 = Subtract(e2, e1);
  return {DiamondAngle(twice_area, Dot(e1, e2)),
          DiamondAngle(twice_area, -Dot(e1, e3)),
          DiamondAngle(twice_area, Dot(e2, e3))};
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_TANGENT_TANGENT_GEOMETRY_H_
