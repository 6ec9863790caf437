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
// What the encoder and the decoder of MESH_PREDICTION_GEOMETRIC_TANGENT
// share: the format, the parents, and the loop that codes every entry.
#ifndef PREDICTION_SCHEMES_TANGENT_MESH_PREDICTION_SCHEME_GEOMETRIC_TANGENT_SHARED_H_
#define PREDICTION_SCHEMES_TANGENT_MESH_PREDICTION_SCHEME_GEOMETRIC_TANGENT_SHARED_H_

#include <array>
#include <cstdint>
#include <vector>

#include "draco/attributes/geometry_attribute.h"
#include "draco/core/decoder_buffer.h"
#include "draco/core/encoder_buffer.h"
#include "draco/core/varint_decoding.h"
#include "draco/core/varint_encoding.h"
#include "prediction_schemes/tangent/geometric_tangent_coder.h"
#include "prediction_schemes/tangent/geometric_tangent_predictor.h"
#include "prediction_schemes/tangent/geometric_tangent_settings.h"

namespace draco {

// Version of the scheme's prediction data; decoders reject other values.
constexpr uint8_t kGeometricTangentFormatVersion = 1;
// x, y, z and the handedness w.
constexpr int kTangentNumComponents = 4;

// The parents, in the order Draco asks for them.
inline GeometryAttribute::Type GeometricTangentParentType(int i) {
  constexpr GeometryAttribute::Type kParents[] = {
      GeometryAttribute::POSITION, GeometryAttribute::NORMAL,
      GeometryAttribute::TEX_COORD};
  return kParents[i];
}
constexpr int kGeometricTangentNumParents = 3;

// Per-attribute choices the encoder makes and the decoder reads.
struct GeometricTangentConfig {
  GeometricTangentKind kind = GeometricTangentKind::kMikkTSpace;
  TangentCodingParameters coding;
  // Which TEX_COORD attribute the tangent follows (glTF: the normal
  // texture's texCoord). Draco hands a scheme the first attribute of each
  // parent type, so this format requires 0.
  int tex_coord_index = 0;
  // Octahedral bits of the normals (Draco's normal quantisation).
  int normal_bits = 0;
  // Whether the handedness, and the copies of kTangentCopyContext, are
  // coded as TangentExceptions instead of per-entry tokens.
  bool handedness_exceptions = false;
  bool copy_exceptions = false;

