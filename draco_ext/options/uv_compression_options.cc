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

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <utility>

#include "draco_ext/options/draco_uv_flags.h"
#include "prediction_schemes/laplacian/uv_laplacian_settings.h"

#ifdef DRACO_TRANSCODER_SUPPORTED
#include "draco/compression/draco_compression_options.h"
#endif

namespace draco {

namespace {

constexpr char kPredictionFlag[] = "-uv_pred";
constexpr char kSeamsFlag[] = "-uv_seams";
constexpr char kAnchorsFlag[] = "-uv_anchors";
constexpr char kRmseFlag[] = "-uv_rmse";
constexpr char kTexelsFlag[] = "-uv_texels";
constexpr char kTextureSizeFlag[] = "-uv_texture_size";
constexpr char kDecodeLimitFlag[] = "-uv_decode_limit";
constexpr char kNoDecodeLimit[] = "none";
// Largest -uv_texture_size: 2^24 texels, beyond any GPU's textures.
constexpr long kMaxTextureSize = 1 << 24;
constexpr char kRandomPrefix[] = "random:";

struct UvSeamCodingName {
  const char *name;
  UvSeamCoding coding;
  const char *description;
};

constexpr UvSeamCodingName kSeamCodingNames[] = {
    {"draco", UvSeamCoding::kDraco,
     "stock Draco: a static-probability bit per edge (default)"},
    {"context", UvSeamCoding::kContext,
     "context-modelled crease bits (draco-uv)"},
};

// Looks |name| up in |table| (entries with a .name); on failure, an error
// that names |flag| and lists the valid names.
template <class TableT>
auto FindName(const TableT &table, const std::string &name, const char *flag)
    -> StatusOr<decltype(&*std::begin(table))> {
  std::string valid;
  for (const auto &entry : table) {
    if (name == entry.name) {
      return &entry;
    }
    valid += (valid.empty() ? "" : ", ") + std::string(entry.name);
  }
  return Status(Status::DRACO_ERROR, std::string("Unknown ") + flag +
                                         " name '" + name +
                                         "'. Valid names: " + valid + ".");
}

bool ParseCount(const std::string &text, int *count) {
  char *end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || value < 0 ||
      value > kUvLaplacianMaxExtraAnchors) {
    return false;
  }
  *count = static_cast<int>(value);
  return true;
}

// "P%" with 0 <= P <= 100 (decimals allowed).
bool ParsePercent(const std::string &text, double *percent) {
  if (text.size() < 2 || text.back() != '%') {
    return false;
  }
  const std::string number = text.substr(0, text.size() - 1);
  char *end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (*end != '\0' || !(value >= 0.0 && value <= 100.0)) {
    return false;
  }
  *percent = value;
  return true;
}

StatusOr<int> ParseTextureSize(const std::string &value) {
  char *end = nullptr;
  const long size = std::strtol(value.c_str(), &end, 10);
  if (value.empty() || *end != '\0' || size < 1 || size > kMaxTextureSize) {
    return ErrorStatus(std::string(kTextureSizeFlag) +
                       " needs a whole number of texels from 1 to " +
                       std::to_string(kMaxTextureSize) + ", got '" + value +
                       "'.");
  }
  return static_cast<int>(size);
}

// One help line per name, descriptions aligned.
template <class EntryT>
std::string NameLines(const EntryT *begin, const EntryT *end) {
  std::string lines;
  for (const EntryT *entry = begin; entry != end; ++entry) {
    std::string line = "                          " + std::string(entry->name);
    line.resize(std::max<size_t>(line.size() + 1, 48), ' ');
    lines += line + entry->description + "\n";
  }
  return lines;
}

}  // namespace

