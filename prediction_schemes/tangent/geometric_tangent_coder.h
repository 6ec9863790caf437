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
// How MESH_PREDICTION_GEOMETRIC_TANGENT turns a predicted unit tangent into
// predictions of Draco's quantised components, one after the other, each
// from the prediction and the components already coded.
//
// A unit tangent in the plane of a known normal has one degree of freedom,
// its angle in that plane; the prediction's error is mostly a turn in the
// plane (the bitangent direction), and a little out of it (the decoded
// normal's quantisation). So the components are coded in this order:
//   1. b1, the axis (other than b3) along which the bitangent is largest:
//      the prediction, rounded;
//   2. b2, the remaining axis: the prediction moved along the bitangent by
//      as much as b1's coded value says the tangent turned, scaled by a gain
//      that shrinks moves no bigger than b1's rounding (eq. (1) below);
//   3. b3, the axis along which the tangent is largest: whatever makes the
//      tangent unit length with b1 and b2 as coded, with the predicted sign;
//   4. w (handedness): the predicted orientation, as a symbol: 0 as
//      predicted, 1 the opposite sign, 2 + zig-zag(residual) anything else.
// Residuals go to UvResidualEncoder in contexts that separate the steps
// and, for the first two, how large the first residual was at the entry's
// neighbours already coded.
#ifndef PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_CODER_H_
#define PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_CODER_H_

#include <algorithm>
#include <array>
#include <cstdint>

#include "draco/core/decoder_buffer.h"
#include "draco/core/encoder_buffer.h"
#include "draco/core/varint_decoding.h"
#include "draco/core/varint_encoding.h"
#include "prediction_schemes/tangent/geometric_tangent_predictor.h"
#include "prediction_schemes/tangent/tangent_geometry.h"

namespace draco {

// Where Draco's quantisation puts a tangent: component c of a unit vector t
// becomes round(offset[c] + scale * t[c]) (both in units of 2^-16 of a
// quantisation step), clamped to [0, max_value]. Component 3 is w.
struct TangentGrid {
  static constexpr int kFractionBits = 16;
  // The largest scale the fixed-point products allow: 2^20 steps per unit
  // (tangents quantised to at most 21 bits).
  static constexpr int64_t kMaxScale = int64_t{1} << (20 + kFractionBits);
  static constexpr int64_t kMaxOffset = int64_t{1} << (31 + kFractionBits);

  std::array<int64_t, 4> offset = {0, 0, 0, 0};
  int64_t scale = 0;
  int32_t max_value = 0;

  bool IsValid() const {
    return scale > 0 && scale <= kMaxScale && max_value >= 0 &&
           max_value < (1 << 30) &&
           std::all_of(offset.begin(), offset.end(), [](int64_t o) {
             return o >= -kMaxOffset && o <= kMaxOffset;
           });
  }
  // The grid coordinate (units of 2^-16) of the unit component |t| on axis
  // |c|; |t| up to 2^25.
  int64_t Coordinate(int c, int64_t t) const {
    return offset[c] + RoundedShiftHalfUp(t * scale, kTangentUnitBits);
  }
  // The grid value nearest to |coordinate| (below 2^61).
  int32_t Round(int64_t coordinate) const {
    return static_cast<int32_t>(std::clamp<int64_t>(
        RoundedShiftHalfUp(coordinate, kFractionBits), 0, max_value));
  }
  // The unit component (kTangentUnit) that grid value |value| on axis |c|
  // stands for, within [-2, 2], rounded toward zero.
  int64_t UnitComponent(int c, int32_t value) const {
    const int64_t distance =
        std::clamp<int64_t>((int64_t{value} << kFractionBits) - offset[c],
                            -2 * scale, 2 * scale);
    return distance * kTangentUnit / scale;
  }

