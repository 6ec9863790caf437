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
#include "draco_ext/options/tangent_compression_options.h"

#include <string>
#include <vector>

#include "draco/core/draco_test_base.h"
#include "draco_ext/options/draco_uv_flags.h"
#include "draco_ext/options/uv_compression_options.h"
#include "prediction_schemes/tangent/geometric_tangent_settings.h"

namespace draco {
namespace {

TEST(TangentCompressionOptionsTest, EveryNameParsesToItsPrediction) {
  for (const TangentPredictionName &entry : TangentPredictionNames()) {
    const auto parsed = ParseTangentPredictionName(entry.name);
    ASSERT_TRUE(parsed.ok()) << entry.name;
    EXPECT_EQ(parsed.value(), entry.prediction);
    EXPECT_STREQ(TangentPredictionNameOf(entry.prediction), entry.name);
  }
}

TEST(TangentCompressionOptionsTest, UnknownNameListsTheValidOnes) {
  const auto parsed = ParseTangentPredictionName("mikkt");
  ASSERT_FALSE(parsed.ok());
  const std::string message = parsed.status().error_msg();
  for (const TangentPredictionName &entry : TangentPredictionNames()) {
    EXPECT_NE(message.find(entry.name), std::string::npos) << message;
  }
}

// Each name asks the scheme for its conventions; the explicit ones for one.
TEST(TangentCompressionOptionsTest, NamesSelectTheirConventions) {
  EXPECT_EQ(GeometricTangentKindsOf(TangentPrediction::kDraco), 0);
  EXPECT_EQ(GeometricTangentKindsOf(TangentPrediction::kAuto),
            kAllGeometricTangentKinds);
  EXPECT_EQ(GeometricTangentKindsOf(TangentPrediction::kGeometric),
            kAllGeometricTangentKinds);
  uint8_t seen = 0;
  for (const TangentPrediction one :
       {TangentPrediction::kMikkTSpace, TangentPrediction::kUniform,
        TangentPrediction::kFace}) {
    const uint8_t kinds = GeometricTangentKindsOf(one);
    EXPECT_EQ(kinds & (kinds - 1), 0) << "one convention";
    EXPECT_EQ(seen & kinds, 0) << "a convention of its own";
    seen |= kinds;
  }
  EXPECT_EQ(seen, kAllGeometricTangentKinds);
}

TEST(TangentCompressionOptionsTest, FlagsParseThroughTheUvParser) {
  const char *argv[] = {"draco_encoder", "-tangent_pred", "auto", "-qtg", "12"};
  UvCompressionOptions options;
  for (int i = 1; i < 5; ++i) {
    ASSERT_TRUE(IsUvCompressionFlag(argv[i]));
    ASSERT_TRUE(ParseUvCompressionFlag(5, const_cast<char **>(argv), &i,
                                       &options)
                    .ok());
  }
  EXPECT_EQ(options.tangent.prediction, TangentPrediction::kAuto);
  EXPECT_EQ(options.tangent.quantization_bits, 12);
  EXPECT_FALSE(options.IsStock());
  EXPECT_TRUE(CheckUvCompressionOptions(options).ok());
}

TEST(TangentCompressionOptionsTest, QuantizationBitsOutsideTheGridFail) {
  TangentCompressionOptions options;
  for (const std::string bad : {"0", "22", "-3", "8x", ""}) {
    EXPECT_FALSE(ParseTangentCompressionFlag("-qtg", bad, &options).ok())
        << bad;
  }
  options.quantization_bits = 22;
  EXPECT_FALSE(CheckTangentCompressionOptions(options).ok());
  options.quantization_bits = 21;
  EXPECT_TRUE(CheckTangentCompressionOptions(options).ok());
}

TEST(TangentCompressionOptionsTest, DefaultIsStockAndHelpNamesEverything) {
  EXPECT_TRUE(TangentCompressionOptions().IsStock());
  EXPECT_TRUE(UvCompressionOptions().IsStock());
  const std::string usage = UvCompressionUsage();
  EXPECT_NE(usage.find("-tangent_pred"), std::string::npos);
  EXPECT_NE(usage.find("-qtg"), std::string::npos);
  for (const TangentPredictionName &entry : TangentPredictionNames()) {
    EXPECT_NE(usage.find(entry.name), std::string::npos) << entry.name;
  }
}

// The tools' unknown-flag check knows the tangent flags as draco-uv's.
TEST(TangentCompressionOptionsTest, MisspeltTangentFlagIsAnError) {
  const UnhandledToolArg verdict =
      ClassifyUnhandledToolArg("draco_encoder", "-tangent_prd", false);
  EXPECT_EQ(verdict.kind, UnhandledToolArg::kError);
  EXPECT_EQ(verdict.suggestion, "-tangent_pred");
}

}  // namespace
}  // namespace draco
