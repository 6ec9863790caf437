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
// The JS encoder API's C++ side (draco_ext/web/uv_web_encoder.h): names
// checked with the valid ones listed, the module default, per-type and
// per-attribute settings and their precedence, stock output without
// settings, the same bytes as draco_encoder's path with them (tangent
// settings included, with the tangents typed TANGENT as draco_encoder reads
// glTF or GENERIC as the JS pipelines hand them over), and a truthful
// UsedDracoUvCoding() and encode count. Each test has its own module state.
#include "draco_ext/web/uv_web_encoder.h"

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "draco/compression/config/compression_shared.h"
#include "draco_ext/options/tangent_prediction_options.h"
#include "draco_ext/options/uv_encode_settings.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

// Offset of the Edgebreaker connectivity method in a file without metadata.
constexpr size_t kEdgebreakerMethodOffset = 11;

std::unique_ptr<Mesh> LoadMesh(const std::string &path) {
  auto mesh = ReadTestMesh(path);
  EXPECT_TRUE(mesh.ok()) << path;
  return mesh.ok() ? std::move(mesh).value() : nullptr;
}

// torus_uv.obj with a second TEX_COORD attribute, a copy of the first.
std::unique_ptr<Mesh> TwoUvMesh() {
  std::unique_ptr<Mesh> mesh = LoadMesh(UvTestdataPath("torus_uv.obj"));
  const PointAttribute *uv =
      mesh->GetNamedAttribute(GeometryAttribute::TEX_COORD);
  auto copy = std::make_unique<PointAttribute>();
  copy->CopyFrom(*uv);
  mesh->AddAttribute(std::move(copy));
  return mesh;
}

// A draco::Encoder set up like draco_encoder -qp 14 -qt 12 -cl |cl|
// (EncodeMeshWithSettings()).
void SetUpLikeDracoEncoder(int cl, Encoder *encoder) {
  encoder->SetAttributeQuantization(GeometryAttribute::POSITION, 14);
  encoder->SetAttributeQuantization(GeometryAttribute::TEX_COORD, 12);
  encoder->SetAttributeQuantization(GeometryAttribute::NORMAL, 8);
  encoder->SetAttributeQuantization(GeometryAttribute::GENERIC, 8);
  encoder->SetSpeedOptions(10 - cl, 10 - cl);
}

DracoUvOptions Options(const std::string &prediction,
                       const std::string &seams = "",
                       const std::string &anchors = "") {
  DracoUvOptions options;
  EXPECT_TRUE(options.SetPrediction(prediction.c_str()))
      << options.GetErrorMessage();
  EXPECT_TRUE(options.SetSeams(seams.c_str())) << options.GetErrorMessage();
  EXPECT_TRUE(options.SetAnchors(anchors.c_str()))
      << options.GetErrorMessage();
  return options;
}

std::vector<char> Bytes(const EncoderBuffer &buffer) {
  return std::vector<char>(buffer.data(), buffer.data() + buffer.size());
}

// Encodes |mesh| through |web| with a draco::Encoder at -cl |cl|.
std::vector<char> EncodeWithEncoder(UvWebEncoder *web, const Mesh &mesh,
                                    int cl = 10) {
  Encoder encoder;
  SetUpLikeDracoEncoder(cl, &encoder);
  EncoderBuffer buffer;
  const Status status = web->EncodeMesh(mesh, &encoder, &buffer);
  EXPECT_TRUE(status.ok()) << status.error_msg_string();
  return Bytes(buffer);
}

std::vector<char> NativeBytes(const Mesh &mesh, const std::string &scheme,
                              int cl = 10) {
  const auto bytes = EncodeMeshToBytes(mesh, Settings(14, 12, cl, scheme));
  EXPECT_TRUE(bytes.ok()) << bytes.status().error_msg_string();
  return bytes.ok() ? bytes.value() : std::vector<char>();
}

