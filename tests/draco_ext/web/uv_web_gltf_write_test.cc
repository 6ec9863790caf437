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
// The JS encoder's glTF writes (DracoUvModule::BeginGltfWrite/EndGltfWrite,
// draco_ext/web/uv_web_encoder.h): inside one, -uv_pred auto makes the same
// choice as the native glTF encoder (ConfigureUvCompressionForGltf()) on the
// first primitive that would need the glTF extension, so a file never grows
// by the marker without saving more; later encodes of the write ride on the
// marker; outside a write, and for other predictions, nothing changes. The
// same for -tangent_pred auto on meshes with tangents (as glTF pipelines
// hand them over, GENERIC), alone and with -uv_pred auto, while a named
// tangent scheme always keeps draco-uv ids, as natively.
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "draco/compression/draco_compression_options.h"
#include "draco_ext/gltf/uv_gltf.h"
#include "draco_ext/options/tangent_prediction_options.h"
#include "draco_ext/web/uv_web_encoder.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

std::unique_ptr<Mesh> LoadMesh(const std::string &path) {
  auto mesh = ReadTestMesh(path);
  EXPECT_TRUE(mesh.ok()) << path;
  return mesh.ok() ? std::move(mesh).value() : nullptr;
}

// A draco::Encoder set up like glTF-Transform's KHRDracoMeshCompression
// defaults (-qp 14 -qt 12 -qn 10 -qg 12, speed 5).
void SetUpLikeGltfTransform(Encoder *encoder) {
  encoder->SetAttributeQuantization(GeometryAttribute::POSITION, 14);
  encoder->SetAttributeQuantization(GeometryAttribute::TEX_COORD, 12);
  encoder->SetAttributeQuantization(GeometryAttribute::NORMAL, 10);
  encoder->SetAttributeQuantization(GeometryAttribute::GENERIC, 12);
  encoder->SetSpeedOptions(5, 5);
}

DracoUvOptions Options(const std::string &prediction,
                       const std::string &seams = "") {
  DracoUvOptions options;
  EXPECT_TRUE(options.SetPrediction(prediction.c_str()));
  EXPECT_TRUE(options.SetSeams(seams.c_str()));
  return options;
}

std::vector<char> Bytes(const EncoderBuffer &buffer) {
  return std::vector<char>(buffer.data(), buffer.data() + buffer.size());
}

std::vector<char> EncodeThroughWeb(UvWebEncoder *web, const Mesh &mesh) {
  Encoder encoder;
  SetUpLikeGltfTransform(&encoder);
  EncoderBuffer buffer;
  const Status status = web->EncodeMesh(mesh, &encoder, &buffer);
  EXPECT_TRUE(status.ok()) << status.error_msg_string();
  return Bytes(buffer);
}

// |mesh| with |prediction| coded by the native glTF encoder as the first
// primitive of a file; |marked| says whether the file got the extension.
std::vector<char> EncodeAsNativeGltf(Mesh *mesh, const std::string &prediction,
                                     bool *marked) {
  DracoCompressionOptions options;
  options.uv.prediction = Options(prediction).options().prediction;
  mesh->SetCompressionOptions(options);
  Encoder settings;
  SetUpLikeGltfTransform(&settings);
  ExpertEncoder encoder(*mesh);
  encoder.Reset(settings.CreateExpertEncoderOptions(*mesh));
  std::set<std::string> used, required;
  EXPECT_TRUE(
      ConfigureUvCompressionForGltf(*mesh, nullptr, encoder, &used, &required)
          .ok());
  *marked = required.count(kUvGltfExtension) > 0;
  EncoderBuffer buffer;
  EXPECT_TRUE(encoder.EncodeToBuffer(&buffer).ok());
  mesh->SetCompressionOptions(DracoCompressionOptions());
  return Bytes(buffer);
}

// The same with the tangent prediction |tangent| (and |uv|) on a mesh with
// tangents.
std::vector<char> EncodeTangentsAsNativeGltf(Mesh *mesh,
                                             const DracoUvOptions &options,
                                             bool *marked) {
  DracoCompressionOptions compression;
  compression.uv = options.options();
  mesh->SetCompressionOptions(compression);
  Encoder settings;
  SetUpLikeGltfTransform(&settings);
  ExpertEncoder encoder(*mesh);
  encoder.Reset(settings.CreateExpertEncoderOptions(*mesh));
  std::set<std::string> used, required;
  EXPECT_TRUE(
      ConfigureUvCompressionForGltf(*mesh, nullptr, encoder, &used, &required)
          .ok());
  *marked = required.count(kUvGltfExtension) > 0;
  EncoderBuffer buffer;
  EXPECT_TRUE(encoder.EncodeToBuffer(&buffer).ok());
  mesh->SetCompressionOptions(DracoCompressionOptions());
  return Bytes(buffer);
}

