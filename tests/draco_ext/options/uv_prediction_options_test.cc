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
#include "draco_ext/options/uv_prediction_options.h"

#include <set>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

UvCompressionOptions WithPrediction(UvPrediction prediction) {
  UvCompressionOptions options;
  options.prediction = prediction;
  return options;
}

class UvPredictionConfigureTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto mesh = ReadTestMesh(DracoTestdataPath("cube_att.obj"));
    ASSERT_TRUE(mesh.ok());
    mesh_ = std::move(mesh).value();
  }
  // An encoder at draco_encoder's defaults but -qp/-qt 11.
  std::unique_ptr<ExpertEncoder> MakeEncoder() const {
    std::unique_ptr<ExpertEncoder> encoder(new ExpertEncoder(*mesh_));
    for (int i = 0; i < mesh_->num_attributes(); ++i) {
      encoder->SetAttributeQuantization(i, 11);
    }
    return encoder;
  }
  std::unique_ptr<Mesh> mesh_;
};

// Every lossless named prediction sets its Draco scheme on every TEX_COORD
// attribute and on nothing else; "draco" sets nothing.
TEST_F(UvPredictionConfigureTest, SetsTheNamedSchemeOnTexCoordsOnly) {
  for (const UvPredictionName &entry : UvPredictionNames()) {
    if (entry.prediction == UvPrediction::kAuto ||
        IsUvLaplacian(entry.prediction)) {
      continue;
    }
    const std::unique_ptr<ExpertEncoder> encoder = MakeEncoder();
    const auto summary = ConfigureUvPrediction(WithPrediction(entry.prediction),
                                               mesh_.get(), encoder.get());
    ASSERT_TRUE(summary.ok()) << entry.name << ": "
                              << summary.status().error_msg();
    EXPECT_EQ(summary.value().empty(), entry.prediction == UvPrediction::kDraco)
        << entry.name;
    for (int i = 0; i < mesh_->num_attributes(); ++i) {
      const bool tex_coord = mesh_->attribute(i)->attribute_type() ==
                             GeometryAttribute::TEX_COORD;
      EXPECT_EQ(encoder->options().GetAttributeInt(i, "prediction_scheme",
                                                   PREDICTION_UNDEFINED),
                tex_coord ? entry.method : PREDICTION_UNDEFINED)
          << entry.name << " attribute " << i;
    }
  }
}

TEST_F(UvPredictionConfigureTest, DracoNameLeavesTheOutputUnchanged) {
  const auto none = EncodeMeshToBytes(*mesh_, {14, 12, 10});
  const auto draco = EncodeMeshToBytes(*mesh_, Settings(14, 12, 10, "draco"));
  ASSERT_TRUE(none.ok() && draco.ok());
  EXPECT_EQ(none.value(), draco.value());
}

TEST_F(UvPredictionConfigureTest, RejectsSequentialEncoding) {
  const auto result =
      EncodeMeshToBytes(*mesh_, Settings(14, 12, 0, "weighted"));
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.status().error_msg_string().find("-cl"), std::string::npos);
}

TEST_F(UvPredictionConfigureTest, RejectsUnquantizedTexCoords) {
  EXPECT_FALSE(
      EncodeMeshToBytes(*mesh_, Settings(14, 0, 10, "weighted")).ok());
}

TEST_F(UvPredictionConfigureTest, RejectsQuantizationBeyondTheSupportedRange) {
  const auto result =
      EncodeMeshToBytes(*mesh_, Settings(14, 21, 10, "weighted"));
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.status().error_msg_string().find("-qt up to 20"),
            std::string::npos);
  EXPECT_TRUE(
      EncodeMeshToBytes(*mesh_, Settings(14, 20, 10, "weighted")).ok());
  // auto simply leaves the scheme out.
  EXPECT_TRUE(EncodeMeshToBytes(*mesh_, Settings(14, 21, 10, "auto")).ok());
}

TEST_F(UvPredictionConfigureTest, RejectsPointClouds) {
  ExpertEncoder encoder(*mesh_);
  EXPECT_FALSE(
      ConfigureUvPrediction(WithPrediction(UvPrediction::kWeighted), nullptr,
                            &encoder)
          .ok());
}

TEST_F(UvPredictionConfigureTest, SummaryNamesTheChosenScheme) {
  const std::unique_ptr<ExpertEncoder> encoder = MakeEncoder();
  const auto summary = ConfigureUvPrediction(
      WithPrediction(UvPrediction::kWeighted), mesh_.get(), encoder.get());
  ASSERT_TRUE(summary.ok()) << summary.status().error_msg();
  EXPECT_NE(summary.value().find("TEX_COORD 0"), std::string::npos);
  EXPECT_NE(summary.value().find("weighted"), std::string::npos);
}

