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
// Measurements behind draco_uv_gltf_eval and the glTF tests: glTF and GLB
// assets transcoded like draco_transcoder, once with stock Draco's coders
// and once per -uv_pred name, then read back and compared.
#ifndef DRACO_EXT_EVAL_UV_GLTF_EVAL_H_
#define DRACO_EXT_EVAL_UV_GLTF_EVAL_H_

#include <cstdint>
#include <string>
#include <vector>

#include "draco/compression/draco_compression_options.h"
#include "draco/core/status.h"
#include "draco/core/status_or.h"
#include "draco/scene/scene.h"

namespace draco {

struct UvGltfEvalOptions {
  // draco_transcoder's defaults: -qp 11 -qt 10, compression level 7.
  DracoCompressionOptions compression;
  // -uv_pred names compared with stock Draco; "<name>+<seams>" also sets
  // -uv_seams (e.g. "weighted+context", "draco+context").
  std::vector<std::string> schemes = {"auto"};
  // Output container: false writes .gltf + .bin (images beside them, not
  // counted), true writes .glb (images inside, counted).
  bool glb = false;
};

// One (asset, scheme) measurement.
struct UvGltfEvalRow {
  std::string asset;
  std::string scheme;
  int primitives = 0;               // Meshes of the scene: glTF primitives.
  int textured_primitives = 0;      // Of these, with a TEXCOORD_n.
  int64_t stock_bytes = 0;          // draco_transcoder without -uv_pred.
  int64_t bytes = 0;                // With -uv_pred |scheme|.
  bool requires_extension = false;  // extensionsRequired has draco-uv's.
  // Read back identical to the stock output (for the lossy laplacian_*
  // schemes: identical but for the TEX_COORD values).
  bool round_trip_ok = false;
  std::string detail;               // Why the round trip failed.
};

// Transcodes |input| into |output| (.gltf or .glb) exactly like
// `draco_transcoder -i input -o output` with |options|.
Status TranscodeGltfFile(const std::string &input, const std::string &output,
                         const DracoCompressionOptions &options);

// Bytes of a transcoded file: the file plus, for .gltf, its buffers. Images
// are not counted (the transcoder copies them unchanged).
StatusOr<int64_t> TranscodedGltfBytes(const std::string &file);

// True when the glTF or GLB |file| lists draco-uv's glTF extension in
// extensionsRequired.
StatusOr<bool> RequiresUvGltfExtension(const std::string &file);

// Compares two decoded scenes mesh by mesh: same number of meshes, faces
// and texture coordinate sets, and bit-identical POSITION and (if
// |compare_tex_coords|) TEX_COORD values at every face corner. The error
// names the first difference.
Status CompareSceneGeometry(const Scene &expected, const Scene &actual,
                            bool compare_tex_coords = true);

// Transcodes |input| with stock options and with every scheme of |options|
// into |work_dir|, reads each result back with Draco's glTF reader and
// compares it with the stock result. Fails when stock coding fails: morph
// targets, which draco_transcoder does not support, or output that Draco's
// own reader cannot read back (a point cloud primitive).
StatusOr<std::vector<UvGltfEvalRow>> EvaluateGltfAsset(
    const std::string &input, const std::string &name,
    const UvGltfEvalOptions &options, const std::string &work_dir);

}  // namespace draco

#endif  // DRACO_EXT_EVAL_UV_GLTF_EVAL_H_