  void Encode(EncoderBuffer *buffer) const {
    EncodeVarint<uint32_t>(static_cast<uint32_t>(max_value), buffer);
    EncodeVarint<uint64_t>(static_cast<uint64_t>(scale), buffer);
    for (const int64_t o : offset) {
      EncodeVarint<int64_t>(o, buffer);
    }
  }
  bool Decode(DecoderBuffer *buffer) {
    uint32_t max;
    uint64_t s;
    if (!DecodeVarint(&max, buffer) || !DecodeVarint(&s, buffer) ||
        s > static_cast<uint64_t>(kMaxScale)) {
      return false;
    }
    for (int64_t &o : offset) {
      if (!DecodeVarint(&o, buffer)) {
        return false;
      }
    }
    max_value = static_cast<int32_t>(std::min<uint32_t>(max, 1u << 30));
    scale = static_cast<int64_t>(s);
    return IsValid();
  }
};

// Residual contexts (a UvResidualEncoder of kTangentNumContexts). The
// first component's split by the neighbour class (TangentNeighbourClass())
// and the fraction class (TangentPredictedValue), the second's by whether
// the neighbours had any first residual and the fraction class, the
// third's by the fraction class.
constexpr int kTangentFirstContext = 0;    // + 2 * neighbour + fraction.
constexpr int kTangentSecondContext = 6;   // + 2 * (neighbour > 0) + fraction.
constexpr int kTangentThirdContext = 10;   // + fraction.
constexpr int kTangentHandednessContext = 12;
// Entries without a prediction, every component.
constexpr int kTangentFallbackContext = 13;
// Entries whose only triangle gave a coded neighbour its value, every
// component (exporters that write one tangent per triangle).
constexpr int kTangentCopyContext = 14;
constexpr int kTangentNumContexts = 15;
constexpr int kTangentNumNeighbourClasses = 3;

// A predicted grid value with what the continuous prediction says about its
// residual: the side of the value the prediction lies on (the coder codes
// |sign| * residual, so that a residual towards the prediction is positive)
// and whether the prediction lies within a quarter step of the value
// (fraction class 0) or nearer to the next one (1).
struct TangentPredictedValue {
  int32_t value = 0;
  int32_t sign = 1;
  int fraction_class = 0;
};

// Per-attribute choices of the sequential coding.
struct TangentCodingParameters {
  TangentGrid grid;
  // Whether w is the opposite of the UV orientation (glTF's V axis points
  // down, so MikkTSpace's sign is inverted in the files' own UVs).
  bool flip_handedness = false;
  // The gain of step 2 in 1/256: 256 moves b2 fully with b1's residual.
  int32_t shift_gain = 0;
  // Neighbour sums (TangentNeighbourSum()) up to [0] are class 0, up to
  // [1] class 1, above class 2.
  std::array<uint8_t, 2> neighbour_thresholds = {0, 2};
};

// The predictions of one entry's components, in coding order. Usage, for an
// entry with a valid prediction: Begin(), then First(), Second() and
// Third() for the components of axes Axis(0), Axis(1) and Axis(2), each
// given the values coded before, then the handedness through
// PredictHandedness().
class TangentComponentPredictor {
 public:
  explicit TangentComponentPredictor(const TangentCodingParameters &params)
      : grid_(params.grid),
        gain_(params.shift_gain),
        flip_handedness_(params.flip_handedness),
        handedness_{params.grid.Round(params.grid.Coordinate(3, kTangentUnit)),
                    params.grid.Round(
                        params.grid.Coordinate(3, -kTangentUnit))} {}

  void Begin(const GeometricTangentPrediction &prediction) {
    const TangentVec3 &t = prediction.tangent;
    const TangentVec3 &b = prediction.bitangent;
    const uint64_t t0 = AbsAsUnsigned(t[0]), t1 = AbsAsUnsigned(t[1]),
                   t2 = AbsAsUnsigned(t[2]);
    const int b3 = t1 > t0 ? (t2 > t1 ? 2 : 1) : (t2 > t0 ? 2 : 0);
    int b1 = b3 == 2 ? 0 : b3 + 1, b2 = b3 == 0 ? 2 : b3 - 1;
    if (AbsAsUnsigned(b[b2]) > AbsAsUnsigned(b[b1])) {
      std::swap(b1, b2);
    }
    axes_ = {b1, b2, b3};
    negative_third_ = t[b3] < 0;
    positive_handedness_ = (prediction.handedness > 0) != flip_handedness_;
    // The grid coordinates of t / |t|: |t[i]| <= length, so |t[i]| *
    // reciprocal <= scale * 2^25 <= 2^61.
    const int64_t reciprocal =
        (grid_.scale << kReciprocalBits) / prediction.length;
    for (int i = 0; i < 3; ++i) {
      coordinate_[i] = grid_.offset[i] +
                       RoundedShiftHalfUp(t[i] * reciprocal, kReciprocalBits);
    }
    // B[b2] / B[b1] in units of 2^-16 (B below 2^44), within [-1, 1] by the
    // choice of b1; 0 where B[b1] is too small (16 times smaller than B[b3])
    // to say how b1 turned.
    const uint64_t along = AbsAsUnsigned(b[b1]);
    ratio_ = along * 16 <= AbsAsUnsigned(b[b3]) || along == 0
                 ? 0
                 : (b[b2] * 65536) / b[b1];
  }
  int Axis(int step) const { return axes_[step]; }
  // The grid coordinate of the predicted tangent on axis |axis|.
  int64_t Coordinate(int axis) const { return coordinate_[axis]; }