const std::vector<UvPredictionName> &UvPredictionNames() {
  static const std::vector<UvPredictionName> names = {
      {"draco", UvPrediction::kDraco, PREDICTION_UNDEFINED,
       "stock Draco's choice (default)"},
      {"parallelogram", UvPrediction::kParallelogram,
       MESH_PREDICTION_PARALLELOGRAM, "Draco's parallelogram prediction"},
      {"multi_parallelogram", UvPrediction::kMultiParallelogram,
       MESH_PREDICTION_CONSTRAINED_MULTI_PARALLELOGRAM,
       "Draco's constrained multi-parallelogram prediction"},
      {"portable", UvPrediction::kPortable,
       MESH_PREDICTION_TEX_COORDS_PORTABLE,
       "Draco's TEX_COORDS_PORTABLE prediction"},
      {"weighted", UvPrediction::kWeighted,
       MESH_PREDICTION_TEX_COORDS_WEIGHTED,
       "mesh-guided weighted parallelogram (draco-uv)"},
      {"weighted_multi", UvPrediction::kWeightedMulti,
       MESH_PREDICTION_TEX_COORDS_WEIGHTED_MULTI,
       "weighted, all stencils: smaller, slower to decode"},
      {"laplacian_tutte", UvPrediction::kLaplacianTutte,
       MESH_PREDICTION_TEX_COORDS_LAPLACIAN,
       "lossy Laplacian coding, Tutte weights (draco-uv)"},
      {"laplacian_cotan", UvPrediction::kLaplacianCotan,
       MESH_PREDICTION_TEX_COORDS_LAPLACIAN,
       "lossy Laplacian coding, cotangent weights (draco-uv)"},
      {"laplacian_mv", UvPrediction::kLaplacianMeanValue,
       MESH_PREDICTION_TEX_COORDS_LAPLACIAN,
       "lossy Laplacian coding, mean-value weights (draco-uv)"},
      {"auto", UvPrediction::kAuto, PREDICTION_UNDEFINED,
       "smallest lossless scheme; weighted_multi only where it saves"
       " half a bit per UV vertex"},
  };
  return names;
}

const char *UvPredictionNameOf(UvPrediction prediction) {
  for (const UvPredictionName &entry : UvPredictionNames()) {
    if (entry.prediction == prediction) {
      return entry.name;
    }
  }
  DRACO_DCHECK(false);
  return "?";
}

std::string UvPredictionNameOf(PredictionSchemeMethod method) {
  for (const UvPredictionName &entry : UvPredictionNames()) {
    if (entry.method == method) {
      return entry.name;
    }
  }
  return std::to_string(static_cast<int>(method));
}

PredictionSchemeMethod UvPredictionMethod(UvPrediction prediction) {
  for (const UvPredictionName &entry : UvPredictionNames()) {
    if (entry.prediction == prediction) {
      return entry.method;
    }
  }
  return PREDICTION_UNDEFINED;
}

bool IsUvLaplacian(UvPrediction prediction) {
  return IsLossyUvPrediction(UvPredictionMethod(prediction));
}

bool IsLossyUvPrediction(PredictionSchemeMethod method) {
  return method == MESH_PREDICTION_TEX_COORDS_LAPLACIAN;
}

bool UvPredictionNeedsQuantizedPositions(PredictionSchemeMethod method) {
  return method == MESH_PREDICTION_TEX_COORDS_PORTABLE ||
         method == MESH_PREDICTION_TEX_COORDS_WEIGHTED ||
         method == MESH_PREDICTION_TEX_COORDS_WEIGHTED_MULTI ||
         method == MESH_PREDICTION_TEX_COORDS_LAPLACIAN;
}

bool HasUvLaplacianCoder() {
#ifdef DRACO_UV_LAPLACIAN
  return true;
#else
  return false;
#endif
}

StatusOr<UvPrediction> ParseUvPredictionName(const std::string &name) {
  DRACO_ASSIGN_OR_RETURN(const UvPredictionName *entry,
                         FindName(UvPredictionNames(), name, kPredictionFlag));
  return entry->prediction;
}

StatusOr<UvSeamCoding> ParseUvSeamCodingName(const std::string &name) {
  DRACO_ASSIGN_OR_RETURN(const UvSeamCodingName *entry,
                         FindName(kSeamCodingNames, name, kSeamsFlag));
  return entry->coding;
}

