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
#include "draco_ext/options/tangent_compression_options.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "prediction_schemes/tangent/geometric_tangent_settings.h"

namespace draco {

namespace {

constexpr char kPredictionFlag[] = "-tangent_pred";
constexpr char kBitsFlag[] = "-qtg";

}  // namespace

const std::vector<TangentPredictionName> &TangentPredictionNames() {
  static const std::vector<TangentPredictionName> names = {
      {"draco", TangentPrediction::kDraco, "stock Draco's choice (default)"},
      {"mikktspace", TangentPrediction::kMikkTSpace,
       "MikkTSpace from positions, normals, UVs (draco-uv)"},
      {"uniform", TangentPrediction::kUniform,
       "the same with equal corner weights (draco-uv)"},
      {"face", TangentPrediction::kFace,
       "per-face UV gradients, not on the normal (draco-uv)"},
      {"geometric", TangentPrediction::kGeometric,
       "the smallest of mikktspace, uniform, face"},
      {"auto", TangentPrediction::kAuto,
       "geometric where smaller than stock, else stock"},
  };
  return names;
}

const char *TangentPredictionNameOf(TangentPrediction prediction) {
  for (const TangentPredictionName &entry : TangentPredictionNames()) {
    if (entry.prediction == prediction) {
      return entry.name;
    }
  }
  DRACO_DCHECK(false);
  return "?";
}

StatusOr<TangentPrediction> ParseTangentPredictionName(
    const std::string &name) {
  std::string valid;
  for (const TangentPredictionName &entry : TangentPredictionNames()) {
    if (name == entry.name) {
      return entry.prediction;
    }
    valid += (valid.empty() ? "" : ", ") + std::string(entry.name);
  }
  return ErrorStatus(std::string("Unknown ") + kPredictionFlag + " name '" +
                     name + "'. Valid names: " + valid + ".");
}

uint8_t GeometricTangentKindsOf(TangentPrediction prediction) {
  switch (prediction) {
    case TangentPrediction::kDraco:
      return 0;
    case TangentPrediction::kMikkTSpace:
      return GeometricTangentKindBit(GeometricTangentKind::kMikkTSpace);
    case TangentPrediction::kUniform:
      return GeometricTangentKindBit(GeometricTangentKind::kUniform);
    case TangentPrediction::kFace:
      return GeometricTangentKindBit(GeometricTangentKind::kFace);
    case TangentPrediction::kGeometric:
    case TangentPrediction::kAuto:
      return kAllGeometricTangentKinds;
  }
  return 0;
}

Status CheckTangentCompressionOptions(
    const TangentCompressionOptions &options) {
  if (options.quantization_bits.has_value() &&
      (*options.quantization_bits < 1 ||
       *options.quantization_bits >
           TangentCompressionOptions::kMaxQuantizationBits)) {
    return ErrorStatus(std::string(kBitsFlag) + " needs 1 to " +
                       std::to_string(
                           TangentCompressionOptions::kMaxQuantizationBits) +
                       " bits.");
  }
  return OkStatus();
}

bool IsTangentCompressionFlag(const char *arg) {
  return std::strcmp(arg, kPredictionFlag) == 0 ||
         std::strcmp(arg, kBitsFlag) == 0;
}

Status ParseTangentCompressionFlag(const std::string &flag,
                                   const std::string &value,
                                   TangentCompressionOptions *options) {
  if (flag == kPredictionFlag) {
    DRACO_ASSIGN_OR_RETURN(options->prediction,
                           ParseTangentPredictionName(value));
    return OkStatus();
  }
  char *end = nullptr;
  const long bits = std::strtol(value.c_str(), &end, 10);
  if (value.empty() || *end != '\0' || bits < 1 ||
      bits > TangentCompressionOptions::kMaxQuantizationBits) {
    return ErrorStatus(std::string(kBitsFlag) + " needs 1 to " +
                       std::to_string(
                           TangentCompressionOptions::kMaxQuantizationBits) +
                       " bits, got '" + value + "'.");
  }
  options->quantization_bits = static_cast<int>(bits);
  return OkStatus();
}

std::string TangentCompressionUsage() {
  std::string lines =
      "  -tangent_pred <name>  prediction of tangent attributes (glTF "
      "TANGENT) from the\n"
      "                          positions, normals and first UV set "
      "(glTF: TEXCOORD_0,\n"
      "                          which the normal texture must use); needs "
      "-cl 5..10,\n"
      "                          quantized normals and losslessly coded "
      "UVs:\n";
  for (const TangentPredictionName &entry : TangentPredictionNames()) {
    std::string line = "                          " + std::string(entry.name);
    line.resize(std::max<size_t>(line.size() + 1, 48), ' ');
    lines += line + entry.description + "\n";
  }
  return lines +
         "  -qtg <bits>           draco_encoder: quantization of tangent "
         "attributes\n"
         "                          (default with -tangent_pred: 8); "
         "draco_transcoder's\n"
         "                          own -qtg does the same for glTF TANGENT "
         "(default 8)\n";
}

}  // namespace draco
