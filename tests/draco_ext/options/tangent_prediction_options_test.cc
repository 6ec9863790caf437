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
#include "draco_ext/options/tangent_prediction_options.h"

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "draco/core/draco_test_base.h"
#include "draco/point_cloud/point_cloud.h"
#include "draco_ext/options/uv_encode_settings.h"
#include "draco_ext/options/uv_prediction_options.h"
#include "prediction_schemes/tangent/geometric_tangent_settings.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

std::unique_ptr<Mesh> Spot() {
  auto mesh = ReadTestMesh(UvTestdataPath("crane_spot_tangents.glb"));
  EXPECT_TRUE(mesh.ok());
  return std::move(mesh).value();
}

int TangentId(const Mesh &mesh) {
  return mesh.GetNamedAttributeId(GeometryAttribute::TANGENT);
}

// draco_encoder -qp 14 -qt 12 -cl |cl| [-uv_pred |uv|] -tangent_pred |name|
// -qtg 8.
UvEncodeSettings TangentSettings(const std::string &name, int cl = 7,
                                 const std::string &uv = "") {
  UvEncodeSettings settings = Settings(14, 12, cl, uv);
  settings.uv.tangent.prediction = ParseTangentPredictionName(name).value();
  settings.uv.tangent.quantization_bits = 8;
  return settings;
}

struct Encoded {
  std::vector<char> bytes;
  std::string summary;
};

Encoded Encode(const Mesh &mesh, const UvEncodeSettings &settings) {
  EncoderBuffer buffer;
  Encoded result;
  const Status status =
      EncodeMeshWithSettings(mesh, settings, &buffer, &result.summary);
  EXPECT_TRUE(status.ok()) << status.error_msg();
  result.bytes.assign(buffer.data(), buffer.data() + buffer.size());
  return result;
}

TEST(TangentPredictionOptionsTest, FindsTangentsByTypeAndByValues) {
  const auto mesh = Spot();
  EXPECT_EQ(TangentAttributeIds(*mesh), std::vector<int>{TangentId(*mesh)});
  // As glTF-Transform hands them to Draco: GENERIC.
  Mesh generic;
  generic.Copy(*mesh);
  PointAttribute *const tangents = generic.attribute(TangentId(*mesh));
  tangents->set_attribute_type(GeometryAttribute::GENERIC);
  const int id = TangentId(*mesh);
  EXPECT_EQ(TangentAttributeIds(generic), std::vector<int>{id});
  // A w that is not +-1 makes it something else.
  float value[4];
  tangents->GetValue(AttributeValueIndex(0), value);
  value[3] = 0.5f;
  tangents->SetAttributeValue(AttributeValueIndex(0), value);
  EXPECT_TRUE(TangentAttributeIds(generic).empty());
}

// -tangent_pred auto is never bigger than stock coding and decodes to the
// same values, on every asset.
TEST(TangentPredictionOptionsTest, AutoIsNeverBiggerThanStock) {
  for (const std::string &path : TangentGltfAssetPaths()) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    const Encoded stock = Encode(*mesh.value(), TangentSettings("draco"));
    const Encoded chosen = Encode(*mesh.value(), TangentSettings("auto"));
    EXPECT_LE(chosen.bytes.size(), stock.bytes.size()) << path;
    EXPECT_NE(chosen.summary.find("Tangent prediction (auto)"),
              std::string::npos)
        << chosen.summary;
    const auto a = DecodeDracoMesh(stock.bytes);
    const auto b = DecodeDracoMesh(chosen.bytes);
    ASSERT_TRUE(a.ok() && b.ok()) << path;
    EXPECT_EQ(CornerValues(*a.value(), GeometryAttribute::GENERIC),
              CornerValues(*b.value(), GeometryAttribute::GENERIC))
        << path;
  }
}

