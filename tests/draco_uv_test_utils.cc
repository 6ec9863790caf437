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
#include "tests/draco_uv_test_utils.h"

#include <algorithm>
#include <cstring>
#include <cstdlib>
#include <filesystem>

#include "draco/compression/decode.h"
#include "draco/io/mesh_io.h"
#include "draco_ext/eval/uv_eval.h"
#include "gtest/gtest.h"

namespace draco {

namespace fs = std::filesystem;

std::string UvTestdataPath(const std::string &name) {
  return std::string(DRACO_UV_TESTDATA_DIR) + "/" + name;
}

std::string DracoTestdataPath(const std::string &name) {
  return std::string(DRACO_UV_DRACO_TESTDATA_DIR) + "/" + name;
}

std::string UvTempPath(const std::string &name) {
  return std::string(DRACO_UV_TEMP_DIR) + "/" + name;
}

std::string CorpusDir() {
  const char *const env = std::getenv("DRACO_UV_CORPUS");
  return env != nullptr ? env : DRACO_UV_CORPUS_DIR;
}

namespace {

bool HasMeshExtension(const fs::path &path) {
  const std::string ext = path.extension().string();
  return ext == ".obj" || ext == ".ply" || ext == ".gltf" || ext == ".glb";
}

bool HasTexturedFaces(const std::string &path) {
  const StatusOr<std::unique_ptr<Mesh>> mesh = ReadTestMesh(path);
  return mesh.ok() && mesh.value()->num_faces() > 0 &&
         mesh.value()->NumNamedAttributes(GeometryAttribute::TEX_COORD) > 0;
}

}  // namespace

std::vector<std::string> DracoTestdataTexturedMeshes() {
  std::vector<std::string> meshes;
  const fs::path root(DRACO_UV_DRACO_TESTDATA_DIR);
  for (const auto &entry : fs::recursive_directory_iterator(root)) {
    if (entry.is_regular_file() && HasMeshExtension(entry.path()) &&
        HasTexturedFaces(entry.path().string())) {
      meshes.push_back(fs::relative(entry.path(), root).string());
    }
  }
  std::sort(meshes.begin(), meshes.end());
  return meshes;
}

std::vector<std::string> TexturedObjPlyMeshPaths() {
  std::vector<std::string> paths = {UvTestdataPath("torus_uv.obj"),
                                    UvTestdataPath("crane_spot.obj")};
  for (const std::string &name : DracoTestdataTexturedMeshes()) {
    const std::string extension = fs::path(name).extension().string();
    if (extension == ".obj" || extension == ".ply") {
      paths.push_back(DracoTestdataPath(name));
    }
  }
  return paths;
}

std::vector<std::string> TangentGltfAssetPaths() {
  std::vector<std::string> paths = {
      UvTestdataPath("small_torus_uv_tangents.glb"),
      UvTestdataPath("small_cube_sphere_tangents.glb"),
      UvTestdataPath("crane_spot_tangents.glb")};
  const fs::path dir = fs::path(CorpusDir()) / "gltf";
  if (!fs::is_directory(dir)) {
    return paths;
  }
  std::vector<std::string> corpus;
  for (const auto &entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".gltf") {
      corpus.push_back(entry.path().string());
    }
  }
  std::sort(corpus.begin(), corpus.end());
  paths.insert(paths.end(), corpus.begin(), corpus.end());
  return paths;
}

std::vector<std::string> CorpusMeshPaths() {
  std::vector<std::string> meshes;
  const fs::path dir = fs::path(CorpusDir()) / "meshes";
  if (!fs::is_directory(dir)) {
    return meshes;
  }
  for (const auto &entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".obj") {
      meshes.push_back(entry.path().string());
    }
  }
  std::sort(meshes.begin(), meshes.end());
  return meshes;
}

StatusOr<std::unique_ptr<Mesh>> ReadTestMesh(const std::string &path) {
  return ReadMeshFromFile(path);
}

UvCompressionOptions UvOptions(const std::string &scheme,
                               const std::string &anchors) {
  UvCompressionOptions options;
  if (!scheme.empty()) {
    const StatusOr<UvCompressionOptions> parsed = ParseUvSchemeName(scheme);
    if (!parsed.ok()) {
      ADD_FAILURE() << parsed.status().error_msg_string();
      return UvCompressionOptions();
    }
    options = parsed.value();
  }
  if (!anchors.empty()) {
    const StatusOr<UvAnchorSpec> spec = ParseUvAnchorSpec(anchors);
    if (!spec.ok()) {
      ADD_FAILURE() << spec.status().error_msg_string();
      return UvCompressionOptions();
    }
    options.anchors = spec.value();
  }
  return options;
}

UvEncodeSettings Settings(int qp, int qt, int cl, const std::string &scheme,
                          const std::string &anchors) {
  UvEncodeSettings settings;
  settings.qp = qp;
  settings.qt = qt;
  settings.cl = cl;
  settings.uv = UvOptions(scheme, anchors);
  return settings;
}

StatusOr<std::vector<char>> EncodeMeshToBytes(
    const Mesh &mesh, const UvEncodeSettings &settings) {
  EncoderBuffer buffer;
  DRACO_RETURN_IF_ERROR(EncodeMeshWithSettings(mesh, settings, &buffer));
  return std::vector<char>(buffer.data(), buffer.data() + buffer.size());
}

StatusOr<std::unique_ptr<Mesh>> DecodeDracoMesh(const std::vector<char> &data) {
  DecoderBuffer buffer;
  buffer.Init(data.data(), data.size());
  Decoder decoder;
  return decoder.DecodeMeshFromBuffer(&buffer);
}

std::vector<float> CornerValues(const Mesh &mesh, GeometryAttribute::Type type,
                                int index) {
  std::vector<float> values;
  const PointAttribute *const att = mesh.GetNamedAttribute(type, index);
  if (att == nullptr) {
    return values;
  }
  std::vector<float> value(att->num_components());
  for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (const PointIndex point : mesh.face(f)) {
      att->ConvertValue(att->mapped_index(point), att->num_components(),
                        value.data());
      values.insert(values.end(), value.begin(), value.end());
    }
  }
  return values;
}

void ExpectSameCornerValues(const Mesh &a, const Mesh &b,
                            const std::string &label) {
  ASSERT_EQ(a.num_faces(), b.num_faces()) << label;
  ASSERT_EQ(a.num_attributes(), b.num_attributes()) << label;
  for (int i = 0; i < a.num_attributes(); ++i) {
    const PointAttribute *const att_a = a.attribute(i);
    const PointAttribute *const att_b =
        b.GetAttributeByUniqueId(att_a->unique_id());
    ASSERT_NE(att_b, nullptr) << label;
    std::vector<float> va(att_a->num_components()), vb(va.size());
    int differing = 0;
    for (FaceIndex f(0); f < a.num_faces(); ++f) {
      for (int k = 0; k < 3; ++k) {
        att_a->ConvertValue(att_a->mapped_index(a.face(f)[k]),
                            att_a->num_components(), va.data());
        att_b->ConvertValue(att_b->mapped_index(b.face(f)[k]),
                            att_b->num_components(), vb.data());
        // Bitwise, so that NaNs compare too.
        differing += std::memcmp(va.data(), vb.data(),
                                 va.size() * sizeof(float)) != 0;
      }
    }
    EXPECT_EQ(differing, 0) << label << ": attribute " << i;
  }
}


}  // namespace draco