std::vector<char> StockBytes(const Mesh &mesh) {
  UvWebModuleState state;
  UvWebEncoder web(&state);
  return EncodeThroughWeb(&web, mesh);
}

// Each mesh as the first primitive of a glTF write: the native glTF
// encoder's bytes and marking, and auto's bytes + the marker never exceed
// stock coding's. Both outcomes occur over the meshes.
TEST(UvWebGltfWriteTest, AutoMakesTheNativeGltfEncodersChoice) {
  int kept = 0, dropped = 0;
  for (const std::string &path : TexturedObjPlyMeshPaths()) {
    const std::unique_ptr<Mesh> mesh = LoadMesh(path);
    ASSERT_NE(mesh, nullptr);
    UvWebModuleState state;
    DracoUvModule module(&state);
    const DracoUvOptions options = Options("auto");
    ASSERT_TRUE(module.SetDefault(&options));
    module.BeginGltfWrite();
    UvWebEncoder web(&state);
    const std::vector<char> ours = EncodeThroughWeb(&web, *mesh);
    module.EndGltfWrite();

    bool marked = false;
    EXPECT_EQ(ours, EncodeAsNativeGltf(mesh.get(), "auto", &marked)) << path;
    EXPECT_EQ(web.UsedDracoUvCoding(), marked) << path;
    EXPECT_EQ(module.GetNumEncodesWithDracoUvIds(), marked ? 1 : 0);
    const size_t stock_size = StockBytes(*mesh).size();
    EXPECT_LE(ours.size() + (marked ? kUvGltfExtensionJsonBytes : 0),
              stock_size)
        << path;
    if (marked) {
      ++kept;
    } else {
      ++dropped;
    }
  }
  EXPECT_GT(kept, 0);
  EXPECT_GT(dropped, 0);
}

// -tangent_pred auto (alone and with -uv_pred auto) and mikktspace as the
// first primitive of a glTF write: the native glTF encoder's bytes and
// marking; auto never exceeds stock coding with the marker counted, the
// named scheme always marks.
TEST(UvWebGltfWriteTest, TangentPredictionMakesTheNativeGltfEncodersChoice) {
  for (const std::string name :
       {"small_torus_uv_tangents.glb", "small_cube_sphere_tangents.glb",
        "crane_spot_tangents.glb"}) {
    std::unique_ptr<Mesh> mesh = LoadMesh(UvTestdataPath(name));
    ASSERT_NE(mesh, nullptr);
    for (const int att_id : TangentAttributeIds(*mesh)) {
      mesh->attribute(att_id)->set_attribute_type(GeometryAttribute::GENERIC);
    }
    for (const std::string uv : {"", "auto"}) {
      for (const std::string tangent : {"auto", "mikktspace"}) {
        UvWebModuleState state;
        DracoUvModule module(&state);
        DracoUvOptions options = Options(uv);
        ASSERT_TRUE(options.SetTangentPrediction(tangent.c_str()));
        ASSERT_TRUE(module.SetDefault(&options));
        module.BeginGltfWrite();
        UvWebEncoder web(&state);
        const std::vector<char> ours = EncodeThroughWeb(&web, *mesh);
        module.EndGltfWrite();
        const std::string what = name + " " + uv + " " + tangent;
        bool marked = false;
        EXPECT_EQ(ours,
                  EncodeTangentsAsNativeGltf(mesh.get(), options, &marked))
            << what;
        EXPECT_EQ(web.UsedDracoUvCoding(), marked) << what;
        if (tangent == "mikktspace") {
          EXPECT_TRUE(marked) << what;
        } else {
          EXPECT_LE(ours.size() + (marked ? kUvGltfExtensionJsonBytes : 0),
                    StockBytes(*mesh).size())
              << what;
        }
      }
    }
  }
}

// A small mesh whose draco-uv saving does not pay for the marker, and a
// large one whose saving does.
struct SmallAndLarge {
  std::unique_ptr<Mesh> small, large;
};

