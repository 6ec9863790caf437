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
// -tangent_pred on a Draco encoder: finds a mesh's tangent attributes, checks
// that the geometric tangent prediction can use exact inputs for them, and
// sets it (or keeps stock coding, saying why). Called by
// ConfigureUvCompression() (uv_configure.h), after the texture coordinates'
// coders are set, because the prediction must not read lossily coded UVs.
#ifndef DRACO_EXT_OPTIONS_TANGENT_PREDICTION_OPTIONS_H_
#define DRACO_EXT_OPTIONS_TANGENT_PREDICTION_OPTIONS_H_

#include <optional>
#include <string>
#include <vector>

#include "draco/compression/expert_encode.h"
#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"
#include "draco_ext/options/tangent_compression_options.h"

namespace draco {

// True when |att| holds tangents by its values: 4 float components, w = +1
// or -1 everywhere, xyz of length 1 (within 1 %) for all but 1 % of the
// values; values with a NaN or an infinity are not counted (but some must
// be finite). How the JavaScript encoder recognises the TANGENT that
// glTF-Transform and gltf-pipeline hand Draco as a GENERIC attribute.
bool HasTangentValues(const PointAttribute &att);

// The tangent attributes of |mesh|: those of type TANGENT (Draco's glTF
// reader's) and the GENERIC ones with tangent values, in attribute order.
std::vector<int> TangentAttributeIds(const Mesh &mesh);

// Why the geometric prediction cannot code tangent attribute |att_id| of
// |mesh| with |encoder|'s present settings exactly, or "" when it can:
// Edgebreaker with an attribute connectivity of its own (-cl 5 to 10),
// quantized positions, a NORMAL attribute with quantized (octahedral)
// normals, a first TEX_COORD attribute coded losslessly on its quantization
// grid, quantized tangents of at most 21 bits, finite values, and a
// quantization grid of at most 2^20 steps per unit (GeometricTangentGrid()).
std::string WhyNoGeometricTangentPrediction(const Mesh &mesh,
                                            const ExpertEncoder &encoder,
                                            int att_id);

// Fails with a message when |options| apply to tangents (anything but
// stock coding without -qtg) and a tangent attribute of |mesh| has NaN or
// infinite values, which Draco's quantization cannot code. The UV options'
// trial encodes (-uv_pred auto) call it first: stock Draco takes minutes to
// quantize an infinite GENERIC value and then throws std::bad_alloc.
Status CheckTangentValues(const TangentCompressionOptions &options,
                          const Mesh *mesh);

// Applies |options| to every tangent attribute of |mesh| on |encoder|,
// whose other settings (and the texture coordinates' coders) must already
// be set: quantizes tangents the encoder does not quantize yet
// (options.quantization_bits, else 8 bits for the geometric names), then
// sets MESH_PREDICTION_GEOMETRIC_TANGENT where WhyNoGeometricTangent-
// Prediction() finds nothing against it, else keeps stock coding and says
// why. kAuto also keeps stock coding where the geometric file is not
// smaller (one trial encode each). kDraco with no -qtg leaves |encoder|
// untouched. Returns a summary line per tangent attribute ("" when nothing
// changed); fails on a point cloud and on tangents with NaN or infinite
// values, which Draco's quantization cannot code either. |encoded_size|,
// the whole file's size with |encoder|'s settings as they are when known
// (ConfigureUvPrediction() measures it for -uv_pred auto), spares kAuto its
// stock trial encodes: with the tangents coded stock and their quantization
// unchanged, those settings are the stock trial's, and each trial then
// measures the settings it leaves for the next tangent attribute.
StatusOr<std::string> ConfigureTangentPrediction(
    const TangentCompressionOptions &options, const Mesh *mesh,
    ExpertEncoder *encoder,
    std::optional<size_t> encoded_size = std::nullopt);

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_TANGENT_PREDICTION_OPTIONS_H_