TEST(UvWebEncoderTest, UnknownNamesFailWithTheValidOnes) {
  DracoUvOptions options;
  EXPECT_FALSE(options.SetPrediction("wieghted"));
  const std::string prediction_error = options.GetErrorMessage();
  for (const char *name : {"wieghted", "auto", "weighted_multi", "draco"}) {
    EXPECT_NE(prediction_error.find(name), std::string::npos)
        << prediction_error;
  }
  EXPECT_FALSE(options.SetSeams("contxt"));
  EXPECT_NE(std::string(options.GetErrorMessage()).find("context"),
            std::string::npos)
      << options.GetErrorMessage();
  EXPECT_FALSE(options.SetAnchors("lots"));
  EXPECT_STRNE(options.GetErrorMessage(), "");
  // Failures leave the options stock; a success clears the message.
  EXPECT_TRUE(options.options().IsStock());
  EXPECT_TRUE(options.SetPrediction("weighted"));
  EXPECT_STREQ(options.GetErrorMessage(), "");
  EXPECT_EQ(options.options().prediction, UvPrediction::kWeighted);
  // "" is Draco's own again.
  EXPECT_TRUE(options.SetPrediction(""));
  EXPECT_TRUE(options.options().IsStock());
}

TEST(UvWebEncoderTest, InconsistentOptionsAreRefusedWithAMessage) {
  UvWebModuleState state;
  DracoUvModule module(&state);
  const DracoUvOptions anchors_without_laplacian =
      Options("weighted", "", "50");
  EXPECT_FALSE(module.SetDefault(&anchors_without_laplacian));
  EXPECT_NE(std::string(module.GetErrorMessage()).find("-uv_anchors"),
            std::string::npos)
      << module.GetErrorMessage();
  EXPECT_FALSE(state.default_options().has_value());
  EXPECT_FALSE(module.SetDefault(nullptr));

  UvWebEncoder web(&state);
  EXPECT_FALSE(web.SetForType(GeometryAttribute::TEX_COORD,
                              &anchors_without_laplacian));
  EXPECT_NE(std::string(web.GetUvCompressionMessage()).find("-uv_anchors"),
            std::string::npos);
  const DracoUvOptions weighted = Options("weighted");
  EXPECT_FALSE(web.SetForType(GeometryAttribute::POSITION, &weighted));
  EXPECT_NE(std::string(web.GetUvCompressionMessage()).find("TEX_COORD"),
            std::string::npos);

  const std::unique_ptr<Mesh> mesh = LoadMesh(UvTestdataPath("torus_uv.obj"));
  const int pos = mesh->GetNamedAttributeId(GeometryAttribute::POSITION);
  EXPECT_FALSE(web.SetForAttribute(mesh.get(), pos, &weighted));
  EXPECT_FALSE(web.SetForAttribute(mesh.get(), mesh->num_attributes(),
                                   &weighted));
  PointCloud cloud;
  EXPECT_FALSE(web.SetForAttribute(&cloud, 0, &weighted));
  // Nothing was set: the encode is stock.
  EXPECT_EQ(EncodeWithEncoder(&web, *mesh), NativeBytes(*mesh, ""));
}

TEST(UvWebEncoderTest, WithoutSettingsTheOutputIsStockDracos) {
  for (const std::string &path : TexturedObjPlyMeshPaths()) {
    const std::unique_ptr<Mesh> mesh = LoadMesh(path);
    UvWebModuleState state;
    UvWebEncoder web(&state);
    for (const int cl : {0, 7, 10}) {
      Encoder stock;
      SetUpLikeDracoEncoder(cl, &stock);
      EncoderBuffer expected;
      ASSERT_TRUE(stock.EncodeMeshToBuffer(*mesh, &expected).ok()) << path;
      EXPECT_EQ(EncodeWithEncoder(&web, *mesh, cl), Bytes(expected)) << path;
      EXPECT_FALSE(web.UsedDracoUvCoding());
      EXPECT_STREQ(web.GetUvCompressionMessage(), "");

      ExpertEncoder expert(*mesh);
      expert.Reset(stock.CreateExpertEncoderOptions(*mesh));
      EncoderBuffer through_web;
      ASSERT_TRUE(web.EncodeWithExpert(*mesh, &expert, &through_web).ok());
      EXPECT_EQ(Bytes(through_web), Bytes(expected)) << path;
    }
    EXPECT_EQ(state.num_encodes_with_draco_uv_ids(), 0);
  }
}

