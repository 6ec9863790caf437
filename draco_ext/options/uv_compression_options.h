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
// UvCompressionOptions: everything draco-uv adds to a mesh's compression
// settings, typed, parsed once from a command line (-uv_pred, -uv_seams,
// -uv_anchors), from glTF options (DracoCompressionOptions::uv) or set from
// C++, and applied to a Draco encoder in one place, ConfigureUvCompression()
// (uv_configure.h). Default-constructed it changes nothing: output stays
// byte-identical to stock Draco.
//
//   -uv_pred <name>     prediction of every TEX_COORD attribute
//     draco               stock Draco's own choice (the default)
//     parallelogram, multi_parallelogram, portable
//                         Draco's own schemes, forced
//     weighted            mesh-guided weighted parallelogram (draco-uv)
//     weighted_multi      weighted with every stencil: smaller, slower
//     laplacian_tutte, laplacian_cotan, laplacian_mv
//                         lossy Laplacian coding (draco-uv; builds with
//                         DRACO_UV_LAPLACIAN only)
//     auto                per attribute, the smallest lossless scheme;
//                         weighted_multi (slower to decode) only where it
//                         saves half a bit per UV vertex
//   -uv_seams draco|context
//                       coding of attribute seams (context: draco-uv's
//                       context-modelled crease bits)
//   -uv_anchors K|P%|random:K|random:P%
//                       extra anchors of the Laplacian names (default:
//                       UvDefaultExtraAnchors(), 0.65 % of the texture
//                       coordinates + 6 % of the boundary ones)
//   -uv_rmse R          error target: per TEX_COORD attribute, the smallest
//                       coding (scheme, -qt, anchors) whose decoded RMSE
//                       (eq. 9, UV units) is at most R (uv_error_target.h)
//   -uv_texels T        the same target as RMSE T / N, in texels of a
//   -uv_texture_size N  texture of N texels (default 4096)
//   -uv_decode_limit X|none
//                       where the encoder chooses the scheme for an error
//                       target, a lossy coding only if its whole-mesh
//                       decode is estimated at most X times the stock-coded
//                       file's (default 2; none: no limit)
//   -tangent_pred, -qtg the mesh's tangents (TangentCompressionOptions,
//                       tangent_compression_options.h)
//
// Draco's compression options header includes this one (patches/0008), so
// it depends on nothing but Draco's status and compression ids.
#ifndef DRACO_EXT_OPTIONS_UV_COMPRESSION_OPTIONS_H_
#define DRACO_EXT_OPTIONS_UV_COMPRESSION_OPTIONS_H_

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "draco/compression/config/compression_shared.h"
#include "draco/core/status.h"
#include "draco/core/status_or.h"
#include "draco/draco_features.h"
#include "draco_ext/options/tangent_compression_options.h"

namespace draco {

enum class UvPrediction : uint8_t {
  kDraco,
  kParallelogram,
  kMultiParallelogram,
  kPortable,
  kWeighted,
  kWeightedMulti,
  kLaplacianTutte,
  kLaplacianCotan,
  kLaplacianMeanValue,
  kAuto,
};

enum class UvSeamCoding : uint8_t { kDraco = 0, kContext = 1 };

// A parsed -uv_anchors value.
struct UvAnchorSpec {
  bool random = false;
  bool is_percent = false;
  int count = 0;       // K, when !is_percent.
  double percent = 0;  // P, when is_percent.

  bool operator==(const UvAnchorSpec &other) const {
    return random == other.random && is_percent == other.is_percent &&
           count == other.count && percent == other.percent;
  }
};

struct UvCompressionOptions {
  // -uv_texture_size without the flag.
  static constexpr int kDefaultTextureSize = 4096;
  // -uv_decode_limit without the flag.
  static constexpr double kDefaultDecodeLimit = 2.0;

  UvPrediction prediction = UvPrediction::kDraco;
  UvSeamCoding seams = UvSeamCoding::kDraco;
  // Extra anchors of the Laplacian predictions; unset keeps the default.
  std::optional<UvAnchorSpec> anchors;
  // Error target, RMSE of eq. (9) per TEX_COORD attribute: -uv_rmse in UV
  // units, or -uv_texels in texels of a -uv_texture_size texture.
  std::optional<double> rmse;
  std::optional<double> texels;
  std::optional<int> texture_size;
  // -uv_decode_limit: the largest estimated whole-mesh decode cost, in
  // multiples of the stock-coded file's, of a lossy coding that the encoder
  // may choose for an error target; infinity for none.
  std::optional<double> decode_limit;
  // How the mesh's tangents are coded (they follow from the UVs).
  TangentCompressionOptions tangent;