  // The first component: the prediction, rounded.
  TangentPredictedValue First() const {
    return ValueAt(coordinate_[axes_[0]]);
  }
  // Eq. (1): the second component moved along the bitangent by gain * (v1
  // - c1) * B[b2] / B[b1], where v1 - c1 is how far the first component's
  // value |v1| lies from its predicted coordinate.
  TangentPredictedValue Second(int32_t v1) const {
    constexpr int64_t kMaxMove = int64_t{1} << 36;
    const int64_t moved = std::clamp<int64_t>(
        (int64_t{v1} << TangentGrid::kFractionBits) - coordinate_[axes_[0]],
        -kMaxMove, kMaxMove);
    const int64_t scaled = RoundedShiftHalfUp(moved * gain_, 8);
    return ValueAt(coordinate_[axes_[1]] +
                   RoundedShiftHalfUp(scaled * ratio_, 16));
  }
  // The third component that makes the tangent unit length with the values
  // |v1| and |v2| of the first two, with the predicted sign.
  TangentPredictedValue Third(int32_t v1, int32_t v2) const {
    const int64_t x1 = grid_.UnitComponent(axes_[0], v1);
    const int64_t x2 = grid_.UnitComponent(axes_[1], v2);
    const int64_t rest = kTangentUnit * kTangentUnit - x1 * x1 - x2 * x2;
    int64_t x3 = rest > 0 ? static_cast<int64_t>(
                                IntSqrtFloor(static_cast<uint64_t>(rest)))
                          : 0;
    if (negative_third_) {
      x3 = -x3;
    }
    return ValueAt(grid_.Coordinate(axes_[2], x3));
  }

  // The predicted w and its opposite.
  std::array<int32_t, 2> PredictHandedness() const {
    return positive_handedness_
               ? handedness_
               : std::array<int32_t, 2>{handedness_[1], handedness_[0]};
  }

 private:
  static constexpr int kReciprocalBits = 25;

  // The grid value nearest to |coordinate|, with its sign and fraction
  // class (TangentPredictedValue).
  TangentPredictedValue ValueAt(int64_t coordinate) const {
    TangentPredictedValue predicted;
    predicted.value = grid_.Round(coordinate);
    const int64_t fraction =
        coordinate - (int64_t{predicted.value} << TangentGrid::kFractionBits);
    predicted.sign = fraction < 0 ? -1 : 1;
    // |fraction| < 2^14 as one unsigned comparison.
    constexpr int64_t kQuarter = int64_t{1} << (TangentGrid::kFractionBits - 2);
    predicted.fraction_class =
        static_cast<uint64_t>(fraction + (kQuarter - 1)) < 2 * kQuarter - 1 ? 0
                                                                           : 1;
    return predicted;
  }

  const TangentGrid grid_;
  const int64_t gain_;
  const bool flip_handedness_;
  // The grid values of w = +1 and w = -1.
  const std::array<int32_t, 2> handedness_;
  std::array<int, 3> axes_ = {0, 1, 2};
  std::array<int64_t, 3> coordinate_ = {0, 0, 0};
  int64_t ratio_ = 0;
  bool negative_third_ = false;
  bool positive_handedness_ = true;
};

// The w symbol of value |w| given the predicted value and its opposite
// (TangentComponentPredictor::PredictHandedness()).
inline int32_t HandednessSymbol(int32_t w, const std::array<int32_t, 2> &predicted) {
  if (w == predicted[0]) {
    return 0;
  }
  if (w == predicted[1]) {
    return 1;
  }
  return 2 + static_cast<int32_t>(
                 ConvertSignedIntToSymbol(int64_t{w} - predicted[0]));
}

// The inverse of HandednessSymbol(); false for symbols no valid w has.
inline bool HandednessFromSymbol(int32_t symbol,
                                 const std::array<int32_t, 2> &predicted,
                                 int32_t max_value, int32_t *w) {
  if (symbol < 0) {
    return false;
  }
  if (symbol < 2) {
    *w = predicted[symbol];
    return true;
  }
  const int64_t value =
      int64_t{predicted[0]} +
      ConvertSymbolToSignedInt(static_cast<uint64_t>(symbol - 2));
  if (value < 0 || value > max_value) {
    return false;
  }
  *w = static_cast<int32_t>(value);
  return true;
}

// The bit lengths of the first residual at an entry's coded neighbours
// summed (-1: none coded), and its context class under |params|.
inline int TangentNeighbourSum(int first_bits, int second_bits) {
  if (first_bits < 0 && second_bits < 0) {
    return -1;
  }
  return std::max(first_bits, 0) + std::max(second_bits, 0);
}
inline int TangentNeighbourClass(int sum,
                                 const TangentCodingParameters &params) {
  if (sum < 0) {
    return 1;
  }
  return sum <= params.neighbour_thresholds[0]
             ? 0
             : (sum <= params.neighbour_thresholds[1] ? 1 : 2);
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_CODER_H_
