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
#include "draco_ext/seams/uv_seam_topology.h"

#include <algorithm>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "tests/draco_ext/seams/uv_seam_test_meshes.h"

namespace draco {
namespace {

// Every edge once in each of its two vertices' rings, and once in Draco's
// seam order.
TEST(UvSeamTopologyTest, ListsEveryEdgeInBothRingsAndOnceInDracoOrder) {
  for (const std::string name : {"cube_att.obj", "sphere.obj", "bun_zipper.ply",
                                 "octagon.obj", "multiple_tetrahedrons.obj"}) {
    const auto mesh = ReadDracoTestMesh(name);
    ASSERT_NE(mesh, nullptr);
    const UvSeamTopology topology = TopologyOf(*mesh);
    std::vector<int> ring_count(topology.num_edges(), 0);
    for (int32_t v = 0; v < topology.num_vertices(); ++v) {
      int boundary = 0;
      for (const int32_t *e = topology.RingBegin(v); e != topology.RingEnd(v);
           ++e) {
        if (*e == UvSeamTopology::kBoundary) {
          ++boundary;
          continue;
        }
        ++ring_count[*e];
        EXPECT_TRUE(topology.EdgeVertex(*e, 0) == v ||
                    topology.EdgeVertex(*e, 1) == v);
      }
      EXPECT_EQ(boundary, topology.IsOpen(v) ? 2 : 0) << name;
    }
    EXPECT_TRUE(std::all_of(ring_count.begin(), ring_count.end(),
                            [](int count) { return count == 2; }))
        << name;
    std::vector<int32_t> order = topology.DracoSeamOrder();
    std::sort(order.begin(), order.end());
    EXPECT_EQ(order.size(), static_cast<size_t>(topology.num_edges()));
    EXPECT_TRUE(std::adjacent_find(order.begin(), order.end()) == order.end());
  }
}

TEST(UvSeamTopologyTest, ClosedMeshHasEulerCharacteristicTwo) {
  const auto mesh = ReadDracoTestMesh("cube_att.obj");
  ASSERT_NE(mesh, nullptr);
  const UvSeamTopology topology = TopologyOf(*mesh);
  EXPECT_EQ(topology.num_vertices() - topology.num_edges() +
                topology.num_corners() / 3,
            2);
}

TEST(UvSeamTopologyTest, RejectsInvalidOppositePairings) {
  UvSeamTopology topology;
  EXPECT_TRUE(topology.Init({-1, -1, -1, -1, -1, -1}));
  EXPECT_TRUE(topology.Init({3, -1, -1, 0, -1, -1}));
  EXPECT_FALSE(topology.Init({3, -1, -1, -1, -1, -1}));  // Not symmetric.
  EXPECT_FALSE(topology.Init({1, 0, -1, -1, -1, -1}));   // Same face.
  EXPECT_FALSE(topology.Init({6, -1, -1, -1, -1, -1}));  // Out of range.
  EXPECT_FALSE(topology.Init({-2, -1, -1}));
  EXPECT_FALSE(topology.Init({-1, -1}));  // Not whole faces.
}

}  // namespace
}  // namespace draco