  void Encode(EncoderBuffer *buffer) const {
    buffer->Encode(static_cast<uint8_t>(
        static_cast<uint8_t>(kind) | (coding.flip_handedness ? 4 : 0) |
        (handedness_exceptions ? 8 : 0) | (copy_exceptions ? 16 : 0)));
    EncodeVarint<uint32_t>(static_cast<uint32_t>(tex_coord_index), buffer);
    buffer->Encode(static_cast<uint8_t>(normal_bits));
    buffer->Encode(static_cast<uint16_t>(coding.shift_gain));
    buffer->Encode(coding.neighbour_thresholds[0]);
    buffer->Encode(coding.neighbour_thresholds[1]);
    coding.grid.Encode(buffer);
  }
  // False for values no encoder writes.
  bool Decode(DecoderBuffer *buffer) {
    uint8_t byte, bits;
    uint32_t index;
    uint16_t gain;
    if (!buffer->Decode(&byte) || (byte & 3) >= kNumGeometricTangentKinds ||
        byte > 31 || !DecodeVarint(&index, buffer) || index != 0 ||
        !buffer->Decode(&bits) || bits < 2 || bits > 30 ||
        !buffer->Decode(&gain) || gain > 256 ||
        !buffer->Decode(&coding.neighbour_thresholds[0]) ||
        !buffer->Decode(&coding.neighbour_thresholds[1]) ||
        coding.neighbour_thresholds[0] > coding.neighbour_thresholds[1] ||
        !coding.grid.Decode(buffer)) {
      return false;
    }
    kind = static_cast<GeometricTangentKind>(byte & 3);
    coding.flip_handedness = (byte & 4) != 0;
    handedness_exceptions = (byte & 8) != 0;
    copy_exceptions = (byte & 16) != 0;
    tex_coord_index = 0;
    normal_bits = bits;
    coding.shift_gain = gain;
    return true;
  }
};

// The entries that GeometricTangentConfig's exception flags take out of the
// token streams, in entry order: entries whose handedness is not the
// predicted one, with their HandednessSymbol(), or whose copy is not exact.
// Most meshes have none or a few, where a token per entry costs its
// decoding however well it compresses. Stream: a varint count, then per
// entry a varint of its gap to the previous one and, for the handedness,
// one of its symbol minus 1.
class TangentExceptions {
 public:
  void Clear() {
    entries_.clear();
    symbols_.clear();
    next_ = 0;
  }
  void Add(int entry, int32_t symbol) {
    entries_.push_back(entry);
    symbols_.push_back(symbol);
  }
  void Encode(bool with_symbols, EncoderBuffer *buffer) const {
    EncodeVarint<uint32_t>(static_cast<uint32_t>(entries_.size()), buffer);
    int previous = -1;
    for (size_t i = 0; i < entries_.size(); ++i) {
      EncodeVarint<uint32_t>(static_cast<uint32_t>(entries_[i] - previous - 1),
                             buffer);
      previous = entries_[i];
      if (with_symbols) {
        EncodeVarint<uint32_t>(static_cast<uint32_t>(symbols_[i] - 1), buffer);
      }
    }
  }
  // False for entries beyond |num_entries| or symbols no w has.
  bool Decode(bool with_symbols, int num_entries, DecoderBuffer *buffer) {
    Clear();
    uint32_t count;
    if (!DecodeVarint(&count, buffer) ||
        count > static_cast<uint32_t>(num_entries)) {
      return false;
    }
    entries_.resize(count);
    symbols_.assign(count, 1);
    int64_t entry = -1;
    for (uint32_t i = 0; i < count; ++i) {
      uint32_t gap, symbol = 0;
      if (!DecodeVarint(&gap, buffer) ||
          (with_symbols &&
           (!DecodeVarint(&symbol, buffer) || symbol >= (1u << 30)))) {
        return false;
      }
      entry += int64_t{gap} + 1;
      if (entry >= num_entries) {
        return false;
      }
      entries_[i] = static_cast<int32_t>(entry);
      symbols_[i] = static_cast<int32_t>(symbol) + 1;
    }
    return true;
  }
  // While decoding, in entry order: whether |entry| is the next exception,
  // and its symbol.
  bool Take(int entry, int32_t *symbol) {
    if (next_ >= entries_.size() || entries_[next_] != entry) {
      return false;
    }
    *symbol = symbols_[next_++];
    return true;
  }
  size_t size() const { return entries_.size(); }

