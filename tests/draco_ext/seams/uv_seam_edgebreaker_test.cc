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
// Whole Draco files with -uv_seams context: they decode to exactly what
// stock coding decodes to, and corrupt seam data stops decoding.
#include <algorithm>
#include <set>
#include <utility>

#include "draco/compression/config/compression_shared.h"
#include "draco/compression/encode.h"
#include "draco/compression/point_cloud/point_cloud_decoder.h"
#include "draco_ext/eval/uv_seam_stats.h"
#include "draco_ext/options/uv_prediction_options.h"
#include "draco_ext/options/uv_seam_options.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

// The Edgebreaker method byte of an encoded mesh without metadata.
int EdgebreakerMethodOf(const std::vector<char> &bytes) {
  DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  DracoHeader header;
  uint8_t method;
  if (!PointCloudDecoder::DecodeHeader(&buffer, &header).ok() ||
      header.encoder_method != MESH_EDGEBREAKER_ENCODING ||
      (header.flags & METADATA_FLAG_MASK) || !buffer.Decode(&method)) {
    return -1;
  }
  return method;
}

// Same faces, points and attribute values at every corner.
void ExpectSameMesh(const Mesh &expected, const Mesh &actual,
                    const std::string &label) {
  ASSERT_EQ(expected.num_faces(), actual.num_faces()) << label;
  ASSERT_EQ(expected.num_points(), actual.num_points()) << label;
  ASSERT_EQ(expected.num_attributes(), actual.num_attributes()) << label;
  for (FaceIndex f(0); f < expected.num_faces(); ++f) {
    ASSERT_EQ(expected.face(f), actual.face(f)) << label << " face " << f;
  }
  for (int type = 0; type < GeometryAttribute::NAMED_ATTRIBUTES_COUNT; ++type) {
    const auto att_type = static_cast<GeometryAttribute::Type>(type);
    for (int i = 0; i < expected.NumNamedAttributes(att_type); ++i) {
      EXPECT_EQ(CornerValues(expected, att_type, i),
                CornerValues(actual, att_type, i))
          << label << " attribute type " << type << " #" << i;
    }
  }
}

// Encodes |mesh| with stock and context seams at |settings| and checks that
// both decode to the same mesh; returns the context-seam file.
std::vector<char> ExpectContextSeamsDecodeLikeStock(const Mesh &mesh,
                                                    UvEncodeSettings settings,
                                                    const std::string &label) {
  settings.uv.seams = UvSeamCoding::kDraco;
  const auto stock = EncodeMeshToBytes(mesh, settings);
  settings.uv.seams = UvSeamCoding::kContext;
  const auto context = EncodeMeshToBytes(mesh, settings);
  EXPECT_TRUE(stock.ok() && context.ok()) << label;
  if (!stock.ok() || !context.ok()) {
    return {};
  }
  const auto stock_mesh = DecodeDracoMesh(stock.value());
  const auto context_mesh = DecodeDracoMesh(context.value());
  EXPECT_TRUE(stock_mesh.ok() && context_mesh.ok()) << label;
  if (stock_mesh.ok() && context_mesh.ok()) {
    ExpectSameMesh(*stock_mesh.value(), *context_mesh.value(), label);
  }
  return context.value();
}

TEST(UvSeamEdgebreakerTest, DecodesLikeStockOnDracoTestdata) {
  const std::vector<std::string> meshes = DracoTestdataTexturedMeshes();
  ASSERT_GE(meshes.size(), 20u);
  for (const std::string &name : meshes) {
    const auto mesh = ReadTestMesh(DracoTestdataPath(name));
    ASSERT_TRUE(mesh.ok()) << name;
    // -cl 5: standard Edgebreaker; -cl 10: valence for meshes of 1000
    // faces or more.
    for (const int cl : {5, 10}) {
      ExpectContextSeamsDecodeLikeStock(*mesh.value(), {14, 12, cl},
                                        name + " cl" + std::to_string(cl));
    }
  }
}

TEST(UvSeamEdgebreakerTest, DecodesLikeStockOnCorpusWithBothMethods) {
  const std::vector<std::string> meshes = CorpusMeshPaths();
  if (meshes.empty()) {
    GTEST_SKIP() << "corpus not found at " << CorpusDir();
  }
  std::set<int> methods;
  for (const std::string &path : meshes) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    for (const int cl : {5, 10}) {
      const std::vector<char> file = ExpectContextSeamsDecodeLikeStock(
          *mesh.value(), {14, 12, cl}, path + " cl" + std::to_string(cl));
      methods.insert(EdgebreakerMethodOf(file));
    }
  }
  EXPECT_EQ(methods,
            std::set<int>({MESH_EDGEBREAKER_STANDARD_CONTEXT_SEAMS_ENCODING,
                           MESH_EDGEBREAKER_VALENCE_CONTEXT_SEAMS_ENCODING}));
}

