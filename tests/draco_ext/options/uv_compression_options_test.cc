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

#include <algorithm>
#include <string>
#include <vector>

#include "draco/compression/draco_compression_options.h"
#include "draco_ext/hooks/prediction_scheme_ids.h"
#include "gtest/gtest.h"
#include "prediction_schemes/laplacian/uv_laplacian_settings.h"

namespace draco {
namespace {

DracoCompressionOptions WithPrediction(UvPrediction prediction) {
  DracoCompressionOptions options;
  options.uv.prediction = prediction;
  return options;
}

UvAnchorSpec Anchors(const std::string &spec) {
  const StatusOr<UvAnchorSpec> parsed = ParseUvAnchorSpec(spec);
  EXPECT_TRUE(parsed.ok()) << spec;
  return parsed.ok() ? parsed.value() : UvAnchorSpec();
}

TEST(UvCompressionOptionsTest, DefaultIsStockAndPassesDracosCheck) {
  const DracoCompressionOptions options;
  EXPECT_TRUE(options.uv.IsStock());
  EXPECT_EQ(options.uv.prediction, UvPrediction::kDraco);
  EXPECT_EQ(options.uv.seams, UvSeamCoding::kDraco);
  EXPECT_FALSE(options.uv.anchors.has_value());
  EXPECT_TRUE(options.Check().ok());
  EXPECT_EQ(options, WithPrediction(UvPrediction::kDraco));
}

TEST(UvCompressionOptionsTest, TakesPartInDracoOptionsEquality) {
  EXPECT_NE(DracoCompressionOptions(), WithPrediction(UvPrediction::kWeighted));
  EXPECT_EQ(WithPrediction(UvPrediction::kAuto),
            WithPrediction(UvPrediction::kAuto));
  DracoCompressionOptions with_anchors =
      WithPrediction(UvPrediction::kLaplacianMeanValue);
  with_anchors.uv.anchors = Anchors("10");
  EXPECT_NE(with_anchors, WithPrediction(UvPrediction::kLaplacianMeanValue));
  DracoCompressionOptions other_anchors = with_anchors;
  other_anchors.uv.anchors = Anchors("random:10");
  EXPECT_NE(with_anchors, other_anchors);
  other_anchors.uv.anchors = Anchors("10");
  EXPECT_EQ(with_anchors, other_anchors);
}

TEST(UvCompressionOptionsTest, EveryNamePassesTheCheckAtTranscoderDefaults) {
  for (const UvPredictionName &entry : UvPredictionNames()) {
    EXPECT_EQ(WithPrediction(entry.prediction).Check().ok(),
              !IsUvLaplacian(entry.prediction) || HasUvLaplacianCoder())
        << entry.name;
  }
}

// The name table is the only one: every -uv_pred name parses to its entry's
// prediction, which maps to its entry's Draco scheme and back to the name.
TEST(UvCompressionOptionsTest, ParsesEveryPredictionNameToItsScheme) {
  std::vector<UvPrediction> seen;
  for (const UvPredictionName &entry : UvPredictionNames()) {
    const StatusOr<UvPrediction> prediction = ParseUvPredictionName(entry.name);
    ASSERT_TRUE(prediction.ok()) << entry.name;
    EXPECT_EQ(prediction.value(), entry.prediction) << entry.name;
    EXPECT_EQ(UvPredictionMethod(entry.prediction), entry.method) << entry.name;
    EXPECT_STREQ(UvPredictionNameOf(entry.prediction), entry.name);
    EXPECT_EQ(std::count(seen.begin(), seen.end(), entry.prediction), 0)
        << entry.name;
    seen.push_back(entry.prediction);
  }
  EXPECT_EQ(seen.size(), static_cast<size_t>(UvPrediction::kAuto) + 1);
  EXPECT_EQ(ParseUvPredictionName("draco").value(), UvPrediction::kDraco);
  EXPECT_EQ(ParseUvPredictionName("weighted").value(), UvPrediction::kWeighted);
  EXPECT_EQ(ParseUvPredictionName("laplacian_mv").value(),
            UvPrediction::kLaplacianMeanValue);
  EXPECT_EQ(ParseUvPredictionName("auto").value(), UvPrediction::kAuto);
  EXPECT_EQ(UvPredictionMethod(UvPrediction::kDraco), PREDICTION_UNDEFINED);
  EXPECT_EQ(UvPredictionMethod(UvPrediction::kAuto), PREDICTION_UNDEFINED);
  EXPECT_EQ(UvPredictionMethod(UvPrediction::kWeighted),
            MESH_PREDICTION_TEX_COORDS_WEIGHTED);
  EXPECT_EQ(UvPredictionMethod(UvPrediction::kPortable),
            MESH_PREDICTION_TEX_COORDS_PORTABLE);
  EXPECT_EQ(UvPredictionMethod(UvPrediction::kLaplacianCotan),
            MESH_PREDICTION_TEX_COORDS_LAPLACIAN);
}

TEST(UvCompressionOptionsTest, NamesDracoSchemesForTheTools) {
  EXPECT_EQ(UvPredictionNameOf(PREDICTION_UNDEFINED), "draco");
  EXPECT_EQ(UvPredictionNameOf(MESH_PREDICTION_PARALLELOGRAM), "parallelogram");
  EXPECT_EQ(UvPredictionNameOf(MESH_PREDICTION_TEX_COORDS_WEIGHTED_MULTI),
            "weighted_multi");
  // An id without a name of its own reads as its number.
  EXPECT_EQ(UvPredictionNameOf(MESH_PREDICTION_GEOMETRIC_NORMAL),
            std::to_string(static_cast<int>(MESH_PREDICTION_GEOMETRIC_NORMAL)));
}

// Draco's patched gate (hooks/prediction_scheme_ids.h) knows draco-uv's
// schemes by id: exactly the names marked draco-uv's.
TEST(UvCompressionOptionsTest, DracoUvNamesSetDracoUvSchemeIds) {
  for (const UvPredictionName &entry : UvPredictionNames()) {
    const bool draco_uv = entry.prediction == UvPrediction::kWeighted ||
                          entry.prediction == UvPrediction::kWeightedMulti ||
                          IsUvLaplacian(entry.prediction);
    EXPECT_EQ(IsDracoUvPredictionMethod(entry.method), draco_uv) << entry.name;
  }
  EXPECT_FALSE(IsDracoUvPredictionMethod(PREDICTION_UNDEFINED));
  EXPECT_FALSE(IsDracoUvPredictionMethod(MESH_PREDICTION_GEOMETRIC_NORMAL));
  EXPECT_FALSE(IsDracoUvPredictionMethod(NUM_PREDICTION_SCHEMES));
}

TEST(UvCompressionOptionsTest, OnlyTheLaplacianPredictionsAreLossy) {
  for (const UvPredictionName &entry : UvPredictionNames()) {
    const bool laplacian = entry.prediction == UvPrediction::kLaplacianTutte ||
                           entry.prediction == UvPrediction::kLaplacianCotan ||
                           entry.prediction == UvPrediction::kLaplacianMeanValue;
    EXPECT_EQ(IsUvLaplacian(entry.prediction), laplacian) << entry.name;
    EXPECT_EQ(IsLossyUvPrediction(entry.method), laplacian) << entry.name;
  }
  EXPECT_FALSE(IsLossyUvPrediction(MESH_PREDICTION_TEX_COORDS_WEIGHTED));
  EXPECT_TRUE(IsLossyUvPrediction(MESH_PREDICTION_TEX_COORDS_LAPLACIAN));
}

TEST(UvCompressionOptionsTest, RejectsUnknownNamesListingValidNames) {
  const StatusOr<UvPrediction> prediction = ParseUvPredictionName("weigthed");
  ASSERT_FALSE(prediction.ok());
  const std::string message = prediction.status().error_msg_string();
  EXPECT_NE(message.find("Unknown -uv_pred name 'weigthed'. Valid names: "),
            std::string::npos)
      << message;
  for (const UvPredictionName &entry : UvPredictionNames()) {
    EXPECT_NE(message.find(entry.name), std::string::npos) << message;
  }
  EXPECT_FALSE(ParseUvPredictionName("").ok());

  const StatusOr<UvSeamCoding> coding = ParseUvSeamCodingName("contex");
  ASSERT_FALSE(coding.ok());
  EXPECT_EQ(coding.status().error_msg_string(),
            "Unknown -uv_seams name 'contex'. Valid names: draco, context.");
}

TEST(UvCompressionOptionsTest, ParsesEverySeamCodingName) {
  for (const UvSeamCoding coding :
       {UvSeamCoding::kDraco, UvSeamCoding::kContext}) {
    const StatusOr<UvSeamCoding> parsed =
        ParseUvSeamCodingName(UvSeamCodingNameOf(coding));
    ASSERT_TRUE(parsed.ok()) << UvSeamCodingNameOf(coding);
    EXPECT_EQ(parsed.value(), coding);
  }
  EXPECT_STREQ(UvSeamCodingNameOf(UvSeamCoding::kDraco), "draco");
  EXPECT_EQ(ParseUvSeamCodingName("context").value(), UvSeamCoding::kContext);
}

TEST(UvCompressionOptionsTest, ParsesAnchorSpecs) {
  UvAnchorSpec count;
  count.count = 100;
  EXPECT_EQ(Anchors("100"), count);
  UvAnchorSpec random_count = count;
  random_count.random = true;
  EXPECT_EQ(Anchors("random:100"), random_count);
  UvAnchorSpec percent;
  percent.is_percent = true;
  percent.percent = 2.5;
  EXPECT_EQ(Anchors("2.5%"), percent);
  UvAnchorSpec random_percent = percent;
  random_percent.random = true;
  EXPECT_EQ(Anchors("random:2.5%"), random_percent);
  EXPECT_EQ(Anchors("0").count, 0);
  EXPECT_EQ(Anchors(std::to_string(kUvLaplacianMaxExtraAnchors)).count,
            kUvLaplacianMaxExtraAnchors);
  EXPECT_EQ(Anchors("100%").percent, 100.0);
  for (const std::string &bad : std::vector<std::string>{
           "", "-3", "random:", "many", "1e3", "%", "101%", "-1%", "2.5.1%",
           "random:x%", "random:-1",
           std::to_string(kUvLaplacianMaxExtraAnchors + 1)}) {
    const StatusOr<UvAnchorSpec> parsed = ParseUvAnchorSpec(bad);
    ASSERT_FALSE(parsed.ok()) << bad;
    EXPECT_NE(parsed.status().error_msg_string().find("-uv_anchors"),
              std::string::npos);
  }
}

TEST(UvCompressionOptionsTest, CheckNeedsALaplacianPredictionForAnchors) {
  UvCompressionOptions options;
  EXPECT_TRUE(CheckUvCompressionOptions(options).ok());
  options.anchors = Anchors("10");
  for (const UvPredictionName &entry : UvPredictionNames()) {
    options.prediction = entry.prediction;
    for (const UvSeamCoding seams :
         {UvSeamCoding::kDraco, UvSeamCoding::kContext}) {
      options.seams = seams;
      const Status status = CheckUvCompressionOptions(options);
      EXPECT_EQ(status.ok(), IsUvLaplacian(entry.prediction)) << entry.name;
      if (!status.ok()) {
        EXPECT_NE(status.error_msg_string().find("-uv_anchors"),
                  std::string::npos);
      }
    }
  }
  // Unset anchors are fine with any prediction.
  options.anchors.reset();
  for (const UvPredictionName &entry : UvPredictionNames()) {
    options.prediction = entry.prediction;
    EXPECT_EQ(CheckUvCompressionOptions(options).ok(),
              !IsUvLaplacian(entry.prediction) || HasUvLaplacianCoder())
        << entry.name;
  }
}

// A Laplacian name is an error in a build without the Laplacian coder.
TEST(UvCompressionOptionsTest, CheckNeedsTheLaplacianCoderInTheBuild) {
#ifdef DRACO_UV_LAPLACIAN
  EXPECT_TRUE(HasUvLaplacianCoder());
#else
  EXPECT_FALSE(HasUvLaplacianCoder());
#endif
  UvCompressionOptions options;
  options.prediction = UvPrediction::kLaplacianCotan;
  const Status status = CheckUvCompressionOptions(options);
  EXPECT_EQ(status.ok(), HasUvLaplacianCoder());
  if (!status.ok()) {
    EXPECT_NE(status.error_msg_string().find("laplacian_cotan"),
              std::string::npos);
  }
}

TEST(UvCompressionOptionsTest, CheckRejectsSettingsTheCodersCannotUse) {
  DracoCompressionOptions sequential = WithPrediction(UvPrediction::kWeighted);
  sequential.compression_level = 0;
  EXPECT_FALSE(sequential.Check().ok());

  DracoCompressionOptions unquantized_uvs =
      WithPrediction(UvPrediction::kParallelogram);
  unquantized_uvs.quantization_bits_tex_coord = 0;
  EXPECT_FALSE(unquantized_uvs.Check().ok());

  DracoCompressionOptions unquantized_positions =
      WithPrediction(UvPrediction::kWeighted);
  unquantized_positions.quantization_position.SetQuantizationBits(0);
  EXPECT_FALSE(unquantized_positions.Check().ok());
  // Auto skips the candidates that need quantized positions.
  unquantized_positions.uv.prediction = UvPrediction::kAuto;
  EXPECT_TRUE(unquantized_positions.Check().ok());
  unquantized_positions.uv.prediction = UvPrediction::kParallelogram;
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
  EXPECT_EQ(options.prediction, UvPrediction::kAuto);
  EXPECT_EQ(options.seams, UvSeamCoding::kDraco);
  EXPECT_FALSE(options.anchors.has_value());
  EXPECT_EQ(index, 2);
}

TEST(UvCompressionFlagTest, RejectsMissingOrUnknownValue) {
  UvCompressionOptions options;
  int index = 1;
  EXPECT_FALSE(Parse({"tool", "-uv_pred"}, &options, &index).ok());
  index = 1;
  const Status unknown = Parse({"tool", "-uv_pred", "fast"}, &options, &index);
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.error_msg_string().find(
                "Unknown -uv_pred name 'fast'. Valid names: draco, "),
            std::string::npos)
      << unknown.error_msg_string();
  EXPECT_TRUE(options.IsStock());
  EXPECT_EQ(options, UvCompressionOptions());
}

TEST(UvCompressionFlagTest, UsageListsEveryName) {
  for (const UvPredictionName &entry : UvPredictionNames()) {
    EXPECT_NE(UvCompressionUsage().find(entry.name), std::string::npos);
  }
  for (const UvSeamCoding coding :
       {UvSeamCoding::kDraco, UvSeamCoding::kContext}) {
    EXPECT_NE(UvCompressionUsage().find(UvSeamCodingNameOf(coding)),
              std::string::npos);
  }
  for (const char *flag : {"-uv_pred", "-uv_seams", "-uv_anchors"}) {
    EXPECT_NE(UvCompressionUsage().find(flag), std::string::npos) << flag;
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
  EXPECT_EQ(options.seams, UvSeamCoding::kContext);
  EXPECT_EQ(options.prediction, UvPrediction::kWeighted);
  EXPECT_FALSE(options.IsStock());
  index = 1;
  EXPECT_FALSE(Parse({"tool", "-uv_seams", "static"}, &options, &index).ok());
}

TEST(UvCompressionFlagTest, ParsesUvAnchorsForTheLaplacianCoder) {
  EXPECT_TRUE(IsUvCompressionFlag("-uv_anchors"));
  UvCompressionOptions options;
  int index = 1;
  ASSERT_TRUE(Parse({"tool", "-uv_anchors", "2%"}, &options, &index).ok());
  ASSERT_TRUE(options.anchors.has_value());
  EXPECT_EQ(*options.anchors, Anchors("2%"));
  EXPECT_TRUE(options.anchors->is_percent);
  EXPECT_EQ(options.anchors->percent, 2.0);
  EXPECT_EQ(index, 2);
  // The flag parser only parses: the pairing with a Laplacian -uv_pred is
  // CheckUvCompressionOptions()'s.
  EXPECT_FALSE(CheckUvCompressionOptions(options).ok());
  index = 1;
  ASSERT_TRUE(
      Parse({"tool", "-uv_pred", "laplacian_cotan"}, &options, &index).ok());
  EXPECT_EQ(options.prediction, UvPrediction::kLaplacianCotan);
  EXPECT_TRUE(CheckUvCompressionOptions(options).ok());
  index = 1;
  EXPECT_FALSE(Parse({"tool", "-uv_anchors", "many"}, &options, &index).ok());
  EXPECT_NE(UvCompressionUsage().find("-uv_anchors"), std::string::npos);
}

TEST(UvCompressionOptionsTest, CheckAnchorsNeedALaplacianScheme) {
  DracoCompressionOptions options =
      WithPrediction(UvPrediction::kLaplacianMeanValue);
  options.uv.anchors = Anchors("random:100");
  EXPECT_TRUE(options.Check().ok());
  EXPECT_NE(options, WithPrediction(UvPrediction::kLaplacianMeanValue));
  options.uv.prediction = UvPrediction::kWeighted;
  EXPECT_FALSE(options.Check().ok());
  // Anchors alone are not stock options that pass unchecked.
  options.uv.prediction = UvPrediction::kDraco;
  EXPECT_FALSE(options.Check().ok());
  options.uv.prediction = UvPrediction::kLaplacianCotan;
  EXPECT_TRUE(options.Check().ok());
}

TEST(UvCompressionOptionsTest, CheckSeamsNeedEdgebreaker) {
  DracoCompressionOptions options;
  options.uv.seams = UvSeamCoding::kDraco;
  EXPECT_TRUE(options.uv.IsStock());
  options.uv.seams = UvSeamCoding::kContext;
  EXPECT_FALSE(options.uv.IsStock());
  EXPECT_TRUE(options.Check().ok());
  EXPECT_NE(options, DracoCompressionOptions());
  options.compression_level = 0;
  EXPECT_FALSE(options.Check().ok());
  options.compression_level = 7;
  EXPECT_TRUE(options.Check().ok());
}

// -tangent_pred in glTF options (draco_transcoder): an error names what is
// missing when the options rule the prediction out on every primitive; auto
// needs only quantized tangents (it keeps stock coding elsewhere).
TEST(UvCompressionOptionsTest, GltfTangentPredictionNeedsWhatItPredictsFrom) {
  struct Case {
    const char *label;
    TangentPrediction prediction;
    void (*change)(DracoCompressionOptions *);
    const char *error;  // "" for valid options.
  };
  const Case cases[] = {
      {"defaults", TangentPrediction::kMikkTSpace,
       [](DracoCompressionOptions *) {}, ""},
      {"auto", TangentPrediction::kAuto, [](DracoCompressionOptions *) {}, ""},
      {"auto at level 3", TangentPrediction::kAuto,
       [](DracoCompressionOptions *o) { o->compression_level = 3; }, ""},
      {"level 0", TangentPrediction::kAuto,
       [](DracoCompressionOptions *o) { o->compression_level = 0; },
       "-tangent_pred needs Edgebreaker encoding: compression level 1 or "
       "more."},
      {"level 4", TangentPrediction::kFace,
       [](DracoCompressionOptions *o) { o->compression_level = 4; },
       "-tangent_pred face needs compression level 5 or more (below, Draco "
       "splits meshes on attribute seams)."},
      {"-qtg 0", TangentPrediction::kAuto,
       [](DracoCompressionOptions *o) { o->quantization_bits_tangent = 0; },
       "-tangent_pred needs quantized tangents: -qtg 1 to 21."},
      {"-qtg 22", TangentPrediction::kGeometric,
       [](DracoCompressionOptions *o) { o->quantization_bits_tangent = 22; },
       "-tangent_pred needs quantized tangents: -qtg 1 to 21."},
      {"-qp 0", TangentPrediction::kUniform,
       [](DracoCompressionOptions *o) {
         o->quantization_position.SetQuantizationBits(0);
       },
       "-tangent_pred uniform needs quantized positions."},
      {"-qn 0", TangentPrediction::kMikkTSpace,
       [](DracoCompressionOptions *o) { o->quantization_bits_normal = 0; },
       "-tangent_pred mikktspace needs quantized normals."},
      {"-qt 0", TangentPrediction::kMikkTSpace,
       [](DracoCompressionOptions *o) { o->quantization_bits_tex_coord = 0; },
       "-tangent_pred mikktspace needs quantized texture coordinates."},
      {"draco_encoder's -qtg", TangentPrediction::kAuto,
       [](DracoCompressionOptions *o) { o->uv.tangent.quantization_bits = 8; },
       "-qtg of draco_encoder (UvCompressionOptions::tangent."
       "quantization_bits) does not apply to glTF: tangents take "
       "DracoCompressionOptions::quantization_bits_tangent "
       "(draco_transcoder's -qtg)."},
  };
  for (const Case &c : cases) {
    DracoCompressionOptions options;
    options.uv.tangent.prediction = c.prediction;
    c.change(&options);
    const Status status = options.Check();
    EXPECT_EQ(status.error_msg_string(), c.error) << c.label;
    EXPECT_EQ(status.ok(), std::string(c.error).empty()) << c.label;
  }
  if (HasUvLaplacianCoder()) {
    DracoCompressionOptions lossy_uvs =
        WithPrediction(UvPrediction::kLaplacianMeanValue);
    lossy_uvs.uv.tangent.prediction = TangentPrediction::kMikkTSpace;
    EXPECT_EQ(lossy_uvs.Check().error_msg_string(),
              "-tangent_pred mikktspace needs losslessly coded texture "
              "coordinates, not -uv_pred laplacian_mv.");
    lossy_uvs.uv.tangent.prediction = TangentPrediction::kAuto;
    EXPECT_TRUE(lossy_uvs.Check().ok());
  }
}

}  // namespace
}  // namespace draco
