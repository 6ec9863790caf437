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
// -uv_anchors and the checks of the Laplacian scheme's settings
// (uv_laplacian_options.h), through the encoder.
#include "draco_ext/options/uv_laplacian_options.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "prediction_schemes/laplacian/uv_laplacian_settings.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

// P% means ceil(P / 100 * the attribute's texture coordinates) anchors.
TEST(UvLaplacianOptionsTest, PercentAnchorsScaleWithTheMesh) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  const int64_t num_values =
      mesh.value()->GetNamedAttribute(GeometryAttribute::TEX_COORD)->size();
  for (const int percent : {1, 5, 20}) {
    const int count = static_cast<int>((percent * num_values + 99) / 100);
    for (const std::string prefix : {"", "random:"}) {
      const auto by_percent = EncodeMeshToBytes(
          *mesh.value(), Settings(14, 10, 10, "laplacian_mv",
                                  prefix + std::to_string(percent) + "%"));
      const auto by_count = EncodeMeshToBytes(
          *mesh.value(), Settings(14, 10, 10, "laplacian_mv",
                                  prefix + std::to_string(count)));
      ASSERT_TRUE(by_percent.ok() && by_count.ok()) << prefix << percent;
      EXPECT_EQ(by_percent.value(), by_count.value()) << prefix << percent;
    }
  }
  for (const std::string bad : {"%", "101%", "-1%", "2.5.1%", "random:x%"}) {
    EXPECT_FALSE(ParseUvAnchorSpec(bad).ok()) << bad;
  }
  EXPECT_TRUE(ParseUvAnchorSpec("0.5%").ok());
}

TEST(UvLaplacianOptionsTest, AnchorCountRoundsPercentagesUp) {
  UvAnchorSpec spec;
  spec.count = 7;
  EXPECT_EQ(UvAnchorCount(spec, 1000), 7);
  spec.random = true;
  EXPECT_EQ(UvAnchorCount(spec, 3), 7);
  spec.is_percent = true;
  spec.percent = 2.5;
  EXPECT_EQ(UvAnchorCount(spec, 1000), 25);
  EXPECT_EQ(UvAnchorCount(spec, 1001), 26);
  spec.percent = 0.01;
  EXPECT_EQ(UvAnchorCount(spec, 50), 1);  // Any positive P gives one.
  spec.percent = 0;
  EXPECT_EQ(UvAnchorCount(spec, 1000), 0);
  spec.percent = 100;
  EXPECT_EQ(UvAnchorCount(spec, int64_t{1} << 30),
            kUvLaplacianMaxExtraAnchors);
}

// The Laplacian predictions reach the scheme's encoder as typed settings:
// the operator, the step from -qt, the finer frame Draco quantises to, and
// the anchors.
TEST(UvLaplacianOptionsTest, StoresTheSettingsOfTheScheme) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  const int att_id =
      mesh.value()->GetNamedAttributeId(GeometryAttribute::TEX_COORD);
  const struct {
    UvPrediction prediction;
    UvLaplacianKind kind;
  } kinds[] = {{UvPrediction::kLaplacianTutte, UvLaplacianKind::kTutte},
               {UvPrediction::kLaplacianCotan, UvLaplacianKind::kCotangent},
               {UvPrediction::kLaplacianMeanValue,
                UvLaplacianKind::kMeanValue}};
  for (const auto &entry : kinds) {
    for (const std::string anchors : {"", "random:7", "12"}) {
      ExpertEncoder encoder(*mesh.value());
      for (int i = 0; i < mesh.value()->num_attributes(); ++i) {
        encoder.SetAttributeQuantization(i, 10);
      }
      const std::optional<UvAnchorSpec> spec =
          anchors.empty() ? std::nullopt
                          : std::optional<UvAnchorSpec>(
                                ParseUvAnchorSpec(anchors).value());
      ASSERT_TRUE(ConfigureUvLaplacian(entry.prediction, spec, *mesh.value(),
                                       att_id, &encoder)
                      .ok());
      const UvLaplacianEncoderOptions settings =
          GetUvLaplacianSettings(encoder.options(), att_id);
      EXPECT_EQ(settings.kind, entry.kind);
      EXPECT_EQ(settings.step_bits, 10);
      EXPECT_EQ(settings.frame_bits, 10 + kUvLaplacianFrameExtraBits);
      EXPECT_EQ(encoder.options().GetAttributeInt(att_id, "quantization_bits",
                                                  -1),
                settings.frame_bits);
      EXPECT_EQ(settings.extra_anchors,
                anchors.empty() ? kUvLaplacianDefaultExtraAnchors
                : anchors == "12" ? 12
                                  : 7)
          << anchors;
      EXPECT_EQ(settings.selection, anchors == "random:7"
                                        ? UvAnchorSelection::kRandom
                                        : UvAnchorSelection::kGreedy)
          << anchors;
    }
  }
  ExpertEncoder encoder(*mesh.value());
  encoder.SetAttributeQuantization(att_id, 10);
  EXPECT_FALSE(ConfigureUvLaplacian(UvPrediction::kWeighted, std::nullopt,
                                    *mesh.value(), att_id, &encoder)
                   .ok());
}

TEST(UvLaplacianOptionsTest, RejectsBadOptions) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  for (const std::string bad : {"-3", "random:"}) {
    EXPECT_FALSE(ParseUvAnchorSpec(bad).ok()) << bad;
  }
  for (const UvEncodeSettings &bad : std::vector<UvEncodeSettings>{
           Settings(14, 10, 10, "weighted", "10"),
           Settings(14, 10, 10, "draco", "10"),
           Settings(14, 10, 10, "draco+context", "10"),
           Settings(14, 21, 10, "laplacian_mv")}) {
    EXPECT_FALSE(EncodeMeshToBytes(*mesh.value(), bad).ok())
        << UvPredictionNameOf(bad.uv.prediction) << " anchors "
        << bad.uv.anchors.has_value() << " qt " << bad.qt;
  }
  EXPECT_FALSE(IsLossyUvPrediction(MESH_PREDICTION_TEX_COORDS_WEIGHTED));
  EXPECT_TRUE(IsLossyUvPrediction(MESH_PREDICTION_TEX_COORDS_LAPLACIAN));
}

}  // namespace
}  // namespace draco
