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
// The encoder settings of the lossy Laplacian texture coordinate scheme
// (MESH_PREDICTION_TEX_COORDS_LAPLACIAN):
//   -uv_pred laplacian_tutte | laplacian_cotan | laplacian_mv
//       the Laplacian (eq. 6-8 of [Váša & Brunnett 2014]); -qt sets the
//       quantisation step of its residuals, range / (2^qt - 1);
//   -uv_anchors K | P% | random:K | random:P%
//       K extra anchors, greedy by largest error (default 50) or random;
//       P% sets K to P percent of the attribute's texture coordinates.
// Lossy: -uv_pred auto never picks these names.
#ifndef DRACO_EXT_OPTIONS_UV_LAPLACIAN_OPTIONS_H_
#define DRACO_EXT_OPTIONS_UV_LAPLACIAN_OPTIONS_H_

#include <string>

#include "draco/compression/config/compression_shared.h"
#include "draco/compression/expert_encode.h"
#include "draco/core/status.h"
#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"

namespace draco {

// True for prediction schemes whose decoded values differ from the
// quantised input.
bool IsLossyUvPrediction(PredictionSchemeMethod method);

// True for the -uv_pred names of the Laplacian scheme.
bool IsUvLaplacianName(const std::string &name);

// Sets up attribute |att_id| of |encoder| for -uv_pred |name| (a Laplacian
// name): the operator, the step from the attribute's quantisation bits (the
// user's -qt, 1 to 20) and a finer quantisation frame for Draco (see
// MeshPredictionSchemeTexCoordsLaplacianEncoder). Call once, after the
// prediction scheme is set.
Status ConfigureUvLaplacian(const std::string &name, int att_id,
                            ExpertEncoder *encoder);

// A parsed -uv_anchors value.
struct UvAnchorSpec {
  bool random = false;
  bool is_percent = false;
  int count = 0;        // K, when !is_percent.
  double percent = 0;   // P, when is_percent.
};

// Parses "K", "P%", "random:K" or "random:P%" (0 <= K <= 2^24,
// 0 <= P <= 100).
StatusOr<UvAnchorSpec> ParseUvAnchorSpec(const std::string &spec);

// Applies -uv_anchors |spec| (ParseUvAnchorSpec()) to every TEX_COORD
// attribute of |mesh| that uses the Laplacian scheme; P% becomes
// ceil(P / 100 * the attribute's number of values). Returns how many
// attributes it set (0 for an empty spec, which changes nothing).
StatusOr<int> ApplyUvAnchors(const std::string &spec, const Mesh *mesh,
                             ExpertEncoder *encoder);

// ApplyUvAnchors() for a command line: a spec without any such attribute
// is an error.
Status ConfigureUvAnchors(const std::string &spec, const Mesh *mesh,
                          ExpertEncoder *encoder);

// Help text of -uv_anchors for the tools' -h.
std::string UvAnchorsUsage();

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_UV_LAPLACIAN_OPTIONS_H_
