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
// The default number of extra anchors of the Laplacian coder
// (uv_laplacian_settings.h: UvDefaultExtraAnchors()) and the settings'
// round trip through Draco's encoder options.
#include "prediction_schemes/laplacian/uv_laplacian_settings.h"

#include <cstdint>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "gtest/gtest.h"

namespace draco {
namespace {

// (texture vertices, boundary vertices) pairs from empty meshes to beyond
// any corpus mesh, with 0 to all vertices on the boundary.
std::vector<std::pair<int, int>> Sizes() {
  std::vector<std::pair<int, int>> sizes = {{0, 0}, {1, 0}, {1, 1}, {3, 3}};
  std::mt19937 random(7);
  for (int i = 0; i < 2000; ++i) {
    const int n = static_cast<int>(random() % (1 << (1 + i % 24)));
    sizes.push_back({n, n == 0 ? 0 : static_cast<int>(random() % (n + 1))});
  }
  return sizes;
}

TEST(UvDefaultExtraAnchorsTest, GrowsWithTheVerticesAndTheBoundary) {
  for (const auto &[n, b] : Sizes()) {
    const int anchors = UvDefaultExtraAnchors(n, b);
    EXPECT_LE(anchors, UvDefaultExtraAnchors(n + 1, b)) << n << " " << b;
    EXPECT_LE(anchors, UvDefaultExtraAnchors(n + 1000, b)) << n << " " << b;
    if (b < n) {
      EXPECT_LE(anchors, UvDefaultExtraAnchors(n, b + 1)) << n << " " << b;
    }
  }
}

TEST(UvDefaultExtraAnchorsTest, OnePerVerticesAndPerBoundaryVertices) {
  // At least one anchor per 154 texture vertices (0.65 %) plus one per 17
  // boundary vertices (6 %), rounded up, and no more than that.
  for (const auto &[n, b] : Sizes()) {
    const double share = 0.0065 * n + 0.06 * b;
    const int anchors = UvDefaultExtraAnchors(n, b);
    EXPECT_GE(anchors, share - 1e-9) << n << " " << b;
    EXPECT_LT(anchors, share + 1) << n << " " << b;
  }
}

TEST(UvDefaultExtraAnchorsTest, NeverMoreThanTheVertices) {
  for (const auto &[n, b] : Sizes()) {
    EXPECT_LE(UvDefaultExtraAnchors(n, b), n) << n << " " << b;
  }
  EXPECT_EQ(UvDefaultExtraAnchors(0, 0), 0);
  const int most = std::numeric_limits<int>::max();
  EXPECT_EQ(UvDefaultExtraAnchors(most, most), kUvLaplacianMaxExtraAnchors);
  EXPECT_EQ(UvDefaultExtraAnchors(-5, -5), 0);
}

TEST(UvLaplacianSettingsTest, DefaultAnchorsSurviveTheEncoderOptions) {
  EncoderOptions options = EncoderOptions::CreateDefaultOptions();
  for (const int anchors : {kUvLaplacianDefaultExtraAnchors, 0, 50}) {
    UvLaplacianEncoderOptions settings;
    settings.extra_anchors = anchors;
    SetUvLaplacianSettings(settings, 1, &options);
    EXPECT_EQ(GetUvLaplacianSettings(options, 1).extra_anchors, anchors);
  }
  EXPECT_EQ(GetUvLaplacianSettings(options, 2).extra_anchors,
            kUvLaplacianDefaultExtraAnchors);
}

}  // namespace
}  // namespace draco
