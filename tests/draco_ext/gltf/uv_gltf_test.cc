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
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "draco/compression/expert_encode.h"
#include "draco/io/scene_io.h"
#include "draco/material/material.h"
#include "draco/mesh/mesh_utils.h"
#include "draco/metadata/geometry_metadata.h"
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
  ASSERT_TRUE(ConfigureUvCompressionForGltf(*mesh_, nullptr, configured, &used_,
                                            &required_)
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
    ASSERT_TRUE(ConfigureUvCompressionForGltf(*mesh_, nullptr, *encoder, &used_,
                                              &required_)
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
  EXPECT_EQ(ConfigureUvCompressionForGltf(*mesh_, nullptr, *laplacian, &used_,
                                          &required_)
                .ok(),
            HasUvLaplacianCoder());
  const std::unique_ptr<ExpertEncoder> weighted =
      MakeEncoder(UvOptions("weighted", "2%"));
  EXPECT_FALSE(ConfigureUvCompressionForGltf(*mesh_, nullptr, *weighted, &used_,
                                             &required_)
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
    EXPECT_EQ(ConfigureUvCompressionForGltf(*mesh_, nullptr, *hooked, &used_,
                                            &required_)
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
    ASSERT_TRUE(ConfigureUvCompressionForGltf(*mesh_, nullptr, *encoder, &used_,
                                              &required_)
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
  options.tangents = {"draco"};
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
  options.tangents = {"draco"};
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

// draco_transcoder -tangent_pred mikktspace on every glTF/GLB asset of
// Draco's testdata (tangents with one or two UV sets, several primitives,
// shared meshes, skins, none at all): every attribute reads back like
// stock coding, and the file requires the extension only where it has
// tangents.
TEST(UvGltfTranscodeTest, TangentPredictionRoundTripsOnEveryAsset) {
  UvGltfEvalOptions options;
  options.schemes = {"draco"};
  options.tangents = {"mikktspace"};
  options.glb = true;
  int with_tangents = 0;
  for (const std::string &asset : DracoTestdataGltfAssets()) {
    const auto rows = EvaluateGltfAsset(DracoTestdataPath(asset), asset,
                                        options, UvTempPath(""));
    if (!rows.ok()) {
      continue;  // Morph targets etc.: stock draco_transcoder fails too.
    }
    for (const UvGltfEvalRow &row : rows.value()) {
      EXPECT_TRUE(row.round_trip_ok) << asset << ": " << row.detail;
      with_tangents += !row.tangent_costs.empty();
      if (row.tangent_costs.empty()) {
        EXPECT_FALSE(row.requires_extension) << asset;
        EXPECT_EQ(row.bytes, row.stock_bytes) << asset;
      }
    }
  }
  EXPECT_GE(with_tangents, 15);
}

TEST(UvGltfTranscodeTest, AutoRoundTripsOnAssetsOfEveryKind) {
  UvGltfEvalOptions options;
  options.schemes = {"auto"};
  options.tangents = {"auto"};
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
  options.tangents = {"draco"};
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

TEST(UvGltfTangentTest, TangentsFollowTheNormalTexturesTexCoords) {
  EXPECT_EQ(GltfTangentTexCoordSet(nullptr), 0);
  const Material plain;
  EXPECT_EQ(GltfTangentTexCoordSet(&plain), 0);
  for (const int set : {0, 1}) {
    Material material;
    material.SetTextureMap(std::unique_ptr<Texture>(new Texture()),
                           TextureMap::NORMAL_TANGENT_SPACE, set);
    EXPECT_EQ(GltfTangentTexCoordSet(&material), set);
  }
  // Other textures on TEXCOORD_1 leave the tangents on TEXCOORD_0.
  Material colored;
  colored.SetTextureMap(std::unique_ptr<Texture>(new Texture()),
                        TextureMap::COLOR, 1);
  EXPECT_EQ(GltfTangentTexCoordSet(&colored), 0);
}

TEST(UvGltfTangentTest,
     FirstTexCoordIsTexcoord0UnlessItsMetadataSaysOtherwise) {
  auto mesh = ReadTestMesh(DracoTestdataPath("sphere_two_tex_coords.gltf"));
  ASSERT_TRUE(mesh.ok());
  ASSERT_EQ(mesh.value()->NumNamedAttributes(GeometryAttribute::TEX_COORD), 2);
  EXPECT_EQ(GltfTexCoordSetOfFirstTexCoord(*mesh.value()), 0);
  std::unique_ptr<AttributeMetadata> metadata(new AttributeMetadata());
  metadata->AddEntryString("attribute_name", "TEXCOORD_1");
  mesh.value()->AddAttributeMetadata(
      mesh.value()->GetNamedAttributeId(GeometryAttribute::TEX_COORD),
      std::move(metadata));
  EXPECT_EQ(GltfTexCoordSetOfFirstTexCoord(*mesh.value()), 1);
}

// |mesh|, a glTF primitive with |uv| options, and its encoder as
// GltfAsset::CompressMeshWithDraco() sets it up for draco_transcoder -qp 14
// -qt 12 -qn 10 -qtg 8 at its compression level 7.
struct GltfPrimitive {
  std::unique_ptr<Mesh> mesh;
  std::unique_ptr<ExpertEncoder> encoder;
  std::set<std::string> used, required;
};

GltfPrimitive MakePrimitive(const std::string &path,
                            const UvCompressionOptions &uv) {
  GltfPrimitive primitive;
  auto mesh = ReadTestMesh(path);
  EXPECT_TRUE(mesh.ok()) << path;
  primitive.mesh = std::move(mesh).value();
  DracoCompressionOptions options;
  options.uv = uv;
  primitive.mesh->SetCompressionOptions(options);
  primitive.encoder.reset(new ExpertEncoder(*primitive.mesh));
  primitive.encoder->SetSpeedOptions(3, 3);
  for (int i = 0; i < primitive.mesh->num_attributes(); ++i) {
    const GeometryAttribute::Type type =
        primitive.mesh->attribute(i)->attribute_type();
    const int bits = type == GeometryAttribute::POSITION    ? 14
                     : type == GeometryAttribute::TEX_COORD ? 12
                     : type == GeometryAttribute::NORMAL    ? 10
                                                            : 8;
    primitive.encoder->SetAttributeQuantization(i, bits);
  }
  return primitive;
}

// Configures |primitive| drawn with |material|; returns the summary.
std::string Configure(GltfPrimitive *primitive, const Material *material) {
  const auto summary = ConfigureUvCompressionForGltfPrimitive(
      *primitive->mesh, material, primitive->encoder.get(), &primitive->used,
      &primitive->required);
  EXPECT_TRUE(summary.ok()) << summary.status().error_msg();
  return summary.ok() ? summary.value() : "";
}

int TangentScheme(const GltfPrimitive &primitive) {
  return primitive.encoder->options().GetAttributeInt(
      primitive.mesh->GetNamedAttributeId(GeometryAttribute::TANGENT),
      "prediction_scheme", PREDICTION_UNDEFINED);
}

UvCompressionOptions TangentOptions(const std::string &uv,
                                    TangentPrediction tangent) {
  UvCompressionOptions options = UvOptions(uv);
  options.tangent.prediction = tangent;
  return options;
}

// Encoded bytes of |encoder|.
std::vector<char> EncodedBytes(ExpertEncoder *encoder) {
  EncoderBuffer buffer;
  EXPECT_TRUE(encoder->EncodeToBuffer(&buffer).ok());
  return std::vector<char>(buffer.data(), buffer.data() + buffer.size());
}

Material NormalTextureOn(int tex_coord_set) {
  Material material;
  material.SetTextureMap(std::unique_ptr<Texture>(new Texture()),
                         TextureMap::NORMAL_TANGENT_SPACE, tex_coord_set);
  return material;
}

// The tangent prediction reads TEXCOORD_0: a primitive whose normal texture
// uses TEXCOORD_1 keeps stock tangent coding, says why, and is coded as
// without -tangent_pred; with the normal texture on TEXCOORD_0 it is
// predicted.
TEST(UvGltfTangentTest, TangentsOfANormalTextureOnTexcoord1KeepStockCoding) {
  const Material on_texcoord_1 = NormalTextureOn(1);
  const Material on_texcoord_0 = NormalTextureOn(0);
  for (const std::string &path : TangentGltfAssetPaths()) {
    for (const TangentPrediction tangent :
         {TangentPrediction::kMikkTSpace, TangentPrediction::kGeometric,
          TangentPrediction::kAuto}) {
      const std::string label = path + " " + TangentPredictionNameOf(tangent);
      GltfPrimitive kept = MakePrimitive(path, TangentOptions("", tangent));
      EXPECT_NE(Configure(&kept, &on_texcoord_1)
                    .find("keeps stock coding: the material's normal texture "
                          "uses TEXCOORD_1, the prediction reads TEXCOORD_0"),
                std::string::npos)
          << label;
      EXPECT_EQ(TangentScheme(kept), PREDICTION_UNDEFINED) << label;
      EXPECT_TRUE(kept.required.empty()) << label;
      GltfPrimitive stock = MakePrimitive(path, UvCompressionOptions());
      EXPECT_EQ(EncodedBytes(kept.encoder.get()),
                EncodedBytes(stock.encoder.get()))
          << label;

      GltfPrimitive predicted =
          MakePrimitive(path, TangentOptions("", tangent));
      Configure(&predicted, &on_texcoord_0);
      if (tangent != TangentPrediction::kAuto) {
        EXPECT_EQ(TangentScheme(predicted), MESH_PREDICTION_GEOMETRIC_TANGENT)
            << label;
      }
      EXPECT_EQ(predicted.required.count(kUvGltfExtension),
                TangentScheme(predicted) == MESH_PREDICTION_GEOMETRIC_TANGENT)
          << label;
    }
  }
}

// A scheme the options name is kept whatever it saves, even where -uv_pred
// or -tangent_pred auto on another attribute would not pay for the
// extension: the primitive needs the extension anyway.
TEST(UvGltfTangentTest, NamedSchemesAreKeptNextToAuto) {
  for (const std::string &path : TangentGltfAssetPaths()) {
    GltfPrimitive uv_named = MakePrimitive(
        path, TangentOptions("weighted", TangentPrediction::kAuto));
    Configure(&uv_named, nullptr);
    const int tex_coord =
        uv_named.mesh->GetNamedAttributeId(GeometryAttribute::TEX_COORD);
    EXPECT_EQ(uv_named.encoder->options().GetAttributeInt(
                  tex_coord, "prediction_scheme", PREDICTION_UNDEFINED),
              MESH_PREDICTION_TEX_COORDS_WEIGHTED)
        << path;
    EXPECT_EQ(uv_named.required.count(kUvGltfExtension), 1u) << path;

    GltfPrimitive tangent_named = MakePrimitive(
        path, TangentOptions("auto", TangentPrediction::kMikkTSpace));
    Configure(&tangent_named, nullptr);
    EXPECT_EQ(TangentScheme(tangent_named), MESH_PREDICTION_GEOMETRIC_TANGENT)
        << path;
    EXPECT_EQ(tangent_named.required.count(kUvGltfExtension), 1u) << path;
  }
}

// auto keeps draco-uv ids only where they save more than the extension's
// JSON: a primitive that keeps them is that much smaller than stock coding,
// one that does not is no bigger.
TEST(UvGltfTangentTest, AutoKeepsDracoUvIdsOnlyWhereTheyPayForTheExtension) {
  for (const std::string &path : TangentGltfAssetPaths()) {
    for (const std::string uv : {"", "auto"}) {
      GltfPrimitive primitive =
          MakePrimitive(path, TangentOptions(uv, TangentPrediction::kAuto));
      Configure(&primitive, nullptr);
      GltfPrimitive stock = MakePrimitive(path, UvCompressionOptions());
      const size_t size = EncodedBytes(primitive.encoder.get()).size();
      const size_t stock_size = EncodedBytes(stock.encoder.get()).size();
      if (primitive.required.empty()) {
        // -uv_pred auto may choose one of Draco's own schemes.
        EXPECT_LE(size, stock_size) << path << " " << uv;
      } else {
        EXPECT_LT(size + kUvGltfExtensionJsonBytes, stock_size)
            << path << " " << uv;
      }
    }
  }
}

// Draco's sphere_two_tex_coords.gltf (TANGENT, TEXCOORD_0 and TEXCOORD_1,
// a normal texture) copied into |dir| with its normal texture on
// TEXCOORD_|set|; returns the copy's path.
std::string SphereWithNormalTextureOn(int set, const std::string &dir) {
  fs::create_directories(dir);
  for (const char *file : {"sphere_buffer0.bin", "sphere_Texture0_Normal.png",
                           "sphere_Texture1_BaseColor.png"}) {
    fs::copy_file(DracoTestdataPath(file), fs::path(dir) / file,
                  fs::copy_options::overwrite_existing);
  }
  nlohmann::json json = nlohmann::json::parse(
      ReadText(DracoTestdataPath("sphere_two_tex_coords.gltf")));
  json["materials"][0]["normalTexture"]["texCoord"] = set;
  const std::string path = (fs::path(dir) / "sphere.gltf").string();
  std::ofstream(path) << json.dump(2);
  return path;
}

std::string ReadBytes(const std::string &path) {
  std::ifstream stream(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(stream),
                     std::istreambuf_iterator<char>());
}

// draco_transcoder -tangent_pred through the glTF encoder's hook: a file
// whose normal texture uses TEXCOORD_1 comes out exactly as without the
// flag; with the normal texture on TEXCOORD_0 its tangents are predicted
// and the file requires the extension.
TEST(UvGltfTranscodeTest, TangentPredictionFollowsTheNormalTexturesTexCoords) {
  for (const TangentPrediction prediction :
       {TangentPrediction::kMikkTSpace, TangentPrediction::kGeometric}) {
    DracoCompressionOptions options;
    options.uv.tangent.prediction = prediction;
    for (const int set : {0, 1}) {
      const std::string dir =
          UvTempPath("normal_texture_on_" + std::to_string(set));
      const std::string input = SphereWithNormalTextureOn(set, dir);
      const std::string stock = (fs::path(dir) / "stock.glb").string();
      const std::string ours = (fs::path(dir) / "ours.glb").string();
      ASSERT_TRUE(
          TranscodeGltfFile(input, stock, DracoCompressionOptions()).ok());
      ASSERT_TRUE(TranscodeGltfFile(input, ours, options).ok()) << set;
      EXPECT_EQ(ReadBytes(ours) == ReadBytes(stock), set == 1) << set;
      EXPECT_EQ(RequiresUvGltfExtension(ours).value(), set == 0) << set;
    }
  }
}

// -tangent_pred auto, alone or with -uv_pred auto, never makes a glTF or GLB
// file bigger than the stock transcoder's, the extension's JSON included,
// and the file reads back like the stock one.
TEST(UvGltfTranscodeTest, TangentAutoNeverMakesAFileBiggerThanStock) {
  for (const std::string &path : TangentGltfAssetPaths()) {
    for (const int qtg : {8, 12}) {
      DracoCompressionOptions stock;
      stock.quantization_position.SetQuantizationBits(14);
      stock.quantization_bits_tex_coord = 12;
      stock.quantization_bits_normal = 10;
      stock.quantization_bits_tangent = qtg;
      for (const char *ext : {".gltf", ".glb"}) {
        const std::string label =
            path + " -qtg " + std::to_string(qtg) + " " + ext;
        const std::string stock_file =
            UvTempPath(std::string("stock_tangents/out") + ext);
        fs::create_directories(fs::path(stock_file).parent_path());
        ASSERT_TRUE(TranscodeGltfFile(path, stock_file, stock).ok()) << label;
        const auto stock_scene = ReadSceneFromFile(stock_file);
        ASSERT_TRUE(stock_scene.ok()) << label;
        for (const UvPrediction uv :
             {UvPrediction::kDraco, UvPrediction::kAuto}) {
          DracoCompressionOptions options = stock;
          options.uv.prediction = uv;
          options.uv.tangent.prediction = TangentPrediction::kAuto;
          const std::string file =
              UvTempPath(std::string("auto_tangents/out") + ext);
          fs::create_directories(fs::path(file).parent_path());
          ASSERT_TRUE(TranscodeGltfFile(path, file, options).ok()) << label;
          EXPECT_LE(TranscodedGltfBytes(file).value(),
                    TranscodedGltfBytes(stock_file).value())
              << label << " " << UvPredictionNameOf(uv);
          const auto scene = ReadSceneFromFile(file);
          ASSERT_TRUE(scene.ok()) << label;
          EXPECT_TRUE(
              CompareSceneGeometry(*stock_scene.value(), *scene.value()).ok())
              << label;
        }
      }
    }
  }
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
