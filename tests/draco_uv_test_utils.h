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
// Shared helpers of the draco-uv tests: test data locations, encoding with
// the tools' settings, decoding, and per-corner attribute comparison.
#ifndef DRACO_UV_TESTS_DRACO_UV_TEST_UTILS_H_
#define DRACO_UV_TESTS_DRACO_UV_TEST_UTILS_H_

#include <memory>
#include <string>
#include <vector>

#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"
#include "draco_ext/options/uv_encode_settings.h"

namespace draco {

// Paths of draco-uv's testdata/, Draco's testdata/ and the real-mesh corpus
// (the DRACO_UV_CORPUS environment variable overrides the configured one).
std::string UvTestdataPath(const std::string &name);
std::string DracoTestdataPath(const std::string &name);
std::string UvTempPath(const std::string &name);
std::string CorpusDir();

// Meshes of Draco's testdata (OBJ, PLY, glTF, GLB) that load and have
// texture coordinates on faces, as paths relative to its testdata/.
std::vector<std::string> DracoTestdataTexturedMeshes();
// Full paths of textured OBJ and PLY meshes, 8 to 10^5 corners: torus_uv
// and crane_spot from our testdata/, then those of Draco's testdata.
std::vector<std::string> TexturedObjPlyMeshPaths();
// The corpus's meshes/*.obj; empty when the corpus is absent.
std::vector<std::string> CorpusMeshPaths();

// Full paths of glTF assets with tangents: the bundled CC0 GLBs with
// MikkTSpace tangents (testdata/*_tangents.glb), then the corpus's Khronos
// glTFs with their own tangents (gltf/*.gltf, when the corpus is there).
std::vector<std::string> TangentGltfAssetPaths();

StatusOr<std::unique_ptr<Mesh>> ReadTestMesh(const std::string &path);

// The draco-uv options of |scheme|, "<uv_pred>[+<uv_seams>]" as
// draco_uv_eval names them (e.g. "weighted+context"; "" is stock Draco),
// with -uv_anchors |anchors| unless empty. A bad name or anchor value fails
// the calling test and gives stock options.
UvCompressionOptions UvOptions(const std::string &scheme,
                               const std::string &anchors = "");
// draco_encoder's -qp |qp| -qt |qt| -cl |cl| with UvOptions(scheme,
// anchors).
UvEncodeSettings Settings(int qp, int qt, int cl, const std::string &scheme,
                          const std::string &anchors = "");

// EncodeMeshWithSettings() into a byte vector.
StatusOr<std::vector<char>> EncodeMeshToBytes(
    const Mesh &mesh, const UvEncodeSettings &settings);
StatusOr<std::unique_ptr<Mesh>> DecodeDracoMesh(const std::vector<char> &data);

// Values of the |index|-th attribute of |type| at every face corner, in face
// order, as float32; identical meshes give identical vectors.
std::vector<float> CornerValues(const Mesh &mesh, GeometryAttribute::Type type,
                                int index = 0);

// Expects every attribute of |a| and |b| (matched by unique id) to have
// bitwise the same values at every face corner (NaNs compare too).
void ExpectSameCornerValues(const Mesh &a, const Mesh &b,
                            const std::string &label);

}  // namespace draco

#endif  // DRACO_UV_TESTS_DRACO_UV_TEST_UTILS_H_