  // The error target in UV units, if one is set.
  std::optional<double> MaxUvRmse() const {
    if (texels.has_value()) {
      return *texels / texture_size.value_or(kDefaultTextureSize);
    }
    return rmse;
  }
  // The decode limit in effect (kDefaultDecodeLimit without the flag).
  double DecodeLimit() const {
    return decode_limit.value_or(kDefaultDecodeLimit);
  }
  // True when the encoder picks the prediction scheme itself: -uv_pred auto,
  // or an error target without a specific -uv_pred.
  bool ChoosesPrediction() const {
    return prediction == UvPrediction::kAuto ||
           (prediction == UvPrediction::kDraco && MaxUvRmse().has_value());
  }
  // True when no draco-uv feature is requested.
  bool IsStock() const {
    return prediction == UvPrediction::kDraco &&
           seams == UvSeamCoding::kDraco && !MaxUvRmse().has_value() &&
           tangent.IsStock();
  }
  bool operator==(const UvCompressionOptions &other) const {
    return prediction == other.prediction && seams == other.seams &&
           anchors == other.anchors && rmse == other.rmse &&
           texels == other.texels && texture_size == other.texture_size &&
           decode_limit == other.decode_limit && tangent == other.tangent;
  }

  bool operator!=(const UvCompressionOptions &other) const {
    return !(*this == other);
  }
};

// One -uv_pred name: the prediction and the Draco scheme it stands for
// (PREDICTION_UNDEFINED for "draco", which lets Draco choose, and "auto").
struct UvPredictionName {
  const char *name;
  UvPrediction prediction;
  PredictionSchemeMethod method;
  const char *description;
};

// All -uv_pred names, in the order -h lists them; the only table of them.
const std::vector<UvPredictionName> &UvPredictionNames();
// The -uv_pred name of |prediction|.
const char *UvPredictionNameOf(UvPrediction prediction);
// The -uv_pred name of a Draco scheme ("draco" for PREDICTION_UNDEFINED,
// the number for ids without a name).
std::string UvPredictionNameOf(PredictionSchemeMethod method);
// The Draco scheme |prediction| sets (PREDICTION_UNDEFINED for kDraco and
// kAuto).
PredictionSchemeMethod UvPredictionMethod(UvPrediction prediction);
// True for the three lossy Laplacian predictions.
bool IsUvLaplacian(UvPrediction prediction);
// True for the prediction schemes whose decoded values differ from the
// quantised input.
bool IsLossyUvPrediction(PredictionSchemeMethod method);
// True for the schemes that predict from quantized positions.
bool UvPredictionNeedsQuantizedPositions(PredictionSchemeMethod method);
// True when this build has the Laplacian coder (DRACO_UV_LAPLACIAN).
bool HasUvLaplacianCoder();

// Name parsers; an unknown name is an error that lists the valid ones.
StatusOr<UvPrediction> ParseUvPredictionName(const std::string &name);
StatusOr<UvSeamCoding> ParseUvSeamCodingName(const std::string &name);
const char *UvSeamCodingNameOf(UvSeamCoding coding);
// Parses "K", "P%", "random:K" or "random:P%" (0 <= K <= 2^24,
// 0 <= P <= 100).
StatusOr<UvAnchorSpec> ParseUvAnchorSpec(const std::string &spec);

// Parses a -uv_rmse or -uv_texels value: a finite number > 0; |flag| names
// the flag in the error.
StatusOr<double> ParseUvErrorTarget(const std::string &flag,
                                    const std::string &value);

// Parses a -uv_decode_limit value: a finite number >= 1, or "none"
// (infinity).
StatusOr<double> ParseUvDecodeLimit(const std::string &value);

// The options on their own: -uv_anchors only with a Laplacian -uv_pred, a
// Laplacian -uv_pred only in a build with the Laplacian coder, at most one
// of -uv_rmse and -uv_texels, each finite and positive, and
// -uv_texture_size only with -uv_texels, -uv_decode_limit (at least 1)
// only with an error target whose scheme the encoder chooses, and the
// tangent options
// (CheckTangentCompressionOptions()). Every entry point checks this before
// it encodes.
Status CheckUvCompressionOptions(const UvCompressionOptions &options);

// True when |arg| is one of draco-uv's command-line flags.
bool IsUvCompressionFlag(const char *arg);

// Parses the flag argv[*index] and its value argv[*index + 1] into
// |options| and leaves *index on the value. Fails when the value is missing
// or invalid (the message lists the valid values).
Status ParseUvCompressionFlag(int argc, char **argv, int *index,
                              UvCompressionOptions *options);

// Help text of the flags, one line per flag and value, and the paragraph on
// unknown flags (UnknownToolFlagUsage(), draco_uv_flags.h).
std::string UvCompressionUsage();

#ifdef DRACO_TRANSCODER_SUPPORTED
struct DracoCompressionOptions;

// CheckUvCompressionOptions(options.uv), and what the rest of |options|
// must allow: Edgebreaker encoding (compression level 1 or more) for
// anything but stock Draco, quantized texture coordinates for -uv_pred and,
// for the schemes that predict from them, quantized positions. Called by
// DracoCompressionOptions::Check().
Status CheckUvCompressionOptions(const DracoCompressionOptions &options);
#endif  // DRACO_TRANSCODER_SUPPORTED

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_UV_COMPRESSION_OPTIONS_H_