// The module default gives draco_encoder's bytes for the same flags, on
// every mesh and for every setting.
TEST(UvWebEncoderTest, ModuleDefaultWritesDracoEncodersBytes) {
  for (const std::string &path : TexturedObjPlyMeshPaths()) {
    const std::unique_ptr<Mesh> mesh = LoadMesh(path);
    for (const std::string scheme :
         {"auto", "weighted_multi", "auto+context", "parallelogram"}) {
      UvWebModuleState state;
      DracoUvModule module(&state);
      const size_t plus = scheme.find('+');
      const DracoUvOptions options =
          Options(scheme.substr(0, plus),
                  plus == std::string::npos ? "" : scheme.substr(plus + 1));
      ASSERT_TRUE(module.SetDefault(&options)) << module.GetErrorMessage();
      UvWebEncoder web(&state);
      EXPECT_EQ(EncodeWithEncoder(&web, *mesh), NativeBytes(*mesh, scheme))
          << path << " " << scheme;
      EXPECT_NE(std::string(web.GetUvCompressionMessage()).find("UV "),
                std::string::npos);
    }
  }
}

// SetRmse() and SetTexels() are draco_encoder's -uv_rmse and -uv_texels:
// the same bytes natively, each replacing the other, bad values refused.
TEST(UvWebEncoderTest, ErrorTargetsWriteDracoEncodersBytes) {
  DracoUvOptions options;
  for (const double bad : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    EXPECT_FALSE(options.SetRmse(bad));
    EXPECT_NE(std::string(options.GetErrorMessage()), "");
    EXPECT_FALSE(options.SetTexels(bad, 4096));
  }
  EXPECT_FALSE(options.SetTexels(0.5, 0));
  EXPECT_FALSE(options.options().MaxUvRmse().has_value());
  const std::unique_ptr<Mesh> mesh = LoadMesh(UvTestdataPath("crane_spot.obj"));
  for (const bool texels : {false, true}) {
    ASSERT_TRUE(texels ? options.SetTexels(2.0, 1024) : options.SetRmse(1e-3))
        << options.GetErrorMessage();
    EXPECT_EQ(options.options().MaxUvRmse().value(),
              texels ? 2.0 / 1024 : 1e-3);
    UvWebModuleState state;
    UvWebEncoder web(&state);
    ASSERT_TRUE(web.SetForType(GeometryAttribute::TEX_COORD, &options))
        << web.GetUvCompressionMessage();
    UvEncodeSettings settings = Settings(14, 12, 10, "");
    settings.uv = options.options();
    const auto native = EncodeMeshToBytes(*mesh, settings);
    ASSERT_TRUE(native.ok()) << native.status().error_msg_string();
    EXPECT_EQ(EncodeWithEncoder(&web, *mesh), native.value());
    EXPECT_NE(std::string(web.GetUvCompressionMessage()).find("error target"),
              std::string::npos);
  }
}

