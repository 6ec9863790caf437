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
#include "draco_ext/eval/uv_seam_stats.h"

#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

// Textured meshes of Draco's testdata and, when present, the corpus.
std::vector<std::string> MeshPaths() {
  std::vector<std::string> paths;
  for (const std::string &name : DracoTestdataTexturedMeshes()) {
    paths.push_back(DracoTestdataPath(name));
  }
  for (const std::string &path : CorpusMeshPaths()) {
    paths.push_back(path);
  }
  return paths;
}

// Stock and context byte counts are exactly what the files contain (their
// difference is the difference of the file sizes), and context coding
// never costs more than stock coding where there are seams.
TEST(UvSeamStatsTest, CountsExactBytesAndContextNeverLosesToStock) {
  const std::vector<std::string> paths = MeshPaths();
  ASSERT_GE(paths.size(), 20u);
  for (const std::string &path : paths) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    for (const int cl : {5, 10}) {
      const auto stats = MeasureUvSeams(path, *mesh.value(), {14, 12, cl});
      ASSERT_TRUE(stats.ok()) << path;
      const UvSeamStats &s = stats.value();
      EXPECT_TRUE(s.sizes_match_files) << path << " cl" << cl;
      if (s.seam_edges > 0) {
        EXPECT_LT(s.context_bytes, s.stock_bytes) << path << " cl" << cl;
      }
      EXPECT_LE(s.context_bytes, s.stock_bytes) << path << " cl" << cl;
    }
  }
}

TEST(UvSeamStatsTest, SeamFreeMeshesCostAtMostOneByteBeyondStockFraming) {
  const auto mesh = ReadTestMesh(DracoTestdataPath("bunny_norm.obj"));
  ASSERT_TRUE(mesh.ok());
  const auto stats = MeasureUvSeams("bunny_norm", *mesh.value(), {14, 12, 10});
  ASSERT_TRUE(stats.ok());
  EXPECT_EQ(stats.value().seam_edges, 0);
  EXPECT_LE(stats.value().context_bytes, 1);
  EXPECT_LE(stats.value().per_edge_bytes, 2);
  EXPECT_LE(stats.value().per_vertex_bytes, 2);
}

}  // namespace
}  // namespace draco
