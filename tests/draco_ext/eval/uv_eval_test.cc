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
#include "draco_ext/eval/uv_eval.h"

#include <string>
#include <vector>

#include "draco_ext/options/tangent_prediction_options.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

// Measured scheme names: "<uv_pred>[+<uv_seams>]", parsed once into the
// options they stand for.
TEST(UvEvalTest, ParsesSchemeNamesIntoOptions) {
  const StatusOr<UvCompressionOptions> plain = ParseUvSchemeName("weighted");
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(plain.value().prediction, UvPrediction::kWeighted);
  EXPECT_EQ(plain.value().seams, UvSeamCoding::kDraco);
  EXPECT_FALSE(plain.value().anchors.has_value());

  const StatusOr<UvCompressionOptions> context =
      ParseUvSchemeName("weighted+context");
  ASSERT_TRUE(context.ok());
  EXPECT_EQ(context.value().prediction, UvPrediction::kWeighted);
  EXPECT_EQ(context.value().seams, UvSeamCoding::kContext);

  const StatusOr<UvCompressionOptions> stock = ParseUvSchemeName("draco");
  ASSERT_TRUE(stock.ok());
  EXPECT_TRUE(stock.value().IsStock());
  EXPECT_EQ(ParseUvSchemeName("draco+draco").value(), stock.value());
  EXPECT_EQ(ParseUvSchemeName("laplacian_mv+context").value().prediction,
            UvPrediction::kLaplacianMeanValue);
}

TEST(UvEvalTest, RejectsUnknownSchemeNamesListingValidOnes) {
  const StatusOr<UvCompressionOptions> prediction =
      ParseUvSchemeName("weigthed+context");
  ASSERT_FALSE(prediction.ok());
  EXPECT_NE(prediction.status().error_msg_string().find(
                "Unknown -uv_pred name 'weigthed'. Valid names: "),
            std::string::npos)
      << prediction.status().error_msg_string();
  const StatusOr<UvCompressionOptions> seams =
      ParseUvSchemeName("weighted+contxt");
  ASSERT_FALSE(seams.ok());
  EXPECT_NE(seams.status().error_msg_string().find(
                "Unknown -uv_seams name 'contxt'. Valid names: "),
            std::string::npos)
      << seams.status().error_msg_string();
  for (const std::string bad :
       {"", "+context", "weighted+", "weighted+context+x"}) {
    EXPECT_FALSE(ParseUvSchemeName(bad).ok()) << bad;
  }
}

UvEvalOptions TangentEvalOptions() {
  UvEvalOptions options;
  options.qt = {12};
  options.schemes = {"draco", "auto"};
  options.tangents = {"draco", "auto", "mikktspace"};
  options.qtg = {8, 12};
  options.repeat = 1;
  return options;
}

// On every asset with tangents: a row per (qt, qtg, scheme, tangents);
// tangent bytes are the difference of the two files draco_encoder writes
// with and without the tangents; stock tangent coding is the reference;
// every coding decodes to stock coding's tangents, and auto is never bigger.
TEST(UvEvalTest, TangentRowsMeasureWhatTheTangentsCost) {
  const UvEvalOptions options = TangentEvalOptions();
  for (const std::string &path : TangentGltfAssetPaths()) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    ASSERT_TRUE(HasTangents(*mesh.value())) << path;
    const std::unique_ptr<Mesh> without =
        MeshWithoutTangents(*mesh.value());
    const auto rows = EvaluateMeshTangents("m", *mesh.value(), options);
    ASSERT_TRUE(rows.ok()) << path << ": " << rows.status().error_msg();
    ASSERT_EQ(rows.value().size(), 1u * 2 * 2 * 3) << path;
    int64_t draco_bytes = 0;
    for (const TangentEvalRow &row : rows.value()) {
      const std::string label = path + " " + row.scheme + " " + row.tangents +
                                " " + std::to_string(row.qtg);
      EXPECT_TRUE(row.round_trip_ok) << label;
      EXPECT_EQ(row.tangent_values, mesh.value()->num_points()) << label;
      UvEncodeSettings settings = Settings(14, row.qt, 10, row.scheme);
      settings.uv.tangent.prediction =
          ParseTangentPredictionName(row.tangents).value();
      settings.uv.tangent.quantization_bits = row.qtg;
      const auto with_bytes = EncodeMeshToBytes(*mesh.value(), settings);
      const auto without_bytes = EncodeMeshToBytes(*without, settings);
      ASSERT_TRUE(with_bytes.ok() && without_bytes.ok()) << label;
      EXPECT_EQ(row.bytes, static_cast<int64_t>(with_bytes.value().size()))
          << label;
      EXPECT_EQ(row.tangent_bytes,
                static_cast<int64_t>(with_bytes.value().size()) -
                    static_cast<int64_t>(without_bytes.value().size()))
          << label;
      if (row.scheme == "draco" && row.tangents == "draco") {
        EXPECT_EQ(row.bytes, row.stock_bytes) << label;
        EXPECT_EQ(row.tangent_bytes, row.stock_tangent_bytes) << label;
      }
      if (row.tangents == "draco") {
        draco_bytes = row.bytes;
      } else if (row.tangents == "auto") {
        EXPECT_LE(row.bytes, draco_bytes) << label;
      }
    }
  }
}

TEST(UvEvalTest, MeshesWithoutTangentsHaveNoTangentRows) {
  const auto mesh = ReadTestMesh(UvTestdataPath("crane_spot.obj"));
  ASSERT_TRUE(mesh.ok());
  EXPECT_FALSE(HasTangents(*mesh.value()));
  const auto rows =
      EvaluateMeshTangents("spot", *mesh.value(), TangentEvalOptions());
  ASSERT_TRUE(rows.ok());
  EXPECT_TRUE(rows.value().empty());
}

}  // namespace
}  // namespace draco