const char *UvSeamCodingNameOf(UvSeamCoding coding) {
  return kSeamCodingNames[static_cast<int>(coding)].name;
}

StatusOr<UvAnchorSpec> ParseUvAnchorSpec(const std::string &spec) {
  UvAnchorSpec parsed;
  parsed.random = spec.rfind(kRandomPrefix, 0) == 0;
  const std::string amount =
      parsed.random ? spec.substr(sizeof(kRandomPrefix) - 1) : spec;
  parsed.is_percent = ParsePercent(amount, &parsed.percent);
  if (!parsed.is_percent && !ParseCount(amount, &parsed.count)) {
    return Status(Status::DRACO_ERROR,
                  "Bad -uv_anchors value '" + spec +
                      "': use K, P% or random:K, random:P% (K >= 0, "
                      "0 <= P <= 100).");
  }
  return parsed;
}

StatusOr<double> ParseUvErrorTarget(const std::string &flag,
                                    const std::string &value) {
  char *end = nullptr;
  const double target = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(target) ||
      target <= 0.0) {
    return ErrorStatus(flag + " needs a positive number, got '" + value + "'.");
  }
  return target;
}

StatusOr<double> ParseUvDecodeLimit(const std::string &value) {
  if (value == kNoDecodeLimit) {
    return std::numeric_limits<double>::infinity();
  }
  char *end = nullptr;
  const double limit = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(limit) || limit < 1.0) {
    return ErrorStatus(std::string(kDecodeLimitFlag) +
                       " needs a number of at least 1 or '" + kNoDecodeLimit +
                       "', got '" + value + "'.");
  }
  return limit;
}

Status CheckUvCompressionOptions(const UvCompressionOptions &options) {
  if (options.rmse.has_value() && options.texels.has_value()) {
    return ErrorStatus(
        "-uv_rmse and -uv_texels both set an error target: give one.");
  }
  for (const auto &[flag, target] :
       {std::make_pair(kRmseFlag, options.rmse),
        std::make_pair(kTexelsFlag, options.texels)}) {
    if (target.has_value() && !(std::isfinite(*target) && *target > 0.0)) {
      return ErrorStatus(std::string(flag) + " needs a positive number.");
    }
  }
  if (options.texture_size.has_value() &&
      (!options.texels.has_value() || *options.texture_size < 1 ||
       *options.texture_size > kMaxTextureSize)) {
    return ErrorStatus(std::string(kTextureSizeFlag) +
                       " needs -uv_texels and 1 to " +
                       std::to_string(kMaxTextureSize) + " texels.");
  }
  if (options.decode_limit.has_value() &&
      (!options.ChoosesPrediction() || !options.MaxUvRmse().has_value() ||
       !(*options.decode_limit >= 1.0))) {
    return ErrorStatus(std::string(kDecodeLimitFlag) +
                       " needs an error target (-uv_rmse or -uv_texels) "
                       "without -uv_pred or with -uv_pred auto, and a limit "
                       "of at least 1.");
  }
  if (IsUvLaplacian(options.prediction) && !HasUvLaplacianCoder()) {
    return ErrorStatus(std::string("-uv_pred ") +
                       UvPredictionNameOf(options.prediction) +
                       ": this build has no Laplacian coder "
                       "(DRACO_UV_LAPLACIAN=OFF).");
  }
  if (options.anchors.has_value() && !IsUvLaplacian(options.prediction)) {
    return ErrorStatus(
        "-uv_anchors needs -uv_pred laplacian_tutte, laplacian_cotan or "
        "laplacian_mv.");
  }
  return CheckTangentCompressionOptions(options.tangent);
}

bool IsUvCompressionFlag(const char *arg) {
  return std::strcmp(arg, kPredictionFlag) == 0 ||
         std::strcmp(arg, kSeamsFlag) == 0 ||
         std::strcmp(arg, kAnchorsFlag) == 0 ||
         std::strcmp(arg, kRmseFlag) == 0 ||
         std::strcmp(arg, kTexelsFlag) == 0 ||
         std::strcmp(arg, kTextureSizeFlag) == 0 ||
         std::strcmp(arg, kDecodeLimitFlag) == 0 ||
         IsTangentCompressionFlag(arg);
}

