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
#include "draco_ext/seams/uv_seam_coder.h"

#include <algorithm>
#include <random>
#include <set>

#include "draco_ext/eval/uv_seam_stats.h"
#include "gtest/gtest.h"
#include "tests/draco_ext/seams/uv_seam_test_meshes.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

// Seam problems of textured meshes of Draco's testdata (Draco's own seams).
std::vector<UvSeamProblem> DracoTestdataProblems() {
  std::vector<UvSeamProblem> problems;
  for (const std::string &name : DracoTestdataTexturedMeshes()) {
    const auto mesh = ReadDracoTestMesh(name);
    if (mesh == nullptr) {
      continue;
    }
    auto problem = BuildUvSeamProblem(*mesh, {14, 12, 10});
    if (problem.ok()) {
      problems.push_back(std::move(problem).value());
    }
  }
  return problems;
}

// Seam bits of |num_attributes| attributes for the edges of |table|.
size_t NumBits(const UvSeamCornerTable &table, int num_attributes) {
  UvSeamContextCoder<UvSeamCornerTable> coder;
  EXPECT_TRUE(coder.Init(table, num_attributes));
  return coder.num_edges() * num_attributes;
}

bool RoundTrips(const UvSeamCornerTable &table, int num_attributes,
                const std::vector<uint8_t> &bits) {
  std::vector<uint8_t> bytes;
  std::vector<uint8_t> decoded;
  return EncodeUvSeams(table, num_attributes, bits, &bytes) &&
         DecodeUvSeams(table, num_attributes, bytes.data(), bytes.size(),
                       &decoded) &&
         decoded == bits;
}

TEST(UvSeamCoderTest, RoundTripsTheSeamsOfDracoTestdata) {
  const std::vector<UvSeamProblem> problems = DracoTestdataProblems();
  ASSERT_GE(problems.size(), 20u);
  for (const UvSeamProblem &problem : problems) {
    EXPECT_TRUE(
        RoundTrips(problem.table, problem.num_attributes, problem.bits));
  }
}

// Random seams (independent, and later attributes partly copying earlier
// ones) on real connectivity: nothing in the coder relies on seams being
// plausible.
TEST(UvSeamCoderTest, RoundTripsArbitrarySeamSetsOfSeveralAttributes) {
  std::mt19937 random(7);
  for (const std::string name :
       {"cube_att.obj", "sphere.obj", "bun_zipper.ply", "octagon.obj"}) {
    const auto mesh = ReadDracoTestMesh(name);
    ASSERT_NE(mesh, nullptr);
    const UvSeamCornerTable table = CornerTableOf(*mesh);
    for (const int num_attributes : {1, 3}) {
      for (const int percent : {0, 2, 30, 100}) {
        std::vector<uint8_t> bits(NumBits(table, num_attributes));
        for (size_t i = 0; i < bits.size(); ++i) {
          const int attribute = static_cast<int>(i % num_attributes);
          bits[i] = attribute == 0 ? static_cast<int>(random() % 100) < percent
                    : attribute == 1
                        ? (random() % 4 == 0 ? !bits[i - 1] : bits[i - 1])
                        : random() % 2;
        }
        EXPECT_TRUE(RoundTrips(table, num_attributes, bits))
            << name << " " << num_attributes << " " << percent;
      }
    }
  }
}

// Quiet edges (no seam or boundary at either end yet) are coded as runs
// per class: seam sets that start, end or never end runs, on closed meshes
// and meshes with boundaries, with seams only in some of several attributes
// (the last attribute's bit on an edge that ends a run is implied).
TEST(UvSeamCoderTest, RoundTripsRunEdgeCases) {
  for (const std::string name :
       {"cube_att.obj", "sphere.obj", "bun_zipper.ply", "octagon.obj"}) {
    const auto mesh = ReadDracoTestMesh(name);
    ASSERT_NE(mesh, nullptr);
    const UvSeamCornerTable table = CornerTableOf(*mesh);
    for (const int num_attributes : {1, 2, 3}) {
      const size_t num_bits = NumBits(table, num_attributes);
      const size_t num_edges = num_bits / num_attributes;
      ASSERT_GT(num_edges, 0u) << name;
      for (const int attribute : {0, num_attributes - 1}) {
        // Seams on the first edge, the last edge, both, every edge, every
        // 7th edge, and none.
        std::vector<std::vector<size_t>> seam_sets = {
            {0}, {num_edges - 1}, {0, num_edges - 1}, {}};
        std::vector<size_t> every, every_7th;
        for (size_t edge = 0; edge < num_edges; ++edge) {
          every.push_back(edge);
          if (edge % 7 == 3) {
            every_7th.push_back(edge);
          }
        }
        seam_sets.push_back(every);
        seam_sets.push_back(every_7th);
        for (const std::vector<size_t> &seams : seam_sets) {
          std::vector<uint8_t> bits(num_bits, 0);
          for (const size_t edge : seams) {
            bits[edge * num_attributes + attribute] = 1;
          }
          EXPECT_TRUE(RoundTrips(table, num_attributes, bits))
              << name << " " << num_attributes << " attribute " << attribute
              << " seams " << seams.size();
        }
      }
    }
  }
}

