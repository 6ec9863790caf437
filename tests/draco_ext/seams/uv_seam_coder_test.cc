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

bool RoundTrips(const UvSeamTopology &topology,
                const std::vector<UvSeamFlags> &seams) {
  const std::vector<uint8_t> bytes = EncodeUvSeams(topology, seams);
  std::vector<UvSeamFlags> decoded;
  return DecodeUvSeams(topology, static_cast<int>(seams.size()), bytes.data(),
                       bytes.size(), &decoded) &&
         decoded == seams;
}

TEST(UvSeamCoderTest, RoundTripsTheSeamsOfDracoTestdata) {
  const std::vector<UvSeamProblem> problems = DracoTestdataProblems();
  ASSERT_GE(problems.size(), 20u);
  for (const UvSeamProblem &problem : problems) {
    EXPECT_TRUE(RoundTrips(problem.topology, problem.seams));
  }
}

// Random seams (independent, and later attributes partly copying earlier
// ones) on real topologies: nothing in the coder relies on seams being
// plausible.
TEST(UvSeamCoderTest, RoundTripsArbitrarySeamSetsOfSeveralAttributes) {
  std::mt19937 random(7);
  for (const std::string name :
       {"cube_att.obj", "sphere.obj", "bun_zipper.ply", "octagon.obj"}) {
    const auto mesh = ReadDracoTestMesh(name);
    ASSERT_NE(mesh, nullptr);
    const UvSeamTopology topology = TopologyOf(*mesh);
    for (const int percent : {0, 2, 30, 100}) {
      std::vector<UvSeamFlags> seams(3, UvSeamFlags(topology.num_edges()));
      for (int32_t e = 0; e < topology.num_edges(); ++e) {
        seams[0][e] = static_cast<int>(random() % 100) < percent;
        seams[1][e] = random() % 4 == 0 ? !seams[0][e] : seams[0][e];
        seams[2][e] = random() % 2;
      }
      EXPECT_TRUE(RoundTrips(topology, seams)) << name << " " << percent;
    }
  }
}

TEST(UvSeamCoderTest, HandlesMeshesWithoutAttributesOrInteriorEdges) {
  const auto mesh = ReadDracoTestMesh("multiple_isolated_triangles.obj");
  ASSERT_NE(mesh, nullptr);
  const UvSeamTopology topology = TopologyOf(*mesh);
  EXPECT_EQ(topology.num_edges(), 0);
  EXPECT_TRUE(RoundTrips(topology, {}));
  EXPECT_TRUE(RoundTrips(topology, {UvSeamFlags(), UvSeamFlags()}));
  EXPECT_TRUE(EncodeUvSeams(topology, {UvSeamFlags()}).empty());
}

TEST(UvSeamCoderTest, RejectsEveryAlteredOrTruncatedStream) {
  const auto mesh = ReadDracoTestMesh("sphere_two_tex_coords.gltf");
  ASSERT_NE(mesh, nullptr);
  const auto problem = BuildUvSeamProblem(*mesh, {14, 12, 10});
  ASSERT_TRUE(problem.ok());
  const UvSeamProblem &p = problem.value();
  const int num_attributes = static_cast<int>(p.seams.size());
  ASSERT_GE(num_attributes, 2);
  const std::vector<uint8_t> bytes = EncodeUvSeams(p.topology, p.seams);
  ASSERT_GE(bytes.size(), 8u);
  std::vector<UvSeamFlags> decoded;
  for (size_t i = 0; i < bytes.size(); ++i) {
    for (const uint8_t flip : {0x01, 0x80, 0xFF}) {
      std::vector<uint8_t> altered = bytes;
      altered[i] ^= flip;
      EXPECT_FALSE(DecodeUvSeams(p.topology, num_attributes, altered.data(),
                                 altered.size(), &decoded))
          << "byte " << i;
    }
    // (No bytes at all is the valid stream of a mesh without seams.)
    if (i > 0) {
      EXPECT_FALSE(
          DecodeUvSeams(p.topology, num_attributes, bytes.data(), i, &decoded))
          << "first " << i << " bytes";
    }
  }
  // A stream of other attributes does not decode either.
  EXPECT_FALSE(DecodeUvSeams(p.topology, num_attributes - 1, bytes.data(),
                             bytes.size(), &decoded));
}

}  // namespace
}  // namespace draco