Status ParseUvCompressionFlag(int argc, char **argv, int *index,
                              UvCompressionOptions *options) {
  const std::string flag = argv[*index];
  if (*index + 1 >= argc) {
    // -qtg has stock draco_transcoder's name: at the end of the command line
    // it is skipped with the warning of stock's -qp there.
    if (IsStockToolValueFlag(flag) &&
        CheckUnhandledToolArg(argc, argv, *index)) {
      return OkStatus();
    }
    return ErrorStatus(flag + " needs a value.");
  }
  const std::string value = argv[++*index];
  if (IsTangentCompressionFlag(flag.c_str())) {
    return ParseTangentCompressionFlag(flag, value, &options->tangent);
  }
  if (flag == kSeamsFlag) {
    DRACO_ASSIGN_OR_RETURN(options->seams, ParseUvSeamCodingName(value));
  } else if (flag == kAnchorsFlag) {
    DRACO_ASSIGN_OR_RETURN(options->anchors, ParseUvAnchorSpec(value));
  } else if (flag == kRmseFlag) {
    DRACO_ASSIGN_OR_RETURN(options->rmse, ParseUvErrorTarget(flag, value));
  } else if (flag == kTexelsFlag) {
    DRACO_ASSIGN_OR_RETURN(options->texels, ParseUvErrorTarget(flag, value));
  } else if (flag == kTextureSizeFlag) {
    DRACO_ASSIGN_OR_RETURN(options->texture_size, ParseTextureSize(value));
  } else if (flag == kDecodeLimitFlag) {
    DRACO_ASSIGN_OR_RETURN(options->decode_limit, ParseUvDecodeLimit(value));
  } else {
    DRACO_ASSIGN_OR_RETURN(options->prediction, ParseUvPredictionName(value));
  }
  return OkStatus();
}

std::string UvCompressionUsage() {
  const std::vector<UvPredictionName> &names = UvPredictionNames();
  return "  -uv_pred <name>       prediction of TEX_COORD attributes "
         "(needs -cl 1..10):\n" +
         NameLines(names.data(), names.data() + names.size()) +
         "  -uv_anchors <K>       extra anchors of -uv_pred laplacian_*, "
         "chosen\n"
         "                          greedily (default: 0.65% of the "
         "texture\n"
         "                          coordinates + 6% of those on the "
         "boundary);\n"
         "                          <P>% is P percent of its texture "
         "coordinates;\n"
         "                          random:<K> or random:<P>% picks them at "
         "random\n"
         "  -uv_rmse <R>          error target of TEX_COORD attributes: "
         "the smallest\n"
         "                          coding (scheme, -qt, anchors) whose "
         "decoded RMSE\n"
         "                          (UV units) is at most R, e.g. 0.0015; "
         "overrides -qt\n"
         "  -uv_texels <T>        the same target in texels of the "
         "texture, e.g. 0.5\n"
         "  -uv_texture_size <N>  texels of that texture (default 4096)\n"
         "  -uv_decode_limit <X>  with an error target: a lossy coding only "
         "where its\n"
         "                          whole-mesh decode is estimated at most X "
         "times the\n"
         "                          stock-coded file's (default 2); none: no "
         "limit\n"
         "  -uv_seams <name>      coding of attribute seams (needs -cl 5..10 "
         "to matter):\n" +
         NameLines(std::begin(kSeamCodingNames), std::end(kSeamCodingNames)) +
         TangentCompressionUsage() + UnknownToolFlagUsage();
}

