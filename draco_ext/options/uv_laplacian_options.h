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
// -uv_pred laplacian_* and -uv_anchors on a Draco encoder: the settings of
// the lossy Laplacian scheme (eq. 6-8 of [Váša & Brunnett 2014]) for one
// TEX_COORD attribute. -qt sets the quantisation step of its residuals,
// range / (2^qt - 1); K extra anchors are chosen greedily by largest error
// or at random; P% sets K to P percent of the attribute's texture
// coordinates; without -uv_anchors the scheme's encoder takes
// UvDefaultExtraAnchors() of the mesh. Called by ConfigureUvPrediction().
#ifndef DRACO_EXT_OPTIONS_UV_LAPLACIAN_OPTIONS_H_
#define DRACO_EXT_OPTIONS_UV_LAPLACIAN_OPTIONS_H_

#include <optional>

#include "draco/compression/expert_encode.h"
#include "draco/core/status.h"
#include "draco/mesh/mesh.h"
#include "draco_ext/options/uv_compression_options.h"

namespace draco {

// Sets up attribute |att_id| of |mesh| on |encoder| for the Laplacian
// |prediction|: the operator, the step from the attribute's quantisation
// bits (the user's -qt, 1 to 20), a finer quantisation frame for Draco, and
// the extra anchors of |anchors| (the default without). Call once, after the
// prediction scheme is set.
Status ConfigureUvLaplacian(UvPrediction prediction,
                            const std::optional<UvAnchorSpec> &anchors,
                            const Mesh &mesh, int att_id,
                            ExpertEncoder *encoder);

// The number of extra anchors |spec| asks for on an attribute of
// |num_values| texture coordinates; a percentage is rounded up, so that
// any positive one gives at least one anchor.
int UvAnchorCount(const UvAnchorSpec &spec, int64_t num_values);

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_UV_LAPLACIAN_OPTIONS_H_
