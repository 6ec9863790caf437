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
#include <string>
#include <vector>

#include "gtest/gtest.h"
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
          *mesh.value(), {14, 10, 10, "laplacian_mv", "",
                          prefix + std::to_string(percent) + "%"});
      const auto by_count = EncodeMeshToBytes(
          *mesh.value(),
          {14, 10, 10, "laplacian_mv", "", prefix + std::to_string(count)});
      ASSERT_TRUE(by_percent.ok() && by_count.ok()) << prefix << percent;
      EXPECT_EQ(by_percent.value(), by_count.value()) << prefix << percent;
    }
  }
  for (const std::string bad : {"%", "101%", "-1%", "2.5.1%", "random:x%"}) {
    EXPECT_FALSE(ParseUvAnchorSpec(bad).ok()) << bad;
  }
  EXPECT_TRUE(ParseUvAnchorSpec("0.5%").ok());
}

TEST(UvLaplacianOptionsTest, RejectsBadOptions) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  for (const UvEncodeSettings &bad : std::vector<UvEncodeSettings>{
           {14, 10, 10, "laplacian_mv", "", "-3"},
           {14, 10, 10, "laplacian_mv", "", "random:"},
           {14, 10, 10, "weighted", "", "10"},
           {14, 10, 10, "", "", "10"},
           {14, 21, 10, "laplacian_mv", "", ""}}) {
    EXPECT_FALSE(EncodeMeshToBytes(*mesh.value(), bad).ok())
        << bad.uv_pred << " " << bad.uv_anchors << " qt " << bad.qt;
  }
  EXPECT_FALSE(IsLossyUvPrediction(MESH_PREDICTION_TEX_COORDS_WEIGHTED));
  EXPECT_TRUE(IsLossyUvPrediction(MESH_PREDICTION_TEX_COORDS_LAPLACIAN));
}

}  // namespace
}  // namespace draco
