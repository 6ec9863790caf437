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

#include "gtest/gtest.h"

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

}  // namespace
}  // namespace draco