 private:
  std::vector<int32_t> entries_;
  std::vector<int32_t> symbols_;
  size_t next_ = 0;
};

// Codes (encodes or decodes, by CoderT) the |values| (4 per entry, in
// entry order) of every entry of |connectivity| with the predictions
// |predict|(entry) returns. CoderT has
//   bool Value(int context, int32_t predicted, int32_t sign, int32_t *value);
//   bool Handedness(int entry, const std::array<int32_t, 2> &predicted,
//                   int32_t *w);
//   bool Copy(int entry, const int32_t *source, int32_t *v);
// (the encoder reads *value, *w and v, the decoder writes them; Value()
// codes sign * (value - predicted), Handedness() HandednessSymbol() in
// kTangentHandednessContext or as an exception, Copy() the 4 components
// against |source| in kTangentCopyContext, or nothing but an exception
// where they differ).
// Entries without a prediction code every component against a coded
// neighbour's value (else the previous entry's, else the zero tangent);
// entries predicted from one triangle that already gave a coded neighbour
// its value copy that value. |neighbour_sums|, when not null, receives
// every entry's TangentNeighbourSum().
template <class PredictFn, class CoderT>
bool CodeGeometricTangents(const TangentConnectivity &connectivity,
                           const TangentCodingParameters &params,
                           PredictFn predict, CoderT *coder, int32_t *values,
                           std::vector<int8_t> *neighbour_sums = nullptr) {
  const uint32_t *const corner_entry = connectivity.corner_entry.data();
  const uint32_t num_corners =
      static_cast<uint32_t>(connectivity.corner_entry.size());
  const CornerIndex *const data_to_corner = connectivity.data_to_corner;
  const int num_entries = connectivity.num_entries;
  // Per coded entry: its first residual's bit length and its single
  // triangle. int32_t: stores of a char type would make the compiler reload
  // everything else.
  std::vector<int32_t> first_bits(num_entries);
  std::vector<int32_t> single_face(num_entries);
  // The entry at the vertex of |corner| if it is coded before |entry|.
  const auto coded_neighbour = [&](uint32_t corner, int entry) {
    const uint32_t data = corner_entry[corner];
    return data < static_cast<uint32_t>(entry) ? static_cast<int>(data) : -1;
  };
  // The neighbour classes of every pair of neighbours' first_bits (+1, 0:
  // no neighbour), and what the encoder's first pass records.
  constexpr int kBits = 9;
  std::array<int8_t, kBits * kBits> class_of, sum_of;
  for (int left = 0; left < kBits; ++left) {
    for (int right = 0; right < kBits; ++right) {
      const int sum = TangentNeighbourSum(left - 1, right - 1);
      sum_of[kBits * left + right] = static_cast<int8_t>(sum);
      class_of[kBits * left + right] =
          static_cast<int8_t>(TangentNeighbourClass(sum, params));
    }
  }
  std::array<int32_t, kTangentNumComponents> fallback;
  for (int c = 0; c < kTangentNumComponents; ++c) {
    fallback[c] = params.grid.Round(
        params.grid.Coordinate(c, c == 3 ? kTangentUnit : 0));
  }
  TangentComponentPredictor components(params);
  for (int entry = 0; entry < num_entries; ++entry) {
    int32_t *const v = values + kTangentNumComponents * entry;
    // Next() and Previous() of the entry's corner, as in every corner
    // table; no neighbours for a corner out of range (corrupt data).
    const uint32_t corner = data_to_corner[entry].value();
    const uint32_t face = corner - corner % 3;
    const bool in_range = corner < num_corners;
    const int left =
        in_range ? coded_neighbour(corner == face + 2 ? face : corner + 1, entry)
                 : -1;
    const int right =
        in_range ? coded_neighbour(corner == face ? face + 2 : corner - 1, entry)
                 : -1;
    const GeometricTangentPrediction prediction = predict(entry);
    single_face[entry] = prediction.single_face;
    int source = -1;
    int context = kTangentFallbackContext;
    if (!prediction.valid) {
      source = left >= 0 ? left : (right >= 0 ? right : entry - 1);
    } else if (prediction.single_face >= 0) {
      for (const int n : {left, right}) {
        if (n >= 0 && single_face[n] == prediction.single_face) {
          source = n;
          context = kTangentCopyContext;
          break;
        }
      }
    }
    if (context == kTangentCopyContext) {
      if (!coder->Copy(entry, values + kTangentNumComponents * source, v)) {
        return false;
      }
      first_bits[entry] = 1;
      continue;
    }
    if (!prediction.valid) {
      for (int c = 0; c < kTangentNumComponents; ++c) {
        const int32_t predicted =
            source >= 0 ? values[kTangentNumComponents * source + c]
                        : fallback[c];
        if (!coder->Value(context, predicted, 1, &v[c])) {
          return false;
        }
      }
      first_bits[entry] = 1;
      continue;
    }
    const int pair = kBits * (left >= 0 ? first_bits[left] : 0) +
                     (right >= 0 ? first_bits[right] : 0);
    if (neighbour_sums != nullptr) {
      (*neighbour_sums)[entry] = sum_of[pair];
    }
    const int neighbour_class = class_of[pair];
    components.Begin(prediction);
    const int b1 = components.Axis(0), b2 = components.Axis(1),
              b3 = components.Axis(2);
    const TangentPredictedValue first = components.First();
    if (!coder->Value(kTangentFirstContext + 2 * neighbour_class +
                          first.fraction_class,
                      first.value, first.sign, &v[b1])) {
      return false;
    }
    first_bits[entry] =
        1 + std::min(7, BitLength(AbsAsUnsigned(int64_t{v[b1]} - first.value)));
    const TangentPredictedValue second = components.Second(v[b1]);
    if (!coder->Value(kTangentSecondContext + 2 * (neighbour_class > 0) +
                          second.fraction_class,
                      second.value, second.sign, &v[b2])) {
      return false;
    }
    const TangentPredictedValue third = components.Third(v[b1], v[b2]);
    if (!coder->Value(kTangentThirdContext + third.fraction_class,
                      third.value, third.sign, &v[b3]) ||
        !coder->Handedness(entry, components.PredictHandedness(), &v[3])) {
      return false;
    }
  }
  return true;
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_TANGENT_MESH_PREDICTION_SCHEME_GEOMETRIC_TANGENT_SHARED_H_