// A lone seam edge anywhere in a mesh of hundreds or thousands of quiet
// edges costs a few bytes, not bits per edge.
TEST(UvSeamCoderTest, LongQuietRunsCostFewBytes) {
  for (const std::string name : {"sphere.obj", "bun_zipper.ply"}) {
    const auto mesh = ReadDracoTestMesh(name);
    ASSERT_NE(mesh, nullptr);
    const UvSeamCornerTable table = CornerTableOf(*mesh);
    const size_t num_edges = NumBits(table, 1);
    ASSERT_GE(num_edges, 300u) << name;
    for (const size_t edge : {size_t{0}, num_edges / 2, num_edges - 1}) {
      std::vector<uint8_t> bits(num_edges, 0);
      bits[edge] = 1;
      std::vector<uint8_t> bytes;
      ASSERT_TRUE(EncodeUvSeams(table, 1, bits, &bytes));
      EXPECT_LE(bytes.size(), 8u) << name << " edge " << edge;
    }
  }
}

TEST(UvSeamCoderTest, HandlesMeshesWithoutAttributesOrInteriorEdges) {
  const auto mesh = ReadDracoTestMesh("multiple_isolated_triangles.obj");
  ASSERT_NE(mesh, nullptr);
  const UvSeamCornerTable table = CornerTableOf(*mesh);
  EXPECT_EQ(NumBits(table, 1), 0u);
  EXPECT_TRUE(RoundTrips(table, 0, {}));
  EXPECT_TRUE(RoundTrips(table, 2, {}));
  std::vector<uint8_t> bytes;
  ASSERT_TRUE(EncodeUvSeams(table, 1, {}, &bytes));
  EXPECT_TRUE(bytes.empty());
  // Bits of edges the table does not have.
  EXPECT_FALSE(EncodeUvSeams(table, 1, {0}, &bytes));
}

TEST(UvSeamCoderTest, RejectsTablesWithCornersOutOfRange) {
  const auto mesh = ReadDracoTestMesh("cube_att.obj");
  ASSERT_NE(mesh, nullptr);
  const UvSeamCornerTable table = CornerTableOf(*mesh);
  std::vector<uint8_t> decoded;
  UvSeamCornerTable bad_vertex = table;
  bad_vertex.vertex[5] = bad_vertex.num_vertices;
  EXPECT_FALSE(DecodeUvSeams(bad_vertex, 1, nullptr, 0, &decoded));
  UvSeamCornerTable bad_opposite = table;
  bad_opposite.opposite[4] = static_cast<uint32_t>(table.num_corners());
  EXPECT_FALSE(DecodeUvSeams(bad_opposite, 1, nullptr, 0, &decoded));
}

TEST(UvSeamCoderTest, RejectsEveryAlteredOrTruncatedStream) {
  const auto mesh = ReadDracoTestMesh("sphere_two_tex_coords.gltf");
  ASSERT_NE(mesh, nullptr);
  const auto problem = BuildUvSeamProblem(*mesh, {14, 12, 10});
  ASSERT_TRUE(problem.ok());
  const UvSeamProblem &p = problem.value();
  ASSERT_GE(p.num_attributes, 2);
  std::vector<uint8_t> bytes;
  ASSERT_TRUE(EncodeUvSeams(p.table, p.num_attributes, p.bits, &bytes));
  ASSERT_GE(bytes.size(), 8u);
  std::vector<uint8_t> decoded;
  for (size_t i = 0; i < bytes.size(); ++i) {
    for (const uint8_t flip : {0x01, 0x80, 0xFF}) {
      std::vector<uint8_t> altered = bytes;
      altered[i] ^= flip;
      EXPECT_FALSE(DecodeUvSeams(p.table, p.num_attributes, altered.data(),
                                 altered.size(), &decoded))
          << "byte " << i;
    }
    // (No bytes at all is the valid stream of a mesh without seams.)
    if (i > 0) {
      EXPECT_FALSE(
          DecodeUvSeams(p.table, p.num_attributes, bytes.data(), i, &decoded))
          << "first " << i << " bytes";
    }
  }
  // A stream of other attributes does not decode either.
  EXPECT_FALSE(DecodeUvSeams(p.table, p.num_attributes - 1, bytes.data(),
                             bytes.size(), &decoded));
}

}  // namespace
}  // namespace draco
