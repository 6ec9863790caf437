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
#include "draco_ext/uv_compression_options.h"

#ifdef DRACO_TRANSCODER_SUPPORTED
#include <cstring>

#include "draco/compression/draco_compression_options.h"
#include "draco_ext/uv_prediction_options.h"

namespace draco {

namespace {

constexpr char kPredictionFlag[] = "-uv_pred";

bool IsStockPredictionName(const std::string &name) {
  return name.empty() || name == "draco";
}

}  // namespace

bool UvCompressionOptions::IsStock() const {
  return IsStockPredictionName(prediction);
}

Status CheckUvCompressionOptions(const DracoCompressionOptions &options) {
  const std::string &name = options.uv.prediction;
  if (IsStockPredictionName(name)) {
    return OkStatus();
  }
  DRACO_ASSIGN_OR_RETURN(const PredictionSchemeMethod method,
                         ParseUvPredictionName(name));
  if (options.compression_level < 1) {
    return ErrorStatus(
        "-uv_pred needs Edgebreaker encoding: compression level 1 or more.");
  }
  if (options.quantization_bits_tex_coord <= 0) {
    return ErrorStatus("-uv_pred needs quantized texture coordinates.");
  }
  const bool positions_quantized =
      !options.quantization_position.AreQuantizationBitsDefined() ||
      options.quantization_position.quantization_bits() > 0;
  if (!positions_quantized && !IsAutoUvPrediction(name) &&
      UvPredictionNeedsQuantizedPositions(method)) {
    return ErrorStatus("-uv_pred " + name + " needs quantized positions.");
  }
  return OkStatus();
}

bool IsUvCompressionFlag(const char *arg) {
  return std::strcmp(arg, kPredictionFlag) == 0;
}

Status ParseUvCompressionFlag(int argc, char **argv, int *index,
                              UvCompressionOptions *options) {
  const std::string flag = argv[*index];
  if (*index + 1 >= argc) {
    return ErrorStatus(flag + " needs a value.");
  }
  const std::string value = argv[++*index];
  DRACO_RETURN_IF_ERROR(ParseUvPredictionName(value).status());
  options->prediction = value;
  return OkStatus();
}

std::string UvCompressionUsage() { return UvPredictionUsage(); }

}  // namespace draco

#endif  // DRACO_TRANSCODER_SUPPORTED