// Every -uv_pred name (from the registry, so new schemes are covered) on
// Draco's testdata and the corpus at -cl 10 (valence Edgebreaker from 1000
// faces), the names taking turns over the meshes so that each name meets
// several meshes without encoding every mesh with every name.
TEST(UvSeamEdgebreakerTest, CombinesWithEveryUvPrediction) {
  std::vector<std::string> uv_preds;
  for (const UvPredictionName &entry : UvPredictionNames()) {
    uv_preds.push_back(entry.name);
  }
  ASSERT_GE(uv_preds.size(), 6u);
  std::vector<std::string> meshes;
  for (const std::string &name : DracoTestdataTexturedMeshes()) {
    meshes.push_back(DracoTestdataPath(name));
  }
  ASSERT_GE(meshes.size(), 2 * uv_preds.size());
  for (const std::string &path : CorpusMeshPaths()) {
    meshes.push_back(path);
  }
  for (size_t i = 0; i < meshes.size(); ++i) {
    const auto mesh = ReadTestMesh(meshes[i]);
    ASSERT_TRUE(mesh.ok()) << meshes[i];
    const std::string &uv_pred = uv_preds[i % uv_preds.size()];
    ExpectContextSeamsDecodeLikeStock(*mesh.value(),
                                      Settings(14, 12, 10, uv_pred),
                                      meshes[i] + " " + uv_pred);
  }
}

// Several texture coordinate sets (and normals) on one mesh.
TEST(UvSeamEdgebreakerTest, DecodesSeveralSeamedAttributesLikeStock) {
  for (const std::string name :
       {"sphere_two_tex_coords.gltf", "MultiUVTest/glTF/MultiUVTest.gltf",
        "sphere.obj", "cube_att.obj"}) {
    const auto mesh = ReadTestMesh(DracoTestdataPath(name));
    ASSERT_TRUE(mesh.ok()) << name;
    const auto problem = BuildUvSeamProblem(*mesh.value(), {14, 12, 10});
    ASSERT_TRUE(problem.ok()) << name;
    EXPECT_GE(problem.value().num_attributes, 2) << name;
    ExpectContextSeamsDecodeLikeStock(*mesh.value(), {14, 12, 10}, name);
  }
}

TEST(UvSeamEdgebreakerTest, LibraryOptionSelectsContextSeams) {
  const auto mesh = ReadTestMesh(UvTestdataPath("bumpy_cube_sphere.obj"));
  ASSERT_TRUE(mesh.ok());
  Encoder encoder;
  encoder.SetAttributeQuantization(GeometryAttribute::POSITION, 14);
  encoder.SetAttributeQuantization(GeometryAttribute::TEX_COORD, 12);
  encoder.SetSpeedOptions(0, 0);
  SetUvSeamCoding(UvSeamCoding::kContext, &encoder.options());
  EncoderBuffer buffer;
  ASSERT_TRUE(encoder.EncodeMeshToBuffer(*mesh.value(), &buffer).ok());
  const std::vector<char> bytes(buffer.data(), buffer.data() + buffer.size());
  EXPECT_EQ(EdgebreakerMethodOf(bytes),
            MESH_EDGEBREAKER_VALENCE_CONTEXT_SEAMS_ENCODING);
  EXPECT_TRUE(DecodeDracoMesh(bytes).ok());
}

// The bytes of the seam stream inside |file|: the stream is exactly what
// EncodeUvSeams() returns for the mesh's seam problem.
std::pair<size_t, size_t> FindSeamStream(const std::vector<char> &file,
                                         const UvSeamProblem &problem) {
  std::vector<uint8_t> stream;
  EXPECT_TRUE(EncodeUvSeams(problem.table, problem.num_attributes, problem.bits,
                            &stream));
  const auto it = std::search(
      file.begin(), file.end(), stream.begin(), stream.end(),
      [](char a, uint8_t b) { return static_cast<uint8_t>(a) == b; });
  return {static_cast<size_t>(it - file.begin()), stream.size()};
}

TEST(UvSeamEdgebreakerTest, CorruptOrTruncatedSeamDataFailsToDecode) {
  for (const std::string name : {"bumpy_cube_sphere.obj", "torus_uv.obj"}) {
    const auto mesh = ReadTestMesh(UvTestdataPath(name));
    ASSERT_TRUE(mesh.ok()) << name;
    for (const int cl : {5, 10}) {
      const UvEncodeSettings settings = Settings(14, 12, cl, "draco+context");
      const auto file = EncodeMeshToBytes(*mesh.value(), settings);
      const auto problem = BuildUvSeamProblem(*mesh.value(), settings);
      ASSERT_TRUE(file.ok() && problem.ok()) << name;
      const auto [begin, size] = FindSeamStream(file.value(), problem.value());
      ASSERT_GE(size, 4u) << name;
      ASSERT_LT(begin + size, file.value().size()) << name;
      for (size_t i = begin; i < begin + size; ++i) {
        std::vector<char> altered = file.value();
        altered[i] ^= 0x10;
        EXPECT_FALSE(DecodeDracoMesh(altered).ok()) << name << " byte " << i;
      }
      // A different length (its last varint byte precedes the stream).
      std::vector<char> longer = file.value();
      ++longer[begin - 1];
      EXPECT_FALSE(DecodeDracoMesh(longer).ok()) << name;
      for (size_t keep = begin - 1; keep < begin + size; ++keep) {
        const std::vector<char> truncated(file.value().begin(),
                                          file.value().begin() + keep);
        EXPECT_FALSE(DecodeDracoMesh(truncated).ok()) << name << " " << keep;
      }
    }
  }
}

}  // namespace
}  // namespace draco
