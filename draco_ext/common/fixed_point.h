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
// Integer helpers for predictions that must decode bit-identically on every
// compiler, optimisation level and CPU. Only well-defined integer operations
// are used: no floating point, no shifts of negative values (implementation
// defined or undefined before C++20), divisions only by positive numbers.
#ifndef DRACO_EXT_COMMON_FIXED_POINT_H_
#define DRACO_EXT_COMMON_FIXED_POINT_H_

#include <cmath>
#include <cstdint>

namespace draco {

// |value| if it is not negative, -|value| otherwise; for values above
// INT64_MIN.
inline uint64_t AbsAsUnsigned(int64_t value) {
  return value < 0 ? 0 - static_cast<uint64_t>(value)
                   : static_cast<uint64_t>(value);
}

// Number of significant bits of |value| (0 for 0).
inline int BitLength(uint64_t value) {
#if defined(__GNUC__)
  return value == 0 ? 0 : 64 - __builtin_clzll(value);
#else
  int bits = 0;
  while (value != 0) {
    value /= 2;
    ++bits;
  }
  return bits;
#endif
}

// |value| / 2^|bits| rounded toward zero, for any sign (a shift of the
// magnitude: right shifts of negative values are implementation defined).
inline int64_t ShiftRightTowardZero(int64_t value, int bits) {
  return value < 0 ? -static_cast<int64_t>(AbsAsUnsigned(value) >> bits)
                   : value >> bits;
}

// floor(num / den) for den > 0 and num, den < 2^62, exact on every
// platform. A 64-bit integer division costs 40 to 90 cycles on many x86
// cores; the double quotient (within a few units of the truth for these
// magnitudes) is only an estimate, which integer products then correct, so
// the result is the mathematically defined integer.
inline uint64_t FloorDivide(uint64_t num, uint64_t den) {
  uint64_t q = static_cast<uint64_t>(static_cast<double>(num) /
                                     static_cast<double>(den));
  // q * den cannot overflow: q <= num / den + 2 and num < 2^62.
  while (q > 0 && q * den > num) {
    --q;
  }
  while (num - q * den >= den) {
    ++q;
  }
  return q;
}

// round(num / den) with halves rounded away from zero, for den > 0 and
// |num|, den < 2^62.
inline int64_t RoundedDivide(int64_t num, int64_t den) {
  const uint64_t magnitude = AbsAsUnsigned(num);
  const uint64_t divisor = static_cast<uint64_t>(den);
  uint64_t quotient = FloorDivide(magnitude, divisor);
  if (2 * (magnitude - quotient * divisor) >= divisor) {
    ++quotient;
  }
  return num < 0 ? -static_cast<int64_t>(quotient)
                 : static_cast<int64_t>(quotient);
}

// round(x / 2^bits) with halves away from zero, for 0 < bits < 63.
inline int64_t RoundedShift(int64_t x, int bits) {
  const int64_t rounded = static_cast<int64_t>(
      (AbsAsUnsigned(x) + (uint64_t{1} << (bits - 1))) >> bits);
  return x < 0 ? -rounded : rounded;
}

// round(x / 2^bits) with halves rounded up (floor(x / 2^bits + 1/2)), for
// |x| < 2^62 and 0 < bits < 62: the value biased to a non-negative one (no
// shift of a negative number) and shifted once, without a branch.
inline int64_t RoundedShiftHalfUp(int64_t x, int bits) {
  constexpr uint64_t kBias = uint64_t{1} << 62;
  return static_cast<int64_t>((static_cast<uint64_t>(x) + kBias +
                               (uint64_t{1} << (bits - 1))) >>
                              bits) -
         static_cast<int64_t>(kBias >> bits);
}

// round(a * b / 2^bits) with halves away from zero, for b >= 0, 0 < bits <
// 63 and |a| * b < 2^63: the fixed-point product with a precomputed
// reciprocal, which replaces a division.
inline int64_t MultiplyShiftRounded(int64_t a, int64_t b, int bits) {
  const uint64_t magnitude = AbsAsUnsigned(a) * static_cast<uint64_t>(b);
  const int64_t rounded = static_cast<int64_t>(
      (magnitude + (uint64_t{1} << (bits - 1))) >> bits);
  return a < 0 ? -rounded : rounded;
}

// x / n rounded toward zero, exactly like the built-in division. Divisors up
// to 32 (the counts this code divides by) are compile-time constants in
// their own case, which compilers turn into a multiplication.
inline int64_t DivideBySmallCount(int64_t x, int n) {
  switch (n) {
#define DRACO_UV_DIVIDE_CASE(k) \
  case k:                       \
    return x / k;
    DRACO_UV_DIVIDE_CASE(1) DRACO_UV_DIVIDE_CASE(2) DRACO_UV_DIVIDE_CASE(3)
    DRACO_UV_DIVIDE_CASE(4) DRACO_UV_DIVIDE_CASE(5) DRACO_UV_DIVIDE_CASE(6)
    DRACO_UV_DIVIDE_CASE(7) DRACO_UV_DIVIDE_CASE(8) DRACO_UV_DIVIDE_CASE(9)
    DRACO_UV_DIVIDE_CASE(10) DRACO_UV_DIVIDE_CASE(11) DRACO_UV_DIVIDE_CASE(12)
    DRACO_UV_DIVIDE_CASE(13) DRACO_UV_DIVIDE_CASE(14) DRACO_UV_DIVIDE_CASE(15)
    DRACO_UV_DIVIDE_CASE(16) DRACO_UV_DIVIDE_CASE(17) DRACO_UV_DIVIDE_CASE(18)
    DRACO_UV_DIVIDE_CASE(19) DRACO_UV_DIVIDE_CASE(20) DRACO_UV_DIVIDE_CASE(21)
    DRACO_UV_DIVIDE_CASE(22) DRACO_UV_DIVIDE_CASE(23) DRACO_UV_DIVIDE_CASE(24)
    DRACO_UV_DIVIDE_CASE(25) DRACO_UV_DIVIDE_CASE(26) DRACO_UV_DIVIDE_CASE(27)
    DRACO_UV_DIVIDE_CASE(28) DRACO_UV_DIVIDE_CASE(29) DRACO_UV_DIVIDE_CASE(30)
    DRACO_UV_DIVIDE_CASE(31) DRACO_UV_DIVIDE_CASE(32)
#undef DRACO_UV_DIVIDE_CASE
    default:
      return x / n;
  }
}

// floor(sqrt(value)) for value < 3 * 2^62 (roots below 2^31.8, so that
// the corrections' squares fit), exact on every platform: the double
// square root is only an estimate (within one of the truth for these
// values), which integer comparisons then correct, so the result is the
// mathematically defined integer whatever the floating point unit does.
inline uint64_t IntSqrtFloor(uint64_t value) {
  uint64_t root =
      static_cast<uint64_t>(std::sqrt(static_cast<double>(value)));
  while (root * root > value) {
    --root;
  }
  while ((root + 1) * (root + 1) <= value) {
    ++root;
  }
  return root;
}

}  // namespace draco

#endif  // DRACO_EXT_COMMON_FIXED_POINT_H_
