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
// and once per (-uv_pred, -tangent_pred) pair, then read back and compared;
// for assets with tangents also without their TANGENT attributes, which
// gives what the tangents cost.
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
  // draco_transcoder's defaults: -qp 11 -qt 10 -qn 8 -qtg 8, compression
  // level 7.
  DracoCompressionOptions compression;
  // -uv_pred names compared with stock Draco; "<name>+<seams>" also sets
  // -uv_seams (e.g. "weighted+context", "draco+context").
  std::vector<std::string> schemes = {"auto"};
  // -tangent_pred names, each measured with every scheme ("draco": stock
  // tangent coding, so that a scheme's row shows its UV coders alone).
  std::vector<std::string> tangents = {"draco", "auto"};
  // Output container: false writes .gltf + .bin (images beside them, not
  // counted), true writes .glb (images inside, counted).
  bool glb = false;
};

// What the TANGENT of one primitive costs, in its Draco buffer.
struct UvGltfTangentCost {
  std::string primitive;    // "<mesh>.<primitive>" of the written glTF.
  int64_t values = 0;       // Its TANGENT accessor's count: one per vertex.
  int64_t stock_bytes = 0;  // Draco buffer with minus without TANGENT,
  int64_t bytes = 0;        // stock coding and the measured coding.
};

// One (asset, scheme, tangents) measurement at the options' -qtg.
struct UvGltfEvalRow {
  std::string asset;
  std::string scheme;
  std::string tangents;             // The -tangent_pred name.
  int qtg = 0;                      // quantization_bits_tangent.
  int primitives = 0;               // Meshes of the scene: glTF primitives.
  int textured_primitives = 0;      // Of these, with a TEXCOORD_n.
  int64_t stock_bytes = 0;          // draco_transcoder without draco-uv.
  int64_t bytes = 0;                // With |scheme| and |tangents|.
  // The Draco buffers of the file (each buffer view once).
  int64_t stock_draco_bytes = 0;
  int64_t draco_bytes = 0;
  // Per primitive with TANGENT (each Draco buffer once), and their sums.
  std::vector<UvGltfTangentCost> tangent_costs;
  int64_t tangent_values = 0;
  int64_t stock_tangent_bytes = 0;
  int64_t tangent_bytes = 0;
  bool requires_extension = false;  // extensionsRequired has draco-uv's.
  // Read back identical to the stock output, every attribute at every
  // corner (for the lossy laplacian_* schemes: but for the TEX_COORD
  // values).
  bool round_trip_ok = false;
  std::string detail;               // Why the round trip failed.
};

// Bits per TANGENT value (8 * tangent bytes / values) and the ratios to
// stock coding of the tangents and of the Draco buffers; 0 without them.
double TangentBitsPerValue(int64_t bytes, int64_t values);
double UvGltfRatio(int64_t bytes, int64_t stock_bytes);

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

// Each primitive's KHR_draco_mesh_compression buffer of a transcoded glTF
// or GLB |file|, each buffer view once: "<mesh>.<primitive>", the buffer's
// bytes and the count of its TANGENT accessor (0 without one).
struct GltfDracoPrimitive {
  std::string primitive;
  int64_t draco_bytes = 0;
  int64_t tangent_values = 0;
};
StatusOr<std::vector<GltfDracoPrimitive>> ReadGltfDracoPrimitives(
    const std::string &file);

// Transcodes |input| like TranscodeGltfFile() with every TANGENT attribute
// deleted first (points that then coincide merge): the file the asset
// would give without tangents.
Status TranscodeGltfFileWithoutTangents(const std::string &input,
                                        const std::string &output,
                                        const DracoCompressionOptions &options);

// Compares two decoded scenes mesh by mesh: same number of meshes, faces
// and attributes of each type, and bit-identical values of every attribute
// at every face corner, except TEX_COORD values unless
// |compare_tex_coords|. The error names the first difference.
Status CompareSceneGeometry(const Scene &expected, const Scene &actual,
                            bool compare_tex_coords = true);

// Transcodes |input| with stock options and with every scheme and tangent
// name of |options| into |work_dir|, reads each result back with Draco's
// glTF reader and compares it with the stock result; with tangents, also
// transcodes each without them. Rows in scheme order, then tangent order.
// Fails when stock coding fails: morph targets, which draco_transcoder does
// not support, or output that Draco's own reader cannot read back (a point
// cloud primitive).
StatusOr<std::vector<UvGltfEvalRow>> EvaluateGltfAsset(
    const std::string &input, const std::string &name,
    const UvGltfEvalOptions &options, const std::string &work_dir);

}  // namespace draco

#endif  // DRACO_EXT_EVAL_UV_GLTF_EVAL_H_