#ifdef DRACO_TRANSCODER_SUPPORTED
namespace {

// The flag that asks for draco-uv's coding in |uv|, for messages.
const char *FirstNonStockFlag(const UvCompressionOptions &uv) {
  return uv.prediction != UvPrediction::kDraco ? kPredictionFlag
         : uv.seams != UvSeamCoding::kDraco    ? kSeamsFlag
         : uv.MaxUvRmse().has_value()          ? kRmseFlag
                                               : "-tangent_pred";
}

// -tangent_pred in glTF options: tangents are quantized by
// quantization_bits_tangent (draco_transcoder's -qtg), and a named
// prediction must be possible on every primitive the options allow.
Status CheckTangentOptions(const DracoCompressionOptions &options) {
  const UvCompressionOptions &uv = options.uv;
  if (uv.tangent.quantization_bits.has_value()) {
    return ErrorStatus(
        "-qtg of draco_encoder (UvCompressionOptions::tangent."
        "quantization_bits) does not apply to glTF: tangents take "
        "DracoCompressionOptions::quantization_bits_tangent "
        "(draco_transcoder's -qtg).");
  }
  if (uv.tangent.prediction == TangentPrediction::kDraco) {
    return OkStatus();
  }
  if (options.quantization_bits_tangent < 1 ||
      options.quantization_bits_tangent >
          TangentCompressionOptions::kMaxQuantizationBits) {
    return ErrorStatus(
        "-tangent_pred needs quantized tangents: -qtg 1 to " +
        std::to_string(TangentCompressionOptions::kMaxQuantizationBits) + ".");
  }
  if (uv.tangent.prediction == TangentPrediction::kAuto) {
    return OkStatus();  // Keeps stock coding where it cannot predict.
  }
  const std::string flag = std::string("-tangent_pred ") +
                           TangentPredictionNameOf(uv.tangent.prediction);
  if (options.compression_level < 5) {
    return ErrorStatus(flag +
                       " needs compression level 5 or more (below, Draco "
                       "splits meshes on attribute seams).");
  }
  if (options.quantization_position.AreQuantizationBitsDefined() &&
      options.quantization_position.quantization_bits() < 1) {
    return ErrorStatus(flag + " needs quantized positions.");
  }
  if (options.quantization_bits_normal < 1) {
    return ErrorStatus(flag + " needs quantized normals.");
  }
  if (options.quantization_bits_tex_coord < 1 && !uv.MaxUvRmse().has_value()) {
    return ErrorStatus(flag + " needs quantized texture coordinates.");
  }
  if (IsUvLaplacian(uv.prediction)) {
    return ErrorStatus(flag +
                       " needs losslessly coded texture coordinates, not "
                       "-uv_pred " +
                       UvPredictionNameOf(uv.prediction) + ".");
  }
  return OkStatus();
}

}  // namespace

Status CheckUvCompressionOptions(const DracoCompressionOptions &options) {
  const UvCompressionOptions &uv = options.uv;
  DRACO_RETURN_IF_ERROR(CheckUvCompressionOptions(uv));
  if (uv.IsStock()) {
    return OkStatus();
  }
  if (options.compression_level < 1) {
    return ErrorStatus(std::string(FirstNonStockFlag(uv)) +
                       " needs Edgebreaker encoding: compression level 1 or "
                       "more.");
  }
  DRACO_RETURN_IF_ERROR(CheckTangentOptions(options));
  if (uv.prediction == UvPrediction::kDraco) {
    return OkStatus();
  }
  if (options.quantization_bits_tex_coord <= 0 && !uv.MaxUvRmse().has_value()) {
    return ErrorStatus("-uv_pred needs quantized texture coordinates.");
  }
  const bool positions_quantized =
      !options.quantization_position.AreQuantizationBitsDefined() ||
      options.quantization_position.quantization_bits() > 0;
  const PredictionSchemeMethod method = UvPredictionMethod(uv.prediction);
  if (!positions_quantized && uv.prediction != UvPrediction::kAuto &&
      UvPredictionNeedsQuantizedPositions(method)) {
    return ErrorStatus(std::string("-uv_pred ") +
                       UvPredictionNameOf(uv.prediction) +
                       " needs quantized positions.");
  }
  return OkStatus();
}
#endif  // DRACO_TRANSCODER_SUPPORTED

}  // namespace draco
