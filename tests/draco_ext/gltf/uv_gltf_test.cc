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
#include "draco_ext/gltf/uv_gltf.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "draco/compression/expert_encode.h"
#include "draco/io/scene_io.h"
#include "draco/mesh/mesh_utils.h"
#include "draco_ext/eval/uv_gltf_eval.h"
#include "draco_ext/options/uv_configure.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

namespace fs = std::filesystem;

// The glTF and GLB assets of Draco's testdata, relative to its testdata/.
std::vector<std::string> DracoTestdataGltfAssets() {
  std::vector<std::string> assets;
  const fs::path root = DracoTestdataPath("");
  for (const auto &entry : fs::recursive_directory_iterator(root)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb")) {
      assets.push_back(fs::relative(entry.path(), root).string());
    }
  }
  std::sort(assets.begin(), assets.end());
  return assets;
}

// An encoder set up like GltfAsset::CompressMeshWithDraco() at the
// transcoder's defaults, on a mesh with |uv| options.
class UvGltfEncoderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto mesh = ReadTestMesh(DracoTestdataPath("sphere.gltf"));
    ASSERT_TRUE(mesh.ok()) << mesh.status().error_msg();
    mesh_ = std::move(mesh).value();
    ASSERT_GT(mesh_->NumNamedAttributes(GeometryAttribute::TEX_COORD), 0);
  }

  std::unique_ptr<ExpertEncoder> MakeEncoder(const UvCompressionOptions &uv) {
    DracoCompressionOptions options;
    options.uv = uv;
    mesh_->SetCompressionOptions(options);
    std::unique_ptr<ExpertEncoder> encoder(new ExpertEncoder(*mesh_));
    encoder->SetSpeedOptions(3, 3);
    for (int i = 0; i < mesh_->num_attributes(); ++i) {
      encoder->SetAttributeQuantization(i, 11);
    }
    return encoder;
  }

  std::vector<char> Encode(ExpertEncoder *encoder) {
    EncoderBuffer buffer;
    EXPECT_TRUE(encoder->EncodeToBuffer(&buffer).ok());
    return std::vector<char>(buffer.data(), buffer.data() + buffer.size());
  }

  std::unique_ptr<Mesh> mesh_;
  std::set<std::string> used_, required_;
};

TEST_F(UvGltfEncoderTest, StockOptionsChangeNeitherBitstreamNorExtensions) {
  const std::unique_ptr<ExpertEncoder> untouched =
      MakeEncoder(UvCompressionOptions());
  const std::unique_ptr<ExpertEncoder> configured =
      MakeEncoder(UvCompressionOptions());
  ASSERT_TRUE(
      ConfigureUvCompressionForGltf(*mesh_, configured, &used_, &required_)
          .ok());
  EXPECT_EQ(Encode(untouched.get()), Encode(configured.get()));
  EXPECT_TRUE(used_.empty());
  EXPECT_TRUE(required_.empty());
}

TEST_F(UvGltfEncoderTest, AnchorsReachTheLaplacianCoder) {
  std::vector<std::vector<char>> streams;
  for (const std::string anchors : {"", "50", "0"}) {
    const std::unique_ptr<ExpertEncoder> encoder =
        MakeEncoder(UvOptions("laplacian_mv", anchors));
    ASSERT_TRUE(
        ConfigureUvCompressionForGltf(*mesh_, *encoder, &used_, &required_)
            .ok())
        << anchors;
    streams.push_back(Encode(encoder.get()));
  }
  EXPECT_NE(streams[1], streams[2]);
  // The default places anchors too (UvDefaultExtraAnchors()).
  EXPECT_NE(streams[0], streams[2]);
}

