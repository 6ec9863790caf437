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
// The glTF extension that marks files using draco-uv's coders.
//
// A file whose Draco buffers use a draco-uv prediction scheme (texture
// coordinates, tangents) or draco-uv's seam coding (-uv_seams context) lists
// kUvGltfExtension in extensionsUsed and extensionsRequired. Like
// KHR_mesh_quantization it has no JSON object of its own: it says that the
// Draco buffers of KHR_draco_mesh_compression may use prediction scheme or
// Edgebreaker method ids that only a decoder with draco-uv knows. Loaders
// that honour extensionsRequired (Draco's own glTF reader, Babylon.js)
// refuse such a file up front; for loaders that do not (three.js warns and
// goes on), the Draco decoder fails on the unknown ids
// (uv_bitstream_guard.h, uv_seam_edgebreaker.h).
#ifndef DRACO_EXT_GLTF_UV_GLTF_EXTENSION_H_
#define DRACO_EXT_GLTF_UV_GLTF_EXTENSION_H_

#include <cstddef>
#include <string>

namespace draco {

constexpr char kUvGltfExtension[] = "DRACOUV_attribute_compression";

// What naming kUvGltfExtension in extensionsUsed and extensionsRequired adds
// to a file whose extensionsRequired already lists KHR_draco_mesh_compression:
// twice the quoted name, a comma and the writer's indentation. Measured by
// deleting the two entries from the written JSON: 74 bytes with Draco's glTF
// writer (.gltf of sphere.gltf) and in glTF-Transform's 2-space .gltf, 64 in
// compact JSON (Draco's GLB, gltf-pipeline). Writers pad each Draco buffer
// to 4 bytes, so a primitive's saving S shrinks the file's buffers by at
// least S - 3 rounded up to a multiple of 4: keeping only savings above 76
// bytes (74 rounded up to 4) removes at least 76 bytes for the 74 added.
constexpr size_t kUvGltfExtensionJsonBytes = 76;

// True for the glTF extensions that draco-uv adds, which Draco's glTF reader
// accepts in extensionsRequired (patches/0010).
inline bool IsUvGltfExtension(const std::string &name) {
  return name == kUvGltfExtension;
}

}  // namespace draco

#endif  // DRACO_EXT_GLTF_UV_GLTF_EXTENSION_H_
