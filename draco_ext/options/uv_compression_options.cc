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
#include "draco_ext/options/uv_compression_options.h"

#ifdef DRACO_TRANSCODER_SUPPORTED
#include <cstring>

#include "draco/compression/draco_compression_options.h"
#include "draco_ext/options/uv_laplacian_options.h"
#include "draco_ext/options/uv_prediction_options.h"
#include "draco_ext/options/uv_seam_options.h"

namespace draco {

namespace {

constexpr char kPredictionFlag[] = "-uv_pred";
constexpr char kSeamsFlag[] = "-uv_seams";
constexpr char kAnchorsFlag[] = "-uv_anchors";

// Also stock for -uv_seams: "draco" is the stock name of both flags.
bool IsStockPredictionName(const std::string &name) {
  return name.empty() || name == "draco";
}

Status CheckUvSeams(const DracoCompressionOptions &options) {
  const std::string &name = options.uv.seams;
  if (IsStockPredictionName(name)) {
    return OkStatus();
  }
  DRACO_RETURN_IF_ERROR(ParseUvSeamCodingName(name).status());
  if (options.compression_level < 1) {
    return ErrorStatus(
        "-uv_seams needs Edgebreaker encoding: compression level 1 or more.");
  }
  return OkStatus();
}

Status CheckUvPrediction(const DracoCompressionOptions &options) {
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

Status CheckUvAnchors(const DracoCompressionOptions &options) {
  if (options.uv.anchors.empty()) {
    return OkStatus();
  }
  DRACO_RETURN_IF_ERROR(ParseUvAnchorSpec(options.uv.anchors).status());
  if (!IsUvLaplacianName(options.uv.prediction)) {
    return ErrorStatus(
        "-uv_anchors needs -uv_pred laplacian_tutte, laplacian_cotan or "
        "laplacian_mv.");
  }
  return OkStatus();
}

}  // namespace

bool UvCompressionOptions::IsStock() const {
  return IsStockPredictionName(prediction) && IsStockPredictionName(seams);
}

Status CheckUvCompressionOptions(const DracoCompressionOptions &options) {
  DRACO_RETURN_IF_ERROR(CheckUvPrediction(options));
  DRACO_RETURN_IF_ERROR(CheckUvAnchors(options));
  return CheckUvSeams(options);
}

bool IsUvCompressionFlag(const char *arg) {
  return std::strcmp(arg, kPredictionFlag) == 0 ||
         std::strcmp(arg, kSeamsFlag) == 0 ||
         std::strcmp(arg, kAnchorsFlag) == 0;
}

Status ParseUvCompressionFlag(int argc, char **argv, int *index,
                              UvCompressionOptions *options) {
  const std::string flag = argv[*index];
  if (*index + 1 >= argc) {
    return ErrorStatus(flag + " needs a value.");
  }
  const std::string value = argv[++*index];
  if (flag == kSeamsFlag) {
    DRACO_RETURN_IF_ERROR(ParseUvSeamCodingName(value).status());
    options->seams = value;
    return OkStatus();
  }
  if (flag == kAnchorsFlag) {
    DRACO_RETURN_IF_ERROR(ParseUvAnchorSpec(value).status());
    options->anchors = value;
    return OkStatus();
  }
  DRACO_RETURN_IF_ERROR(ParseUvPredictionName(value).status());
  options->prediction = value;
  return OkStatus();
}

std::string UvCompressionUsage() {
  return UvPredictionUsage() + UvSeamCodingUsage();
}

}  // namespace draco

#endif  // DRACO_TRANSCODER_SUPPORTED