SmallAndLarge FindSmallAndLarge() {
  SmallAndLarge meshes;
  for (const std::string &path : TexturedObjPlyMeshPaths()) {
    std::unique_ptr<Mesh> mesh = LoadMesh(path);
    UvWebModuleState state;
    UvWebEncoder web(&state);
    const DracoUvOptions options = Options("auto");
    EXPECT_TRUE(web.SetForType(GeometryAttribute::TEX_COORD, &options));
    const size_t auto_size = EncodeThroughWeb(&web, *mesh).size();
    const size_t stock_size = StockBytes(*mesh).size();
    if (!web.UsedDracoUvCoding()) {
      continue;
    }
    if (auto_size + kUvGltfExtensionJsonBytes >= stock_size) {
      if (meshes.small == nullptr) {
        meshes.small = std::move(mesh);
      }
    } else if (meshes.large == nullptr) {
      meshes.large = std::move(mesh);
    }
  }
  return meshes;
}

TEST(UvWebGltfWriteTest, LaterEncodesRideOnTheMarkerAndWritesEnd) {
  const SmallAndLarge meshes = FindSmallAndLarge();
  ASSERT_NE(meshes.small, nullptr);
  ASSERT_NE(meshes.large, nullptr);
  const std::vector<char> small_stock = StockBytes(*meshes.small);
  UvWebModuleState state;
  DracoUvModule module(&state);
  const DracoUvOptions options = Options("auto");
  ASSERT_TRUE(module.SetDefault(&options));
  UvWebEncoder web(&state);
  // Outside a write, auto compares Draco bytes only.
  const std::vector<char> small_auto = EncodeThroughWeb(&web, *meshes.small);
  EXPECT_TRUE(web.UsedDracoUvCoding());
  EXPECT_LT(small_auto.size(), small_stock.size());

  // First in a write, the small mesh stays stock and says why.
  module.BeginGltfWrite();
  EXPECT_EQ(EncodeThroughWeb(&web, *meshes.small), small_stock);
  EXPECT_FALSE(web.UsedDracoUvCoding());
  EXPECT_NE(std::string(web.GetUvCompressionMessage()).find(kUvGltfExtension),
            std::string::npos)
      << web.GetUvCompressionMessage();
  // The large mesh pays for the marker; then the small one rides on it.
  EncodeThroughWeb(&web, *meshes.large);
  EXPECT_TRUE(web.UsedDracoUvCoding());
  UvWebEncoder second(&state);
  EXPECT_EQ(EncodeThroughWeb(&second, *meshes.small), small_auto);
  EXPECT_TRUE(second.UsedDracoUvCoding());

  // A new write starts without the marker again.
  module.BeginGltfWrite();
  EXPECT_EQ(EncodeThroughWeb(&web, *meshes.small), small_stock);
  module.EndGltfWrite();
  EXPECT_EQ(EncodeThroughWeb(&web, *meshes.small), small_auto);
  EXPECT_EQ(module.GetNumEncodesWithDracoUvIds(), 4);
}

// Only auto falls back: an explicit prediction, or context seams (which need
// the marker anyway), keep draco-uv's coding in a write and pay for the
// marker, so auto rides on it afterwards.
TEST(UvWebGltfWriteTest, ExplicitCodingsAndContextSeamsAreKept) {
  const SmallAndLarge meshes = FindSmallAndLarge();
  ASSERT_NE(meshes.small, nullptr);
  for (const auto &[prediction, seams] :
       std::vector<std::pair<std::string, std::string>>{{"weighted", ""},
                                                        {"auto", "context"}}) {
    UvWebModuleState state;
    DracoUvModule module(&state);
    module.BeginGltfWrite();
    UvWebEncoder web(&state);
    const DracoUvOptions options = Options(prediction, seams);
    ASSERT_TRUE(web.SetForType(GeometryAttribute::TEX_COORD, &options));
    UvWebModuleState outside;
    UvWebEncoder reference(&outside);
    ASSERT_TRUE(reference.SetForType(GeometryAttribute::TEX_COORD, &options));
    EXPECT_EQ(EncodeThroughWeb(&web, *meshes.small),
              EncodeThroughWeb(&reference, *meshes.small))
        << prediction << "+" << seams;
    EXPECT_TRUE(web.UsedDracoUvCoding()) << prediction << "+" << seams;

    const DracoUvOptions automatic = Options("auto");
    UvWebEncoder later(&state);
    ASSERT_TRUE(later.SetForType(GeometryAttribute::TEX_COORD, &automatic));
    EncodeThroughWeb(&later, *meshes.small);
    EXPECT_TRUE(later.UsedDracoUvCoding()) << prediction << "+" << seams;
    module.EndGltfWrite();
  }
}

}  // namespace
}  // namespace draco