// Like a primitive of a multi-primitive asset that has no texture
// coordinates: -uv_anchors is checked on the options, as on the command
// line, so such a primitive neither fails valid options nor lets invalid
// ones through.
TEST_F(UvGltfEncoderTest, AnchorsAreCheckedOnTheOptionsNotThePrimitive) {
  while (mesh_->NumNamedAttributes(GeometryAttribute::TEX_COORD) > 0) {
    mesh_->DeleteAttribute(
        mesh_->GetNamedAttributeId(GeometryAttribute::TEX_COORD, 0));
  }
  const std::unique_ptr<ExpertEncoder> laplacian =
      MakeEncoder(UvOptions("laplacian_mv", "2%"));
  EXPECT_EQ(
      ConfigureUvCompressionForGltf(*mesh_, *laplacian, &used_, &required_)
          .ok(),
      HasUvLaplacianCoder());
  const std::unique_ptr<ExpertEncoder> weighted =
      MakeEncoder(UvOptions("weighted", "2%"));
  EXPECT_FALSE(
      ConfigureUvCompressionForGltf(*mesh_, *weighted, &used_, &required_)
          .ok());
}

// The glTF hook, draco_transcoder's path (TranscodeGltfFile()) and
// ConfigureUvCompression() accept and reject the same options: every entry
// point checks them with the same strictness.
TEST_F(UvGltfEncoderTest, EntryPointsRejectTheSameAnchorOptions) {
  struct Case {
    std::string scheme;
    std::string anchors;
    bool valid;
  };
  const bool laplacian = HasUvLaplacianCoder();
  const std::string input = DracoTestdataPath("sphere.gltf");
  for (const Case &c : std::vector<Case>{{"draco", "10", false},
                                         {"draco+context", "10", false},
                                         {"weighted", "2%", false},
                                         {"auto", "random:5", false},
                                         {"parallelogram", "0", false},
                                         {"laplacian_mv", "10", laplacian},
                                         {"laplacian_tutte", "random:2%",
                                          laplacian},
                                         {"laplacian_cotan", "", laplacian},
                                         {"weighted", "", true}}) {
    const std::string label = c.scheme + " -uv_anchors '" + c.anchors + "'";
    const UvCompressionOptions uv = UvOptions(c.scheme, c.anchors);
    EXPECT_EQ(CheckUvCompressionOptions(uv).ok(), c.valid) << label;

    const std::unique_ptr<ExpertEncoder> direct =
        MakeEncoder(UvCompressionOptions());
    EXPECT_EQ(ConfigureUvCompression(uv, mesh_.get(), direct.get()).ok(),
              c.valid)
        << label;

    const std::unique_ptr<ExpertEncoder> hooked = MakeEncoder(uv);
    EXPECT_EQ(
        ConfigureUvCompressionForGltf(*mesh_, *hooked, &used_, &required_)
            .ok(),
        c.valid)
        << label;

    DracoCompressionOptions options;
    options.uv = uv;
    EXPECT_EQ(options.Check().ok(), c.valid) << label;
    EXPECT_EQ(
        TranscodeGltfFile(input, UvTempPath("anchors_sphere.gltf"), options)
            .ok(),
        c.valid)
        << label;
  }
}

TEST_F(UvGltfEncoderTest, ExtensionIsRequiredExactlyForDracoUvSchemes) {
  for (const std::string name :
       {"draco", "parallelogram", "portable", "weighted"}) {
    used_.clear();
    required_.clear();
    const std::unique_ptr<ExpertEncoder> encoder =
        MakeEncoder(UvOptions(name));
    ASSERT_TRUE(
        ConfigureUvCompressionForGltf(*mesh_, *encoder, &used_, &required_)
            .ok())
        << name;
    const bool uses_draco_uv = UsesDracoUvScheme(*mesh_, *encoder);
    EXPECT_EQ(uses_draco_uv, name == std::string("weighted")) << name;
    EXPECT_EQ(required_.count(kUvGltfExtension) == 1, uses_draco_uv) << name;
    EXPECT_EQ(used_, required_) << name;
  }
}