TEST(UvWebEncoderTest, ModuleDefaultAppliesToEveryTexCoordAttribute) {
  const std::unique_ptr<Mesh> mesh = TwoUvMesh();
  UvWebModuleState state;
  DracoUvModule module(&state);
  const DracoUvOptions weighted = Options("weighted");
  ASSERT_TRUE(module.SetDefault(&weighted));
  UvWebEncoder web(&state);
  const std::vector<char> bytes = EncodeWithEncoder(&web, *mesh);
  const std::string message = web.GetUvCompressionMessage();
  EXPECT_NE(message.find("TEX_COORD 0 (attribute 1) -> weighted"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("TEX_COORD 1 (attribute 2) -> weighted"),
            std::string::npos)
      << message;
  EXPECT_EQ(bytes, NativeBytes(*mesh, "weighted"));
  EXPECT_TRUE(web.UsedDracoUvCoding());

  // Cleared, the module is stock again.
  module.ClearDefault();
  EXPECT_EQ(EncodeWithEncoder(&web, *mesh), NativeBytes(*mesh, ""));
  EXPECT_FALSE(web.UsedDracoUvCoding());
  EXPECT_EQ(module.GetNumEncodesWithDracoUvIds(), 1);
}

TEST(UvWebEncoderTest, OwnSettingsOverrideTheModuleDefault) {
  const std::unique_ptr<Mesh> mesh = TwoUvMesh();
  UvWebModuleState state;
  DracoUvModule module(&state);
  const DracoUvOptions weighted = Options("weighted");
  const DracoUvOptions stock = Options("");
  ASSERT_TRUE(module.SetDefault(&weighted));

  // Encoder: by type, for every TEX_COORD attribute.
  UvWebEncoder by_type(&state);
  ASSERT_TRUE(by_type.SetForType(GeometryAttribute::TEX_COORD, &stock));
  EXPECT_EQ(EncodeWithEncoder(&by_type, *mesh), NativeBytes(*mesh, ""));
  EXPECT_FALSE(by_type.UsedDracoUvCoding());

  // ExpertEncoder: attribute 2 keeps stock prediction, attribute 1 the
  // default.
  const int second = mesh->GetNamedAttributeId(GeometryAttribute::TEX_COORD, 1);
  UvWebEncoder by_attribute(&state);
  ASSERT_TRUE(by_attribute.SetForAttribute(mesh.get(), second, &stock));
  Encoder options;
  SetUpLikeDracoEncoder(10, &options);
  ExpertEncoder expert(*mesh);
  expert.Reset(options.CreateExpertEncoderOptions(*mesh));
  EncoderBuffer buffer;
  ASSERT_TRUE(by_attribute.EncodeWithExpert(*mesh, &expert, &buffer).ok());
  const std::string message = by_attribute.GetUvCompressionMessage();
  EXPECT_NE(message.find("TEX_COORD 0 (attribute 1) -> weighted"),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find("TEX_COORD 1"), std::string::npos) << message;
  EXPECT_TRUE(by_attribute.UsedDracoUvCoding());
  // The caller's ExpertEncoder keeps its own options.
  EXPECT_EQ(expert.options().GetAttributeInt(1, "prediction_scheme",
                                             PREDICTION_UNDEFINED),
            PREDICTION_UNDEFINED);
  // The same as configuring attribute 1 alone by hand.
  ExpertEncoder by_hand(*mesh);
  by_hand.Reset(options.CreateExpertEncoderOptions(*mesh));
  ASSERT_TRUE(by_hand
                  .SetAttributePredictionScheme(
                      1, MESH_PREDICTION_TEX_COORDS_WEIGHTED)
                  .ok());
  EncoderBuffer expected;
  ASSERT_TRUE(by_hand.EncodeToBuffer(&expected).ok());
  EXPECT_EQ(Bytes(buffer), Bytes(expected));
}

// UsedDracoUvCoding() and the count say whether draco-uv ids were written:
// the context seams' Edgebreaker method, or a draco-uv prediction scheme.
TEST(UvWebEncoderTest, UsedDracoUvCodingTellsTheTruth) {
  const std::unique_ptr<Mesh> mesh = LoadMesh(UvTestdataPath("torus_uv.obj"));
  struct Case {
    std::string prediction, seams;
    int cl;
    bool used;
  };
  const std::vector<Case> cases = {
      {"weighted", "", 10, true},      {"", "context", 10, true},
      {"parallelogram", "", 10, false},  // A stock scheme, forced.
      {"", "context", 3, false},  // Draco codes no seams at -cl 1..4.
      {"portable", "context", 7, true},
  };
  UvWebModuleState state;
  int expected_count = 0;
  for (const Case &c : cases) {
    UvWebEncoder web(&state);
    const DracoUvOptions options = Options(c.prediction, c.seams);
    ASSERT_TRUE(web.SetForType(GeometryAttribute::TEX_COORD, &options));
    const std::vector<char> bytes = EncodeWithEncoder(&web, *mesh, c.cl);
    EXPECT_EQ(web.UsedDracoUvCoding(), c.used) << c.prediction << c.seams;
    const std::string scheme =
        c.prediction.empty() && c.seams.empty()
            ? ""
            : (c.prediction.empty() ? "draco" : c.prediction) +
                  (c.seams.empty() ? "" : "+" + c.seams);
    EXPECT_EQ(bytes, NativeBytes(*mesh, scheme, c.cl)) << scheme;
    // The seams' method id is in the file for context seams only.
    ASSERT_GT(bytes.size(), kEdgebreakerMethodOffset);
    const bool context_method =
        bytes[kEdgebreakerMethodOffset] ==
            MESH_EDGEBREAKER_STANDARD_CONTEXT_SEAMS_ENCODING ||
        bytes[kEdgebreakerMethodOffset] ==
            MESH_EDGEBREAKER_VALENCE_CONTEXT_SEAMS_ENCODING;
    EXPECT_EQ(context_method, c.seams == "context" && c.used) << scheme;
    expected_count += c.used ? 1 : 0;
  }
  EXPECT_EQ(state.num_encodes_with_draco_uv_ids(), expected_count);
}

// SetTangentPrediction() and SetTangentQuantization() are draco_encoder's
// -tangent_pred and -qtg: the same bytes natively, with the tangents as
// TANGENT or as GENERIC, alone or with a UV prediction; bad values refused.
TEST(UvWebEncoderTest, TangentSettingsWriteDracoEncodersBytes) {
  DracoUvOptions checked;
  EXPECT_FALSE(checked.SetTangentPrediction("mikkt"));
  EXPECT_NE(std::string(checked.GetErrorMessage()).find("mikktspace"),
            std::string::npos)
      << checked.GetErrorMessage();
  for (const long bad : {-1L, 22L, 1L << 40}) {
    EXPECT_FALSE(checked.SetTangentQuantization(bad)) << bad;
    EXPECT_NE(std::string(checked.GetErrorMessage()), "");
  }
  EXPECT_TRUE(checked.options().tangent.IsStock());
  for (const std::string name :
       {"small_torus_uv_tangents.glb", "small_cube_sphere_tangents.glb"}) {
    const std::unique_ptr<Mesh> read = LoadMesh(UvTestdataPath(name));
    Mesh generic;
    generic.Copy(*read);
    const int tangent_id = TangentAttributeIds(*read).at(0);
    generic.attribute(tangent_id)
        ->set_attribute_type(GeometryAttribute::GENERIC);
    for (const Mesh *mesh : std::vector<const Mesh *>{read.get(), &generic}) {
      for (const std::string uv : {"", "auto"}) {
        for (const std::string tangent : {"auto", "mikktspace", "geometric"}) {
          for (const int qtg : {0, 10}) {
            UvWebModuleState state;
            DracoUvModule module(&state);
            DracoUvOptions options = Options(uv);
            ASSERT_TRUE(options.SetTangentPrediction(tangent.c_str()));
            ASSERT_TRUE(options.SetTangentQuantization(qtg));
            ASSERT_TRUE(module.SetDefault(&options))
                << module.GetErrorMessage();
            UvWebEncoder web(&state);
            UvEncodeSettings settings;
            settings.uv = options.options();
            EncoderBuffer native;
            ASSERT_TRUE(EncodeMeshWithSettings(*mesh, settings, &native).ok());
            const std::string what =
                name + " " + uv + " " + tangent + " " + std::to_string(qtg) +
                " " + (mesh == read.get() ? "TANGENT" : "GENERIC");
            const std::vector<char> bytes = EncodeWithEncoder(&web, *mesh);
            EXPECT_EQ(bytes, Bytes(native)) << what;
            EXPECT_NE(std::string(web.GetUvCompressionMessage())
                          .find("Tangent prediction"),
                      std::string::npos)
                << what << ": " << web.GetUvCompressionMessage();
            // Named geometric schemes write draco-uv ids on these meshes.
            if (tangent != "auto") {
              EXPECT_TRUE(web.UsedDracoUvCoding()) << what;
            }
          }
        }
      }
    }
  }
}

TEST(UvWebEncoderTest, AFailedEncodeSaysWhy) {
  const std::unique_ptr<Mesh> mesh = LoadMesh(UvTestdataPath("torus_uv.obj"));
  UvWebModuleState state;
  DracoUvModule module(&state);
  const DracoUvOptions weighted = Options("weighted");
  ASSERT_TRUE(module.SetDefault(&weighted));
  UvWebEncoder web(&state);
  Encoder sequential;
  SetUpLikeDracoEncoder(0, &sequential);
  EncoderBuffer buffer;
  EXPECT_FALSE(web.EncodeMesh(*mesh, &sequential, &buffer).ok());
  EXPECT_NE(std::string(web.GetUvCompressionMessage()).find("Edgebreaker"),
            std::string::npos)
      << web.GetUvCompressionMessage();
  EXPECT_FALSE(web.UsedDracoUvCoding());
  EXPECT_EQ(module.GetNumEncodesWithDracoUvIds(), 0);
  // Point clouds stay stock under a module default.
  EXPECT_TRUE(web.EncodePointCloud(*mesh, &sequential, &buffer).ok());
  EXPECT_STREQ(web.GetUvCompressionMessage(), "");
}

}  // namespace
}  // namespace draco
