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
// draco-uv in glTF files: the texture coordinate and tangent coders of each
// KHR_draco_mesh_compression primitive, and the glTF extension
// (uv_gltf_extension.h) that marks files using them. The rule that -uv_pred
// auto pays for the extension is shared with the JS encoder's glTF writes
// (web/uv_web_encoder.h), which build without Draco's transcoder.
#ifndef DRACO_EXT_GLTF_UV_GLTF_H_
#define DRACO_EXT_GLTF_UV_GLTF_H_

#include <memory>
#include <set>
#include <string>

#include "draco/compression/expert_encode.h"
#include "draco/core/status.h"
#include "draco/core/status_or.h"
#include "draco/draco_features.h"
#include "draco/mesh/mesh.h"
#include "draco_ext/gltf/uv_gltf_extension.h"

#ifdef DRACO_TRANSCODER_SUPPORTED
#include "draco/material/material.h"
#endif

namespace draco {

// True when |encoder| is set to code an attribute of |mesh| (texture
// coordinates, tangents) with a draco-uv scheme, i.e. when its output needs
// a decoder with draco-uv.
bool UsesDracoUvScheme(const Mesh &mesh, const ExpertEncoder &encoder);

// -uv_pred auto or -tangent_pred auto on a primitive of a glTF file that
// does not list kUvGltfExtension yet, with |encoder| configured for |mesh| by
// ConfigureUvCompression() and every draco-uv id left to the encoder's
// choice: when |encoder| would write draco-uv prediction ids with stock
// seams, keeps them only if they save more bytes than naming the extension
// adds to the file (kUvGltfExtensionJsonBytes), else sets every attribute
// with one back to Draco's own prediction, so that auto never makes a file
// bigger than stock coding. With context seams the primitive needs the
// extension anyway and |encoder| is left as it is. Once a primitive keeps
// draco-uv ids, later primitives of the file ride on the extension for free
// (the caller stops asking).
Status KeepDracoUvOnlyIfItPaysForTheExtension(const Mesh &mesh,
                                              ExpertEncoder *encoder);

#ifdef DRACO_TRANSCODER_SUPPORTED

// The glTF TEXCOORD_n set that a primitive drawn with |material| has its
// TANGENT follow: the set its normal texture is mapped with
// (normalTexture.texCoord, which Draco's glTF reader keeps as the
// NORMAL_TANGENT_SPACE texture map's tex_coord_index), 0 without a material
// or a normal texture, as glTF defaults it.
int GltfTangentTexCoordSet(const Material *material);

// The glTF TEXCOORD_n set that Draco's glTF writer names the first TEX_COORD
// attribute of |mesh|, the one MESH_PREDICTION_GEOMETRIC_TANGENT predicts
// from: TEXCOORD_1 when its metadata says "attribute_name" TEXCOORD_1
// (CheckAndGetTexCoordAttributeOrder() of gltf_encoder.cc), else
// TEXCOORD_0. Draco's glTF reader lists TEXCOORD_0 first.
int GltfTexCoordSetOfFirstTexCoord(const Mesh &mesh);

// Applies the UvCompressionOptions of |mesh| (mesh.GetCompressionOptions()
// .uv) to |encoder|, which encodes |mesh|, the copy of a glTF primitive in
// GltfAsset::CompressMeshWithDraco() (patches/0009) with quantization set
// and V already flipped to glTF's convention (the coders infer UV
// orientation from the data, so the mirror costs nothing); |material| is
// the primitive's (null for none).
//  * Tangents keep stock coding when they follow other texture coordinates
//    than the first TEX_COORD attribute, which the tangent prediction reads:
//    GltfTangentTexCoordSet() differs from GltfTexCoordSetOfFirstTexCoord().
//  * With draco-uv ids that the encoder chose (-uv_pred auto, an error
//    target, -tangent_pred auto) and none that the options named, a
//    primitive coded while the extension is not yet required goes through
//    KeepDracoUvOnlyIfItPaysForTheExtension().
//  * When an attribute ends up with a draco-uv scheme or the seams with
//    draco-uv's coding (-uv_seams context, which applies to every primitive
//    with an attribute besides positions), adds kUvGltfExtension to
//    |extensions_used| and |extensions_required|.
// Stock options change nothing. Returns the summary lines of
// ConfigureUvCompression() and of these rules.
StatusOr<std::string> ConfigureUvCompressionForGltfPrimitive(
    const Mesh &mesh, const Material *material, ExpertEncoder *encoder,
    std::set<std::string> *extensions_used,
    std::set<std::string> *extensions_required);

// The hook: ConfigureUvCompressionForGltfPrimitive() without the summary (a
// library stays quiet). Draco 1.5.5 holds the encoder by value and 1.5.7
// and newer in a unique_ptr; one overload each keeps the hook's text the
// same in both.
Status ConfigureUvCompressionForGltf(
    const Mesh &mesh, const Material *material, ExpertEncoder &encoder,
    std::set<std::string> *extensions_used,
    std::set<std::string> *extensions_required);
Status ConfigureUvCompressionForGltf(
    const Mesh &mesh, const Material *material,
    const std::unique_ptr<ExpertEncoder> &encoder,
    std::set<std::string> *extensions_used,
    std::set<std::string> *extensions_required);

#endif  // DRACO_TRANSCODER_SUPPORTED

}  // namespace draco

#endif  // DRACO_EXT_GLTF_UV_GLTF_H_
