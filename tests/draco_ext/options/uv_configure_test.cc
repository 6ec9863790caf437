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
// ConfigureUvCompression(): the checks first, then the seam coding, then the
// prediction of every TEX_COORD attribute.
#include "draco_ext/options/uv_configure.h"

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "draco_ext/options/uv_prediction_options.h"
#include "draco_ext/options/uv_seam_options.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

class UvConfigureTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
    ASSERT_TRUE(mesh.ok());
    mesh_ = std::move(mesh).value();
    tex_coord_ = mesh_->GetNamedAttributeId(GeometryAttribute::TEX_COORD);
    ASSERT_GE(tex_coord_, 0);
  }

  // An encoder at draco_encoder's -cl 10 with every attribute at 11 bits.
  std::unique_ptr<ExpertEncoder> MakeEncoder() const {
    std::unique_ptr<ExpertEncoder> encoder(new ExpertEncoder(*mesh_));
    encoder->SetSpeedOptions(0, 0);
    for (int i = 0; i < mesh_->num_attributes(); ++i) {
      encoder->SetAttributeQuantization(i, 11);
    }
    return encoder;
  }

  static std::vector<char> Encode(ExpertEncoder *encoder) {
    EncoderBuffer buffer;
    EXPECT_TRUE(encoder->EncodeToBuffer(&buffer).ok());
    return std::vector<char>(buffer.data(), buffer.data() + buffer.size());
  }

  int PredictionScheme(const ExpertEncoder &encoder) const {
    return encoder.options().GetAttributeInt(tex_coord_, "prediction_scheme",
                                             PREDICTION_UNDEFINED);
  }

  std::unique_ptr<Mesh> mesh_;
  int tex_coord_ = -1;
};

TEST_F(UvConfigureTest, StockOptionsLeaveTheEncoderUntouched) {
  const std::unique_ptr<ExpertEncoder> untouched = MakeEncoder();
  const std::unique_ptr<ExpertEncoder> configured = MakeEncoder();
  const auto summary = ConfigureUvCompression(UvCompressionOptions(),
                                              mesh_.get(), configured.get());
  ASSERT_TRUE(summary.ok()) << summary.status().error_msg();
  EXPECT_EQ(summary.value(), "");
  EXPECT_EQ(Encode(untouched.get()), Encode(configured.get()));
  // Stock options need nothing, not even a mesh.
  EXPECT_TRUE(
      ConfigureUvCompression(UvCompressionOptions(), nullptr, configured.get())
          .ok());
}

TEST_F(UvConfigureTest, AppliesTheSeamCodingThenThePrediction) {
  const UvCompressionOptions options = UvOptions("weighted+context");
  const std::unique_ptr<ExpertEncoder> encoder = MakeEncoder();
  const auto summary =
      ConfigureUvCompression(options, mesh_.get(), encoder.get());
  ASSERT_TRUE(summary.ok()) << summary.status().error_msg();
  EXPECT_EQ(GetUvSeamCoding(encoder->options()), UvSeamCoding::kContext);
  EXPECT_EQ(PredictionScheme(*encoder), MESH_PREDICTION_TEX_COORDS_WEIGHTED);
  // The summary follows the order: seams, then one line per attribute.
  const size_t seams = summary.value().find("UV seams: context");
  const size_t prediction = summary.value().find("UV prediction: ");
  ASSERT_NE(seams, std::string::npos) << summary.value();
  ASSERT_NE(prediction, std::string::npos) << summary.value();
  EXPECT_LT(seams, prediction);

  // The same as the two steps by hand.
  const std::unique_ptr<ExpertEncoder> by_hand = MakeEncoder();
  ASSERT_TRUE(
      ConfigureUvSeams(options.seams, mesh_.get(), by_hand.get()).ok());
  ASSERT_TRUE(ConfigureUvPrediction(options, mesh_.get(), by_hand.get()).ok());
  EXPECT_EQ(Encode(encoder.get()), Encode(by_hand.get()));
}

// -uv_pred auto measures its candidates with the seam coding already set:
// with either seam coding it picks the smallest candidate with that coding,
// weighted_multi (slower to decode) counted half a bit per UV vertex
// (distinct position and texture coordinate pair) larger. Both outcomes
// occur on these meshes.
TEST_F(UvConfigureTest, AutoMeasuresCandidatesWithTheChosenSeamCoding) {
  std::vector<std::string> paths = TexturedObjPlyMeshPaths();
  for (const std::string &name : DracoTestdataTexturedMeshes()) {
    paths.push_back(DracoTestdataPath(name));
  }
  int multi_taken = 0, multi_left = 0;
  for (const std::string &path : paths) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    if (mesh.value()->NumNamedAttributes(GeometryAttribute::TEX_COORD) != 1) {
      continue;  // Auto picks attribute by attribute.
    }
    const PointAttribute *const pos =
        mesh.value()->GetNamedAttribute(GeometryAttribute::POSITION);
    const PointAttribute *const uv =
        mesh.value()->GetNamedAttribute(GeometryAttribute::TEX_COORD);
    std::set<std::pair<uint32_t, uint32_t>> uv_vertices;
    for (PointIndex p(0); p < mesh.value()->num_points(); ++p) {
      uv_vertices.insert(
          {pos->mapped_index(p).value(), uv->mapped_index(p).value()});
    }
    for (const std::string seams : {"", "+context"}) {
      const auto size_of = [&](const std::string &prediction) {
        const auto bytes = EncodeMeshToBytes(
            *mesh.value(), Settings(14, 12, 10, prediction + seams));
        return bytes.ok() ? bytes.value().size()
                          : std::numeric_limits<size_t>::max();
      };
      size_t fastest_smallest = std::numeric_limits<size_t>::max();
      for (const char *candidate :
           {"draco", "parallelogram", "multi_parallelogram", "portable",
            "weighted"}) {
        fastest_smallest = std::min(fastest_smallest, size_of(candidate));
      }
      // weighted_multi decodes slower: it must save half a bit per UV vertex.
      const size_t multi = size_of("weighted_multi");
      const bool take_multi =
          multi + (uv_vertices.size() + 15) / 16 < fastest_smallest;
      EXPECT_EQ(size_of("auto"), take_multi ? multi : fastest_smallest)
          << path << seams;
      ++(take_multi ? multi_taken : multi_left);
    }
  }
  EXPECT_GT(multi_taken, 0);
  EXPECT_GE(multi_left, 3);
}