// -uv_pred auto measures the file with its choice and the tangents coded
// stock; -tangent_pred auto takes that size for its stock trial instead of
// encoding again, which changes neither its choice nor its summary (which
// gives both sizes).
TEST(TangentPredictionOptionsTest, ReusesTheUvChoicesSizeForStockTangents) {
  UvCompressionOptions uv;
  uv.prediction = UvPrediction::kAuto;
  TangentCompressionOptions tangent;
  tangent.prediction = TangentPrediction::kAuto;
  for (const std::string &path : TangentGltfAssetPaths()) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    for (const int speed : {0, 3}) {
      // draco_transcoder -qp 14 -qt 12 -qn 10 -qtg 8 at -cl 10 and 7.
      auto make_encoder = [&]() {
        auto encoder = std::make_unique<ExpertEncoder>(*mesh.value());
        encoder->SetSpeedOptions(speed, speed);
        for (int i = 0; i < mesh.value()->num_attributes(); ++i) {
          const GeometryAttribute::Type type =
              mesh.value()->attribute(i)->attribute_type();
          encoder->SetAttributeQuantization(
              i, type == GeometryAttribute::POSITION    ? 14
                 : type == GeometryAttribute::TEX_COORD ? 12
                 : type == GeometryAttribute::NORMAL    ? 10
                                                        : 8);
        }
        return encoder;
      };
      const auto reused = make_encoder();
      std::optional<size_t> size;
      ASSERT_TRUE(
          ConfigureUvPrediction(uv, mesh.value().get(), reused.get(), &size)
              .ok());
      ASSERT_TRUE(size.has_value()) << path;
      EncoderBuffer buffer;
      ASSERT_TRUE(reused->EncodeToBuffer(&buffer).ok());
      EXPECT_EQ(size.value(), buffer.size()) << path;
      const auto measured = make_encoder();
      ASSERT_TRUE(
          ConfigureUvPrediction(uv, mesh.value().get(), measured.get()).ok());
      const auto with_size = ConfigureTangentPrediction(
          tangent, mesh.value().get(), reused.get(), size);
      const auto without = ConfigureTangentPrediction(
          tangent, mesh.value().get(), measured.get());
      ASSERT_TRUE(with_size.ok() && without.ok()) << path;
      EXPECT_NE(with_size.value().find("(auto)"), std::string::npos)
          << with_size.value();
      EXPECT_EQ(with_size.value(), without.value()) << path;
    }
  }
}

TEST(TangentPredictionOptionsTest, ExplicitNamesSetTheGeometricScheme) {
  const auto mesh = Spot();
  const Encoded stock = Encode(*mesh, TangentSettings("draco"));
  for (const char *name : {"mikktspace", "uniform", "face", "geometric"}) {
    const Encoded ours = Encode(*mesh, TangentSettings(name));
    EXPECT_NE(ours.summary.find(std::string("-> ") + name),
              std::string::npos)
        << ours.summary;
    const auto a = DecodeDracoMesh(stock.bytes);
    const auto b = DecodeDracoMesh(ours.bytes);
    ASSERT_TRUE(b.ok()) << name;
    EXPECT_EQ(CornerValues(*a.value(), GeometryAttribute::GENERIC),
              CornerValues(*b.value(), GeometryAttribute::GENERIC))
        << name;
  }
}

// Where the prediction could not read exact inputs, the encoder keeps
// stock coding, says why, and writes exactly the stock file.
TEST(TangentPredictionOptionsTest, KeepsStockCodingWhereInputsAreNotExact) {
  const auto spot = Spot();
  Mesh no_normals;
  no_normals.Copy(*spot);
  no_normals.DeleteAttribute(
      no_normals.GetNamedAttributeId(GeometryAttribute::NORMAL));
  Mesh nan_normal;
  nan_normal.Copy(*spot);
  const float nan[3] = {std::numeric_limits<float>::quiet_NaN(), 0, 1};
  nan_normal.attribute(nan_normal.GetNamedAttributeId(GeometryAttribute::NORMAL))
      ->SetAttributeValue(AttributeValueIndex(5), nan);
  // Tangents along one axis, as on a flat asset: a quantization step far
  // below the scheme's fixed point.
  Mesh flat_tangents;
  flat_tangents.Copy(*spot);
  PointAttribute *const tangents = flat_tangents.attribute(TangentId(*spot));
  for (AttributeValueIndex i(0); i < tangents->size(); ++i) {
    const float along_x[4] = {1, (i.value() % 2) * 1e-6f, 0, 1};
    tangents->SetAttributeValue(i, along_x);
  }
  struct Case {
    const Mesh *mesh;
    int cl;
    std::string uv;
    std::string why;
  };
  const Case cases[] = {
      {&flat_tangents, 7, "", "span too small a range"},
      {spot.get(), 3, "", "-cl 5 or higher"},
      {spot.get(), 0, "", "Edgebreaker"},
      {spot.get(), 7, "laplacian_mv", "coded lossily"},
      {&no_normals, 7, "", "no NORMAL"},
      {&nan_normal, 7, "", "NORMAL has NaN"},
  };
  for (const Case &c : cases) {
    for (const char *name : {"auto", "mikktspace"}) {
      const Encoded ours = Encode(*c.mesh, TangentSettings(name, c.cl, c.uv));
      const Encoded stock = Encode(*c.mesh, TangentSettings("draco", c.cl, c.uv));
      EXPECT_NE(ours.summary.find("keeps stock coding"), std::string::npos)
          << ours.summary;
      EXPECT_NE(ours.summary.find(c.why), std::string::npos) << ours.summary;
      EXPECT_EQ(ours.bytes, stock.bytes) << c.why << " " << name;
    }
  }
}

