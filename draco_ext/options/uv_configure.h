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
// ConfigureUvCompression(): the one place that turns UvCompressionOptions
// into Draco encoder settings. draco_encoder (patches/0004), the glTF
// encoder (gltf/uv_gltf.h), EncodeMeshWithSettings() (uv_encode_settings.h)
// and so draco_uv_eval and the benchmarks all go through it, so a flag means
// the same, with the same checks, whatever the entry point.
#ifndef DRACO_EXT_OPTIONS_UV_CONFIGURE_H_
#define DRACO_EXT_OPTIONS_UV_CONFIGURE_H_

#include <map>
#include <string>

#include "draco/compression/expert_encode.h"
#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"
#include "draco_ext/options/uv_compression_options.h"

namespace draco {

// Checks |options| (CheckUvCompressionOptions()) and applies them to
// |encoder|, which encodes |mesh| (null for a point cloud) and whose other
// options must already be set: first the seam coding, then the prediction
// of every TEX_COORD attribute with its Laplacian settings, then that of
// the tangents (options.tangent), in that order because -uv_pred auto
// measures candidates with the chosen seam coding and the tangents'
// prediction must know how the UVs are coded.
// Stock options leave |encoder| untouched. Returns the per-attribute
// summary lines for command-line tools ("" when nothing changed).
StatusOr<std::string> ConfigureUvCompression(
    const UvCompressionOptions &options, const Mesh *mesh,
    ExpertEncoder *encoder);

// Per attribute: |per_attribute| maps TEX_COORD attribute ids of |mesh| to
// their options (an id of any other attribute is an error); attributes
// without an entry keep stock prediction. Each entry is checked, then the
// seams are coded with context when any entry asks for it (Edgebreaker codes
// the seams of all attributes together), then each attribute's prediction is
// applied in attribute order, then the tangent options of the last entry
// that has any apply to the mesh's tangents (TangentOptionsOf()). An empty
// map leaves |encoder| untouched.
StatusOr<std::string> ConfigureUvCompression(
    const std::map<int, UvCompressionOptions> &per_attribute,
    const Mesh *mesh, ExpertEncoder *encoder);

// The tangent options the per-attribute ConfigureUvCompression() applies to
// the mesh's tangents: those of the last entry of |per_attribute| that has
// any, else stock coding.
TangentCompressionOptions TangentOptionsOf(
    const std::map<int, UvCompressionOptions> &per_attribute);

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_UV_CONFIGURE_H_
