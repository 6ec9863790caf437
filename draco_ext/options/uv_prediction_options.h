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
// The -uv_pred contract shared by draco_encoder, draco_transcoder and
// draco_uv_eval: a name selects the prediction scheme of every TEX_COORD
// attribute of a mesh.
//
//   draco            stock Draco's own choice (the default; changes nothing)
//   parallelogram    MESH_PREDICTION_PARALLELOGRAM
//   multi_parallelogram
//                    MESH_PREDICTION_CONSTRAINED_MULTI_PARALLELOGRAM
//   portable         MESH_PREDICTION_TEX_COORDS_PORTABLE
//   weighted         MESH_PREDICTION_TEX_COORDS_WEIGHTED (draco-uv), decodes
//                    as fast as stock Draco
//   weighted_multi   MESH_PREDICTION_TEX_COORDS_WEIGHTED_MULTI: weighted
//                    with every stencil; smaller, slower to decode
//   laplacian_tutte, laplacian_cotan, laplacian_mv
//                    MESH_PREDICTION_TEX_COORDS_LAPLACIAN (draco-uv, lossy:
//                    see uv_laplacian_options.h)
//   auto             per attribute, the smallest of the lossless schemes
//                    above that decode as fast as stock (all but
//                    weighted_multi and the Laplacians)
#ifndef DRACO_EXT_OPTIONS_UV_PREDICTION_OPTIONS_H_
#define DRACO_EXT_OPTIONS_UV_PREDICTION_OPTIONS_H_

#include <string>
#include <vector>

#include "draco/compression/config/compression_shared.h"
#include "draco/compression/expert_encode.h"
#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"

namespace draco {

// One -uv_pred name and the prediction scheme it stands for. |method| is
// PREDICTION_UNDEFINED for "draco" (Draco chooses) and for "auto".
struct UvPredictionName {
  const char *name;
  PredictionSchemeMethod method;
  const char *description;
};

// All names, in the order -h lists them.
const std::vector<UvPredictionName> &UvPredictionNames();

// Help text for the tools' -h.
std::string UvPredictionUsage();

// Resolves |name| to a prediction method. "auto" resolves to
// PREDICTION_UNDEFINED too; check IsAutoUvPrediction() first. An unknown name
// is an error listing the valid names.
StatusOr<PredictionSchemeMethod> ParseUvPredictionName(const std::string &name);
bool IsAutoUvPrediction(const std::string &name);

// The -uv_pred name of |method| as a UV prediction ("draco" for
// PREDICTION_UNDEFINED, or the numeric id for methods without a name).
std::string UvPredictionNameOf(PredictionSchemeMethod method);

// True for the methods that predict from quantized positions.
bool UvPredictionNeedsQuantizedPositions(PredictionSchemeMethod method);

// True for the prediction scheme ids that stock Draco does not define (all
// of draco-uv's): a file using one needs a decoder with draco-uv.
bool IsDracoUvPredictionMethod(PredictionSchemeMethod method);

// Applies -uv_pred |name| to every TEX_COORD attribute of |mesh| on
// |encoder|, whose options must already be set. An empty name or "draco"
// leaves the encoder untouched, so the output stays byte-identical to stock
// Draco. "auto" encodes the mesh once per candidate and attribute and keeps
// the smallest. Fails on an unknown name, on a point cloud (|mesh| null),
// and on settings under which the scheme cannot work (sequential encoding at
// -cl 0, unquantised positions or texture coordinates). Returns a one-line
// summary per attribute for the tools to print ("" when nothing changed).
StatusOr<std::string> ConfigureUvPrediction(const std::string &name,
                                            const Mesh *mesh,
                                            ExpertEncoder *encoder);

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_UV_PREDICTION_OPTIONS_H_
