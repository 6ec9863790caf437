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
// -uv_pred on a Draco encoder: sets the prediction scheme of every TEX_COORD
// attribute of a mesh, after checking that the encoder's settings allow it;
// -uv_pred auto encodes once per candidate and keeps the smallest. Called by
// ConfigureUvCompression() (uv_configure.h), the one place that applies
// UvCompressionOptions.
#ifndef DRACO_EXT_OPTIONS_UV_PREDICTION_OPTIONS_H_
#define DRACO_EXT_OPTIONS_UV_PREDICTION_OPTIONS_H_

#include <optional>
#include <string>

#include "draco/compression/expert_encode.h"
#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"
#include "draco_ext/options/uv_compression_options.h"

namespace draco {

// Applies options.prediction to every TEX_COORD attribute of |mesh| on
// |encoder|, whose options must already be set; the Laplacian predictions
// also get options.anchors (uv_laplacian_options.h). kDraco leaves the
// encoder untouched, so the output stays byte-identical to stock Draco.
// kAuto encodes the mesh once per candidate and attribute and keeps the
// smallest. Fails on a point cloud (|mesh| null) and on settings under which
// the scheme cannot work (sequential encoding at -cl 0, unquantised
// positions or texture coordinates, NaN or infinite values). Returns a
// one-line summary per attribute for the tools to print ("" when nothing
// changed).
//
// When |encoded_size| is not null, sets it to the whole file's size with the
// settings left on |encoder| where a trial encode measured exactly those
// (kAuto's choice for the last TEX_COORD attribute), else to nullopt, so
// that the tangents' trial encodes can reuse it.
StatusOr<std::string> ConfigureUvPrediction(
    const UvCompressionOptions &options, const Mesh *mesh,
    ExpertEncoder *encoder, std::optional<size_t> *encoded_size = nullptr);

// The same for the one TEX_COORD attribute |att_id| of |mesh| (an error for
// any other attribute), leaving the others untouched.
StatusOr<std::string> ConfigureUvPredictionOf(
    const UvCompressionOptions &options, const Mesh *mesh, int att_id,
    ExpertEncoder *encoder, std::optional<size_t> *encoded_size = nullptr);

// -uv_pred auto's choice for one TEX_COORD attribute.
struct UvAutoChoice {
  PredictionSchemeMethod method = PREDICTION_UNDEFINED;
  size_t bytes = 0;        // The whole file with |method|.
  size_t stock_bytes = 0;  // The whole file with Draco's own choice.
  int num_encodes = 0;     // Trial encodes it took.
};

// The scheme that Draco 1.5.5 picks itself for TEX_COORD attribute |att_id|
// of |mesh| under |options| (SelectPredictionMethod() in
// prediction_scheme_encoder_factory.cc): TEX_COORDS_PORTABLE at speeds 0 to
// 3 for 2 components with positions integral or quantized to at most 21
// bits (twice those plus the UVs' bits under 64), else parallelogram at
// speeds 2 to 7 or under 40 points, constrained multi-parallelogram at 0
// and 1, and difference coding from speed 8.
PredictionSchemeMethod StockUvPrediction(const Mesh &mesh,
                                         const EncoderOptions &options,
                                         int att_id);

// -uv_pred auto for TEX_COORD attribute |att_id| of |mesh| on |encoder|,
// whose settings (-cl, -qt) must already allow -uv_pred: measures every
// lossless candidate the settings allow and leaves the smallest set,
// counting weighted_multi (slower to decode) half a bit per UV vertex
// larger. Stock Draco's choice comes first and wins ties; the candidate
// that StockUvPrediction() names is not encoded again. Only the stock
// choice is encoded whole: the others' whole-file sizes are its size plus
// the difference their trial encodes of the positions and this attribute
// alone show (TrialEncoder), which is exact for lossless predictions and
// spares the other attributes' encoding.
StatusOr<UvAutoChoice> ChooseSmallestUvPrediction(const Mesh &mesh, int att_id,
                                                  ExpertEncoder *encoder);

// "TEX_COORD <index> (attribute <att_id>)", how summaries name attribute
// |att_id| of |mesh|, a TEX_COORD attribute.
std::string UvAttributeLabel(const Mesh &mesh, int att_id);

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_UV_PREDICTION_OPTIONS_H_