// Draco cannot quantize them either: a clear error, not a crash; also as
// GENERIC, where the other values still make them tangents, and before
// -uv_pred auto's trial encodes (stock Draco takes minutes over an infinite
// GENERIC value, then throws std::bad_alloc).
TEST(TangentPredictionOptionsTest, NonFiniteTangentsAreAnError) {
  for (const GeometryAttribute::Type type :
       {GeometryAttribute::TANGENT, GeometryAttribute::GENERIC}) {
    for (const float bad : {std::numeric_limits<float>::infinity(),
                            std::numeric_limits<float>::quiet_NaN()}) {
      Mesh mesh;
      mesh.Copy(*Spot());
      const int id = TangentId(mesh);
      const float value[4] = {bad, 0, 0, 1};
      mesh.attribute(id)->SetAttributeValue(AttributeValueIndex(5), value);
      mesh.attribute(id)->set_attribute_type(type);
      for (const char *uv : {"", "auto"}) {
        EncoderBuffer buffer;
        const Status status = EncodeMeshWithSettings(
            mesh, TangentSettings("auto", 7, uv), &buffer);
        EXPECT_FALSE(status.ok()) << type << " " << uv;
        EXPECT_NE(std::string(status.error_msg()).find("NaN or infinite"),
                  std::string::npos)
            << status.error_msg();
      }
    }
  }
}

// Draco spreads the 2^qtg quantization steps over the range of the values;
// where that range is small (tangents that barely vary; all w = 1 and at
// -qtg 21 already a range below 2) the grid is finer than the scheme's
// fixed point (2^20 steps per unit), the encoder used to fail ("Failed to
// encode point attributes") and the decoder would refuse the grid. Every
// name keeps stock coding there and says why.
TEST(TangentPredictionOptionsTest, TooFineAGridKeepsStockCoding) {
  Mesh narrow;
  narrow.Copy(*Spot());
  PointAttribute *const tangents = narrow.attribute(TangentId(narrow));
  for (AttributeValueIndex i(0); i < tangents->size(); ++i) {
    // Unit tangents within 0.004 degrees of +x, w = 1.
    const float a = 1e-5f * static_cast<float>(i.value() % 7);
    const float value[4] = {std::cos(a), std::sin(a), 0, 1};
    tangents->SetAttributeValue(i, value);
  }
  for (const int bits : {8, 12}) {
    for (const char *name : {"auto", "mikktspace", "geometric"}) {
      UvEncodeSettings settings = TangentSettings(name);
      settings.uv.tangent.quantization_bits = bits;
      UvEncodeSettings stock_settings = TangentSettings("draco");
      stock_settings.uv.tangent.quantization_bits = bits;
      const Encoded ours = Encode(narrow, settings);
      const Encoded stock = Encode(narrow, stock_settings);
      EXPECT_NE(ours.summary.find("keeps stock coding: its values span too "
                                  "small a range"),
                std::string::npos)
          << ours.summary;
      EXPECT_EQ(ours.bytes, stock.bytes) << name << " " << bits;
    }
  }
}

TEST(TangentPredictionOptionsTest, MeshesWithoutTangentsAreUntouched) {
  const auto mesh = ReadTestMesh(UvTestdataPath("crane_spot.obj"));
  ASSERT_TRUE(mesh.ok());
  UvEncodeSettings settings = Settings(14, 12, 7, "");
  const Encoded stock = Encode(*mesh.value(), settings);
  settings.uv.tangent.prediction = TangentPrediction::kAuto;
  const Encoded ours = Encode(*mesh.value(), settings);
  EXPECT_EQ(ours.bytes, stock.bytes);
  EXPECT_EQ(ours.summary, "");
}

TEST(TangentPredictionOptionsTest, PointCloudsAreAnError) {
  ExpertEncoder encoder(*Spot());
  TangentCompressionOptions options;
  options.prediction = TangentPrediction::kAuto;
  EXPECT_FALSE(ConfigureTangentPrediction(options, nullptr, &encoder).ok());
}

}  // namespace
}  // namespace draco