// StockUvPrediction() names the scheme that Draco picks itself: setting it
// encodes the same bytes as leaving the choice to Draco, at every speed with
// connectivity and with positions that do and do not allow
// TEX_COORDS_PORTABLE (quantized to 14 or 22 bits, unquantized). -uv_pred
// auto relies on it to leave out that candidate's trial encode.
TEST(UvStockPredictionTest, NamesTheSchemeDracoPicks) {
  std::set<PredictionSchemeMethod> named;
  for (const std::string &path : TexturedObjPlyMeshPaths()) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    for (const int speed : {0, 1, 2, 3, 4, 7, 8, 9}) {
      for (const int position_bits : {14, 22, -1}) {
        ExpertEncoder encoder(*mesh.value());
        encoder.SetSpeedOptions(speed, speed);
        for (int i = 0; i < mesh.value()->num_attributes(); ++i) {
          encoder.SetAttributeQuantization(
              i, mesh.value()->attribute(i)->attribute_type() ==
                         GeometryAttribute::POSITION
                     ? position_bits
                     : 12);
        }
        const int att_id =
            mesh.value()->GetNamedAttributeId(GeometryAttribute::TEX_COORD);
        const PredictionSchemeMethod method =
            StockUvPrediction(*mesh.value(), encoder.options(), att_id);
        named.insert(method);
        EncoderBuffer stock, set;
        ASSERT_TRUE(encoder.EncodeToBuffer(&stock).ok()) << path;
        ASSERT_TRUE(encoder.SetAttributePredictionScheme(att_id, method).ok());
        ASSERT_TRUE(encoder.EncodeToBuffer(&set).ok()) << path;
        EXPECT_EQ(std::vector<char>(stock.data(), stock.data() + stock.size()),
                  std::vector<char>(set.data(), set.data() + set.size()))
            << path << " at speed " << speed << ", positions at "
            << position_bits << " bits";
      }
    }
  }
  EXPECT_EQ(named, std::set<PredictionSchemeMethod>(
                       {PREDICTION_DIFFERENCE, MESH_PREDICTION_PARALLELOGRAM,
                        MESH_PREDICTION_CONSTRAINED_MULTI_PARALLELOGRAM,
                        MESH_PREDICTION_TEX_COORDS_PORTABLE}));
}

// -uv_pred auto keeps stock Draco's choice among its candidates, so it can
// never produce a larger file than stock at the same settings.
TEST(UvPredictionAutoTest, IsNeverLargerThanStockOnDracoTestdata) {
  for (const std::string &name : DracoTestdataTexturedMeshes()) {
    const auto mesh = ReadTestMesh(DracoTestdataPath(name));
    ASSERT_TRUE(mesh.ok()) << name;
    for (const int cl : {7, 10}) {
      const auto stock = EncodeMeshToBytes(*mesh.value(), {14, 10, cl});
      const auto automatic =
          EncodeMeshToBytes(*mesh.value(), Settings(14, 10, cl, "auto"));
      ASSERT_TRUE(stock.ok() && automatic.ok()) << name;
      EXPECT_LE(automatic.value().size(), stock.value().size()) << name;
    }
  }
}

// -uv_pred auto encodes the whole mesh once, with Draco's own choice, and
// the other candidates with the positions and texture coordinates alone;
// the sizes it reports are still the whole file's, on meshes with normals
// and tangents besides, and its choice is never larger than stock's.
TEST(UvPredictionAutoTest, ReportsTheWholeFilesSizes) {
  for (const std::string &path : TangentGltfAssetPaths()) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    const int att_id =
        mesh.value()->GetNamedAttributeId(GeometryAttribute::TEX_COORD);
    for (const int speed : {0, 3}) {
      ExpertEncoder encoder(*mesh.value());
      encoder.SetSpeedOptions(speed, speed);
      for (int i = 0; i < mesh.value()->num_attributes(); ++i) {
        const GeometryAttribute::Type type =
            mesh.value()->attribute(i)->attribute_type();
        encoder.SetAttributeQuantization(
            i, type == GeometryAttribute::POSITION ? 14
               : type == GeometryAttribute::NORMAL ? 10
                                                   : 12);
      }
      EncoderBuffer stock, chosen;
      ASSERT_TRUE(encoder.EncodeToBuffer(&stock).ok()) << path;
      const auto choice =
          ChooseSmallestUvPrediction(*mesh.value(), att_id, &encoder);
      ASSERT_TRUE(choice.ok()) << path << ": " << choice.status().error_msg();
      ASSERT_TRUE(encoder.EncodeToBuffer(&chosen).ok()) << path;
      EXPECT_EQ(choice.value().stock_bytes, stock.size()) << path;
      EXPECT_EQ(choice.value().bytes, chosen.size())
          << path << " at speed " << speed;
      EXPECT_LE(chosen.size(), stock.size()) << path;
    }
  }
}

}  // namespace
}  // namespace draco
