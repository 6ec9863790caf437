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
#include "draco_ext/options/uv_compression_options.h"

#include <string>
#include <vector>

#include "draco/compression/draco_compression_options.h"
#include "draco_ext/options/uv_prediction_options.h"
#include "draco_ext/options/uv_seam_options.h"
#include "gtest/gtest.h"

namespace draco {
namespace {

DracoCompressionOptions WithPrediction(const std::string &name) {
  DracoCompressionOptions options;
  options.uv.prediction = name;
  return options;
}

TEST(UvCompressionOptionsTest, DefaultIsStockAndPassesDracosCheck) {
  const DracoCompressionOptions options;
  EXPECT_TRUE(options.uv.IsStock());
  EXPECT_TRUE(WithPrediction("draco").uv.IsStock());
  EXPECT_TRUE(options.Check().ok());
  EXPECT_EQ(options, WithPrediction(""));
}

TEST(UvCompressionOptionsTest, TakesPartInDracoOptionsEquality) {
  EXPECT_NE(DracoCompressionOptions(), WithPrediction("weighted"));
  EXPECT_EQ(WithPrediction("auto"), WithPrediction("auto"));
}

TEST(UvCompressionOptionsTest, EveryNamePassesTheCheckAtTranscoderDefaults) {
  for (const UvPredictionName &entry : UvPredictionNames()) {
    EXPECT_TRUE(WithPrediction(entry.name).Check().ok()) << entry.name;
  }
}

TEST(UvCompressionOptionsTest, CheckRejectsUnknownName) {
  const Status status = WithPrediction("weigthed").Check();
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error_msg_string().find("weigthed"), std::string::npos);
}

TEST(UvCompressionOptionsTest, CheckRejectsSettingsTheCodersCannotUse) {
  DracoCompressionOptions sequential = WithPrediction("weighted");
  sequential.compression_level = 0;
  EXPECT_FALSE(sequential.Check().ok());

  DracoCompressionOptions unquantized_uvs = WithPrediction("parallelogram");
  unquantized_uvs.quantization_bits_tex_coord = 0;
  EXPECT_FALSE(unquantized_uvs.Check().ok());

  DracoCompressionOptions unquantized_positions = WithPrediction("weighted");
  unquantized_positions.quantization_position.SetQuantizationBits(0);
  EXPECT_FALSE(unquantized_positions.Check().ok());
  // Auto skips the candidates that need quantized positions.
  unquantized_positions.uv.prediction = "auto";
  EXPECT_TRUE(unquantized_positions.Check().ok());
  unquantized_positions.uv.prediction = "parallelogram";
  EXPECT_TRUE(unquantized_positions.Check().ok());

  // Stock options stay valid whatever the rest says.
  DracoCompressionOptions stock;
  stock.compression_level = 0;
  stock.quantization_bits_tex_coord = 0;
  EXPECT_TRUE(stock.Check().ok());
}

Status Parse(std::vector<std::string> args, UvCompressionOptions *options,
             int *index) {
  std::vector<char *> argv;
  for (std::string &arg : args) {
    argv.push_back(&arg[0]);
  }
  return ParseUvCompressionFlag(static_cast<int>(argv.size()), argv.data(),
                                index, options);
}

TEST(UvCompressionFlagTest, ParsesUvPredAndStopsOnItsValue) {
  EXPECT_TRUE(IsUvCompressionFlag("-uv_pred"));
  EXPECT_FALSE(IsUvCompressionFlag("-qt"));
  UvCompressionOptions options;
  int index = 1;
  ASSERT_TRUE(Parse({"tool", "-uv_pred", "auto", "-o"}, &options, &index).ok());
  EXPECT_EQ(options.prediction, "auto");
  EXPECT_EQ(index, 2);
}

TEST(UvCompressionFlagTest, RejectsMissingOrUnknownValue) {
  UvCompressionOptions options;
  int index = 1;
  EXPECT_FALSE(Parse({"tool", "-uv_pred"}, &options, &index).ok());
  index = 1;
  EXPECT_FALSE(Parse({"tool", "-uv_pred", "fast"}, &options, &index).ok());
  EXPECT_TRUE(options.IsStock());
}

TEST(UvCompressionFlagTest, UsageListsEveryName) {
  for (const UvPredictionName &entry : UvPredictionNames()) {
    EXPECT_NE(UvCompressionUsage().find(entry.name), std::string::npos);
  }
  for (const UvSeamCodingName &entry : UvSeamCodingNames()) {
    EXPECT_NE(UvCompressionUsage().find(entry.name), std::string::npos);
  }
}

TEST(UvCompressionFlagTest, ParsesUvSeamsNextToUvPred) {
  EXPECT_TRUE(IsUvCompressionFlag("-uv_seams"));
  UvCompressionOptions options;
  int index = 1;
  ASSERT_TRUE(Parse({"tool", "-uv_seams", "context", "-uv_pred", "weighted"},
                    &options, &index)
                  .ok());
  EXPECT_EQ(index, 2);
  index = 3;
  ASSERT_TRUE(Parse({"tool", "-uv_seams", "context", "-uv_pred", "weighted"},
                    &options, &index)
                  .ok());
  EXPECT_EQ(options.seams, "context");
  EXPECT_EQ(options.prediction, "weighted");
  EXPECT_FALSE(options.IsStock());
  index = 1;
  EXPECT_FALSE(Parse({"tool", "-uv_seams", "static"}, &options, &index).ok());
}

TEST(UvCompressionFlagTest, ParsesUvAnchorsForTheLaplacianCoder) {
  EXPECT_TRUE(IsUvCompressionFlag("-uv_anchors"));
  UvCompressionOptions options;
  int index = 1;
  ASSERT_TRUE(Parse({"tool", "-uv_anchors", "2%"}, &options, &index).ok());
  EXPECT_EQ(options.anchors, "2%");
  EXPECT_EQ(index, 2);
  index = 1;
  EXPECT_FALSE(Parse({"tool", "-uv_anchors", "many"}, &options, &index).ok());
  EXPECT_NE(UvCompressionUsage().find("-uv_anchors"), std::string::npos);
}

TEST(UvCompressionOptionsTest, CheckAnchorsNeedALaplacianScheme) {
  DracoCompressionOptions options = WithPrediction("laplacian_mv");
  options.uv.anchors = "random:100";
  EXPECT_TRUE(options.Check().ok());
  EXPECT_NE(options, WithPrediction("laplacian_mv"));
  options.uv.prediction = "weighted";
  EXPECT_FALSE(options.Check().ok());
  options.uv.prediction = "laplacian_cotan";
  options.uv.anchors = "-5";
  EXPECT_FALSE(options.Check().ok());
}

TEST(UvCompressionOptionsTest, CheckSeamsNeedKnownNameAndEdgebreaker) {
  DracoCompressionOptions options;
  options.uv.seams = "draco";
  EXPECT_TRUE(options.uv.IsStock());
  options.uv.seams = "context";
  EXPECT_FALSE(options.uv.IsStock());
  EXPECT_TRUE(options.Check().ok());
  EXPECT_NE(options, DracoCompressionOptions());
  options.compression_level = 0;
  EXPECT_FALSE(options.Check().ok());
  options.compression_level = 7;
  options.uv.seams = "contxt";
  EXPECT_FALSE(options.Check().ok());
}

}  // namespace
}  // namespace draco