// Every glTF/GLB asset of Draco's testdata that draco_transcoder handles
// (multiple primitives, two UV sets, KHR_texture_transform, skinning, a
// point cloud next to a mesh), transcoded to glTF and to GLB with the
// weighted scheme, reads back with the same positions and UVs as with stock
// coding, and requires the draco-uv extension exactly when it has UVs.
TEST(UvGltfTranscodeTest, EveryAssetRoundTripsLikeStockCoding) {
  UvGltfEvalOptions options;
  options.schemes = {"weighted"};
  int evaluated = 0, textured = 0;
  for (const std::string &asset : DracoTestdataGltfAssets()) {
    for (const bool glb : {false, true}) {
      options.glb = glb;
      const auto rows = EvaluateGltfAsset(DracoTestdataPath(asset), asset,
                                          options, UvTempPath(""));
      if (!rows.ok()) {
        continue;  // Morph targets etc.: stock draco_transcoder fails too.
      }
      for (const UvGltfEvalRow &row : rows.value()) {
        ++evaluated;
        textured += row.textured_primitives > 0;
        EXPECT_TRUE(row.round_trip_ok) << asset << ": " << row.detail;
        EXPECT_EQ(row.requires_extension, row.textured_primitives > 0) << asset;
      }
    }
  }
  EXPECT_GE(evaluated, 100);
  EXPECT_GE(textured, 60);
}

// draco_transcoder -uv_seams context, alone and with -uv_pred weighted:
// every asset reads back like stock coding, and every textured one requires
// the draco-uv extension (its seams are draco-uv's).
TEST(UvGltfTranscodeTest, ContextSeamsRoundTripAndRequireTheExtension) {
  UvGltfEvalOptions options;
  options.schemes = {"draco+context", "weighted+context"};
  int textured = 0;
  for (const std::string &asset : DracoTestdataGltfAssets()) {
    const auto rows = EvaluateGltfAsset(DracoTestdataPath(asset), asset,
                                        options, UvTempPath(""));
    if (!rows.ok()) {
      continue;  // Morph targets etc.: stock draco_transcoder fails too.
    }
    for (const UvGltfEvalRow &row : rows.value()) {
      EXPECT_TRUE(row.round_trip_ok)
          << asset << " " << row.scheme << ": " << row.detail;
      if (row.textured_primitives > 0) {
        ++textured;
        EXPECT_TRUE(row.requires_extension) << asset << " " << row.scheme;
      }
    }
  }
  EXPECT_GE(textured, 60);
}

TEST(UvGltfTranscodeTest, AutoRoundTripsOnAssetsOfEveryKind) {
  UvGltfEvalOptions options;
  options.schemes = {"auto"};
  for (const std::string asset :
       {"CesiumMilkTruck/glTF/CesiumMilkTruck.gltf",
        "MultiUVTest/glTF/MultiUVTest.gltf",
        "glTF/TextureTransformTestWithRequired/"
        "TextureTransformTestWithRequired.gltf",
        "CesiumMan/glTF_Binary/CesiumMan.glb", "simple_skin.gltf"}) {
    const auto rows = EvaluateGltfAsset(DracoTestdataPath(asset), asset,
                                        options, UvTempPath(""));
    ASSERT_TRUE(rows.ok()) << asset << ": " << rows.status().error_msg();
    for (const UvGltfEvalRow &row : rows.value()) {
      EXPECT_TRUE(row.round_trip_ok) << asset << ": " << row.detail;
    }
  }
}

// The lossy Laplacian coder through draco_transcoder: positions and
// everything but the UV values read back like stock coding, and the file
// requires the draco-uv extension.
TEST(UvGltfTranscodeTest, LaplacianRoundTripsOnAssetsOfEveryKind) {
  UvGltfEvalOptions options;
  options.schemes = {"laplacian_mv", "laplacian_cotan"};
  for (const std::string asset :
       {"CesiumMilkTruck/glTF/CesiumMilkTruck.gltf",
        "MultiUVTest/glTF/MultiUVTest.gltf",
        "CesiumMan/glTF_Binary/CesiumMan.glb"}) {
    const auto rows = EvaluateGltfAsset(DracoTestdataPath(asset), asset,
                                        options, UvTempPath(""));
    ASSERT_TRUE(rows.ok()) << asset << ": " << rows.status().error_msg();
    for (const UvGltfEvalRow &row : rows.value()) {
      EXPECT_TRUE(row.round_trip_ok) << asset << ": " << row.detail;
      EXPECT_TRUE(row.requires_extension) << asset;
    }
  }
}

