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
// TangentCompressionOptions: how draco-uv codes a mesh's tangents (glTF
// TANGENT: xyz a unit vector, w = +1 or -1), typed, parsed once from a
// command line (-tangent_pred, and -qtg in draco_encoder) or set from C++,
// carried by UvCompressionOptions::tangent and applied with the rest by
// ConfigureUvCompression() (uv_configure.h). Default-constructed it changes
// nothing.
//
//   -tangent_pred <name>  prediction of every tangent attribute
//     draco               stock Draco's own choice (the default)
//     mikktspace          MESH_PREDICTION_GEOMETRIC_TANGENT with MikkTSpace's
//                         corner-angle weighting
//     uniform             the same, every corner weighted equally
//     face                the same, per-face gradients not projected onto
//                         the normal (exporters that write one tangent per
//                         triangle)
//     geometric           MESH_PREDICTION_GEOMETRIC_TANGENT, whichever of the
//                         three the encoder finds smallest
//     auto                geometric where it is smaller than stock Draco's
//                         coding, else stock; never bigger
//   -qtg <bits>           draco_encoder: quantisation of tangent attributes
//                         (draco_transcoder has its own -qtg); the tangent
//                         names quantise with 8 bits, as draco_transcoder
//                         does, where nothing else set them.
#ifndef DRACO_EXT_OPTIONS_TANGENT_COMPRESSION_OPTIONS_H_
#define DRACO_EXT_OPTIONS_TANGENT_COMPRESSION_OPTIONS_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "draco/core/status.h"
#include "draco/core/status_or.h"

namespace draco {

enum class TangentPrediction : uint8_t {
  kDraco,
  kMikkTSpace,
  kUniform,
  kFace,
  kGeometric,
  kAuto,
};

struct TangentCompressionOptions {
  // Bits of tangents quantised where nothing else set them.
  static constexpr int kDefaultQuantizationBits = 8;
  // The geometric scheme's grid holds up to 2^21 values.
  static constexpr int kMaxQuantizationBits = 21;

  TangentPrediction prediction = TangentPrediction::kDraco;
  // -qtg of draco_encoder: quantisation of tangent attributes.
  std::optional<int> quantization_bits;

  bool IsStock() const {
    return prediction == TangentPrediction::kDraco &&
           !quantization_bits.has_value();
  }
  bool operator==(const TangentCompressionOptions &other) const {
    return prediction == other.prediction &&
           quantization_bits == other.quantization_bits;
  }
  bool operator!=(const TangentCompressionOptions &other) const {
    return !(*this == other);
  }
};

// One -tangent_pred name.
struct TangentPredictionName {
  const char *name;
  TangentPrediction prediction;
  const char *description;
};

// All -tangent_pred names, in the order -h lists them; the only table of
// them.
const std::vector<TangentPredictionName> &TangentPredictionNames();
const char *TangentPredictionNameOf(TangentPrediction prediction);
// An unknown name is an error that lists the valid ones.
StatusOr<TangentPrediction> ParseTangentPredictionName(
    const std::string &name);

// The conventions MESH_PREDICTION_GEOMETRIC_TANGENT tries for |prediction|
// (a mask of GeometricTangentKindBit()); 0 for kDraco.
uint8_t GeometricTangentKindsOf(TangentPrediction prediction);

// -qtg must be 1 to kMaxQuantizationBits.
Status CheckTangentCompressionOptions(const TangentCompressionOptions &options);

// The flags (-tangent_pred, -qtg) and their parsing, as
// UvCompressionOptions' flag parser hands them on.
bool IsTangentCompressionFlag(const char *arg);
Status ParseTangentCompressionFlag(const std::string &flag,
                                   const std::string &value,
                                   TangentCompressionOptions *options);
std::string TangentCompressionUsage();

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_TANGENT_COMPRESSION_OPTIONS_H_