// The options are checked before anything is applied: a rejected call
// leaves the encoder as it was.
TEST_F(UvConfigureTest, ChecksTheOptionsBeforeApplyingAny) {
  for (const std::string scheme :
       {"draco", "draco+context", "weighted+context", "auto+context"}) {
    const std::unique_ptr<ExpertEncoder> encoder = MakeEncoder();
    const auto summary = ConfigureUvCompression(UvOptions(scheme, "10"),
                                                mesh_.get(), encoder.get());
    ASSERT_FALSE(summary.ok()) << scheme;
    EXPECT_NE(summary.status().error_msg_string().find("-uv_anchors"),
              std::string::npos)
        << scheme;
    EXPECT_EQ(GetUvSeamCoding(encoder->options()), UvSeamCoding::kDraco)
        << scheme;
    EXPECT_EQ(PredictionScheme(*encoder), PREDICTION_UNDEFINED) << scheme;
  }
  const std::unique_ptr<ExpertEncoder> encoder = MakeEncoder();
  const auto summary = ConfigureUvCompression(
      UvOptions("laplacian_cotan+context", "10"), mesh_.get(), encoder.get());
  ASSERT_EQ(summary.ok(), HasUvLaplacianCoder());
  if (summary.ok()) {
    EXPECT_EQ(GetUvSeamCoding(encoder->options()), UvSeamCoding::kContext);
    EXPECT_EQ(PredictionScheme(*encoder), MESH_PREDICTION_TEX_COORDS_LAPLACIAN);
  }
}

TEST_F(UvConfigureTest, RejectsPointCloudsAndSequentialEncoding) {
  for (const std::string scheme : {"weighted", "draco+context"}) {
    const std::unique_ptr<ExpertEncoder> encoder = MakeEncoder();
    EXPECT_FALSE(
        ConfigureUvCompression(UvOptions(scheme), nullptr, encoder.get()).ok())
        << scheme;
    encoder->SetSpeedOptions(10, 10);
    const auto sequential =
        ConfigureUvCompression(UvOptions(scheme), mesh_.get(), encoder.get());
    ASSERT_FALSE(sequential.ok()) << scheme;
    EXPECT_NE(sequential.status().error_msg_string().find("-cl"),
              std::string::npos)
        << sequential.status().error_msg_string();
  }
}

// The per-attribute form: each listed TEX_COORD attribute gets its own
// prediction, the others stay stock; seams are per mesh.
TEST_F(UvConfigureTest, PerAttributeFormConfiguresTheListedAttributes) {
  const std::unique_ptr<ExpertEncoder> untouched = MakeEncoder();
  const std::unique_ptr<ExpertEncoder> empty = MakeEncoder();
  ASSERT_TRUE(ConfigureUvCompression(std::map<int, UvCompressionOptions>(),
                                     mesh_.get(), empty.get())
                  .ok());
  EXPECT_EQ(Encode(untouched.get()), Encode(empty.get()));

  // The same as the all-attributes form on a mesh with one TEX_COORD.
  const UvCompressionOptions options = UvOptions("weighted+context");
  const std::unique_ptr<ExpertEncoder> all = MakeEncoder();
  const std::unique_ptr<ExpertEncoder> listed = MakeEncoder();
  const auto all_summary =
      ConfigureUvCompression(options, mesh_.get(), all.get());
  const auto listed_summary = ConfigureUvCompression(
      std::map<int, UvCompressionOptions>{{tex_coord_, options}}, mesh_.get(),
      listed.get());
  ASSERT_TRUE(all_summary.ok() && listed_summary.ok());
  EXPECT_EQ(all_summary.value(), listed_summary.value());
  EXPECT_EQ(Encode(all.get()), Encode(listed.get()));

  // Any other attribute is an error, and so are inconsistent options.
  const int pos = mesh_->GetNamedAttributeId(GeometryAttribute::POSITION);
  const std::unique_ptr<ExpertEncoder> encoder = MakeEncoder();
  EXPECT_FALSE(ConfigureUvCompression(
                   std::map<int, UvCompressionOptions>{{pos, options}},
                   mesh_.get(), encoder.get())
                   .ok());
  EXPECT_FALSE(ConfigureUvCompression(
                   std::map<int, UvCompressionOptions>{
                       {tex_coord_, UvOptions("weighted", "50")}},
                   mesh_.get(), encoder.get())
                   .ok());
  EXPECT_EQ(PredictionScheme(*encoder), PREDICTION_UNDEFINED);
}

}  // namespace
}  // namespace draco