TEST(UvGltfTranscodeTest, StockOutputDoesNotRequireTheExtension) {
  const std::string output = UvTempPath("stock_milk_truck.gltf");
  ASSERT_TRUE(
      TranscodeGltfFile(
          DracoTestdataPath("CesiumMilkTruck/glTF/CesiumMilkTruck.gltf"),
          output, DracoCompressionOptions())
          .ok());
  const auto requires_extension = RequiresUvGltfExtension(output);
  ASSERT_TRUE(requires_extension.ok());
  EXPECT_FALSE(requires_extension.value());
}

std::string ReadText(const std::string &path) {
  std::ifstream stream(path);
  return std::string(std::istreambuf_iterator<char>(stream),
                     std::istreambuf_iterator<char>());
}

// The reader hook accepts draco-uv's extension, not every unknown one.
TEST(UvGltfTranscodeTest, ReaderStillRejectsOtherUnknownRequiredExtensions) {
  DracoCompressionOptions options;
  options.uv.prediction = UvPrediction::kWeighted;
  const std::string output = UvTempPath("weighted_sphere.gltf");
  ASSERT_TRUE(
      TranscodeGltfFile(DracoTestdataPath("sphere.gltf"), output, options)
          .ok());
  ASSERT_TRUE(ReadSceneFromFile(output).ok());

  std::string json = ReadText(output);
  const std::string name = kUvGltfExtension;
  std::string other = name;
  other.back() = other.back() == 'x' ? 'y' : 'x';
  for (size_t pos = json.find(name); pos != std::string::npos;
       pos = json.find(name, pos)) {
    json.replace(pos, name.size(), other);
  }
  std::ofstream(output) << json;
  const auto scene = ReadSceneFromFile(output);
  ASSERT_FALSE(scene.ok());
  EXPECT_NE(scene.status().error_msg_string().find(other), std::string::npos);
}

// glTF stores V flipped (v' = 1 - v) relative to Draco's meshes, which
// mirrors every UV chart. The weighted scheme infers the orientation of
// each chart from decoded data, so the mirror image costs the same up to
// the rounding of the flipped values: a few bytes on tiny meshes.
TEST(UvGltfOrientationTest, WeightedCostIsInsensitiveToTheVFlip) {
  double total = 0, total_flipped = 0;
  int compared = 0;
  for (const std::string &name : DracoTestdataTexturedMeshes()) {
    const auto mesh = ReadTestMesh(DracoTestdataPath(name));
    ASSERT_TRUE(mesh.ok()) << name;
    Mesh flipped;
    flipped.Copy(*mesh.value());
    for (int i = 0;
         i < flipped.NumNamedAttributes(GeometryAttribute::TEX_COORD); ++i) {
      ASSERT_TRUE(MeshUtils::FlipTextureUvValues(
          false, true,
          flipped.attribute(
              flipped.GetNamedAttributeId(GeometryAttribute::TEX_COORD, i))));
    }
    const auto original =
        EncodeMeshToBytes(*mesh.value(), Settings(14, 12, 10, "weighted"));
    const auto mirrored =
        EncodeMeshToBytes(flipped, Settings(14, 12, 10, "weighted"));
    ASSERT_TRUE(original.ok() && mirrored.ok()) << name;
    const double a = original.value().size(), b = mirrored.value().size();
    EXPECT_LE(std::abs(a - b), std::max(32.0, 0.01 * a)) << name;
    total += a;
    total_flipped += b;
    ++compared;
  }
  EXPECT_GE(compared, 20);
  EXPECT_LE(std::abs(total - total_flipped), 0.001 * total);
}

}  // namespace
}  // namespace draco
