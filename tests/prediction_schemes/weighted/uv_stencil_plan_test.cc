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
// Tests of UvStencilPlanner: on grids in the max prediction degree order
// and in random orders, every stencil is a face of the tip whose other
// vertices come first, the reach face is one when it can be, and the
// neighbours are known vertices next to the tip; on corrupt connectivity
// the plans stay within their bounds and name only valid entries.
#include "prediction_schemes/weighted/uv_stencil_plan.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "gtest/gtest.h"

namespace draco {
namespace {

// A triangulated n x n cell grid, one entry per vertex, with opposite
// corners matched across shared edges (none on the border).
UvCornerGraph MakeGridGraph(int n) {
  UvCornerGraph graph;
  const auto vertex = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      for (const int v :
           {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j),
            vertex(i + 1, j + 1), vertex(i, j + 1)}) {
        graph.entry.push_back(v);
      }
    }
  }
  graph.opposite.assign(graph.entry.size(), UvCornerGraph::kNone);
  std::map<std::pair<int32_t, int32_t>, int32_t> corner_of_edge;
  for (int32_t c = 0; c < graph.num_corners(); ++c) {
    // The edge opposite c, from Next(c) to Previous(c).
    const int32_t a = graph.entry[UvCornerGraph::Next(c)];
    const int32_t b = graph.entry[UvCornerGraph::Previous(c)];
    const auto twin = corner_of_edge.find({b, a});
    if (twin != corner_of_edge.end()) {
      graph.opposite[c] = twin->second;
      graph.opposite[twin->second] = c;
    }
    corner_of_edge[{a, b}] = c;
  }
  return graph;
}

// Draco's order (entry p first reached through its first corner), shuffled.
UvProcessingOrder RandomOrder(const UvCornerGraph &graph, int num_entries,
                              std::mt19937 *random) {
  std::vector<CornerIndex> corner_of_entry(num_entries);
  for (int c = graph.num_corners() - 1; c >= 0; --c) {
    corner_of_entry[graph.entry[c]] = CornerIndex(c);
  }
  std::vector<int> permutation(num_entries);
  std::iota(permutation.begin(), permutation.end(), 0);
  std::shuffle(permutation.begin(), permutation.end(), *random);
  UvProcessingOrder order;
  order.Reset(num_entries);
  for (const int entry : permutation) {
    order.Add(entry, static_cast<int32_t>(corner_of_entry[entry].value()));
  }
  return order;
}

bool IsFaceOf(const UvCornerGraph &graph, int32_t a, int32_t b, int32_t c) {
  const std::multiset<int32_t> wanted = {a, b, c};
  for (int32_t f = 0; f < graph.num_faces(); ++f) {
    if (std::multiset<int32_t>(graph.entry.begin() + 3 * f,
                               graph.entry.begin() + 3 * f + 3) == wanted) {
      return true;
    }
  }
  return false;
}

bool AreNeighbours(const UvCornerGraph &graph, int32_t a, int32_t b) {
  for (int32_t c = 0; c < graph.num_corners(); ++c) {
    if (graph.entry[c] == a &&
        (graph.entry[UvCornerGraph::Next(c)] == b ||
         graph.entry[UvCornerGraph::Previous(c)] == b)) {
      return true;
    }
  }
  return false;
}

// The properties of the file comment, for every step of |order|. Returns
// the number of steps with several stencils.
int ExpectValidPlans(const UvCornerGraph &graph,
                      const UvProcessingOrder &order) {
  const UvStencilPlanner planner(graph, order);
  int num_with_two = 0;
  for (int step = 0; step < static_cast<int>(order.entries.size()); ++step) {
    const int32_t tip = order.entries[step];
    UvStencilPlan plan;
    planner.Build(step, &plan);
    EXPECT_LE(plan.num_stencils, UvStencilPlan::kMaxStencils);
    EXPECT_LE(plan.num_neighbours, UvStencilPlan::kMaxNeighbours);
    for (int i = 0; i < plan.num_stencils; ++i) {
      const UvStencilPlan::Stencil &s = plan.stencils[i];
      EXPECT_LT(order.rank[s.l], step);
      EXPECT_LT(order.rank[s.r], step);
      EXPECT_NE(s.l, s.r);
      EXPECT_TRUE(IsFaceOf(graph, tip, s.l, s.r)) << "step " << step;
      if (s.b != UvCornerGraph::kNone) {
        EXPECT_LT(order.rank[s.b], step);
        EXPECT_TRUE(IsFaceOf(graph, s.b, s.l, s.r)) << "step " << step;
      }
    }
    for (int i = 0; i < plan.num_neighbours; ++i) {
      EXPECT_LT(order.rank[plan.neighbours[i]], step);
      EXPECT_TRUE(AreNeighbours(graph, tip, plan.neighbours[i]));
    }
    // The reach face is the first stencil whenever its L and R are known.
    const int32_t reach = order.corners[step];
    const int32_t l = graph.entry[UvCornerGraph::Next(reach)];
    const int32_t r = graph.entry[UvCornerGraph::Previous(reach)];
    if (order.rank[l] < step && order.rank[r] < step) {
      EXPECT_GE(plan.num_stencils, 1) << "step " << step;
      if (plan.num_stencils >= 1) {
        EXPECT_EQ(plan.stencils[0].l, l);
        EXPECT_EQ(plan.stencils[0].r, r);
      }
    }
    num_with_two += plan.num_stencils >= 2;
  }
  return num_with_two;
}

TEST(UvStencilPlanTest, StencilsAreEarlierFacesOfTheTipInTheMaxDegreeOrder) {
  for (const int n : {5, 12, 20}) {
    const UvCornerGraph graph = MakeGridGraph(n);
    const int num_entries = (n + 1) * (n + 1);
    std::vector<CornerIndex> data_to_corner(num_entries);
    for (int c = graph.num_corners() - 1; c >= 0; --c) {
      data_to_corner[graph.entry[c]] = CornerIndex(c);
    }
    UvProcessingOrder order;
    BuildMaxDegreeOrder(graph, data_to_corner, &order);
    // The order predicts a vertex late, so that it has several stencils.
    EXPECT_GT(ExpectValidPlans(graph, order), num_entries / 4) << n;
  }
}

TEST(UvStencilPlanTest, StencilsAreEarlierFacesOfTheTipInRandomOrders) {
  std::mt19937 random(7);
  for (const int n : {2, 4, 9}) {
    const UvCornerGraph graph = MakeGridGraph(n);
    for (int trial = 0; trial < 20; ++trial) {
      ExpectValidPlans(graph, RandomOrder(graph, (n + 1) * (n + 1), &random));
    }
  }
}

TEST(UvStencilPlanTest, CorruptConnectivityStaysWithinBounds) {
  // Opposite corners and entries as BuildUvCornerGraph() bounds them (any
  // corner or kNone, any entry or kNone), and reach corners anywhere.
  std::mt19937 random(11);
  for (int trial = 0; trial < 200; ++trial) {
    const int num_entries = 1 + static_cast<int>(random() % 20);
    const int num_corners = 3 * (1 + static_cast<int>(random() % 20));
    UvCornerGraph graph;
    for (int c = 0; c < num_corners; ++c) {
      graph.entry.push_back(static_cast<int32_t>(random() % (num_entries + 1)) -
                            1);
      graph.opposite.push_back(
          static_cast<int32_t>(random() % (num_corners + 1)) - 1);
    }
    UvProcessingOrder order;
    order.Reset(num_entries);
    for (int p = 0; p < num_entries; ++p) {
      order.Add(p, static_cast<int32_t>(random() % (num_corners + 2)) - 1);
    }
    const UvStencilPlanner planner(graph, order);
    for (int step = 0; step < num_entries; ++step) {
      UvStencilPlan plan;
      planner.Build(step, &plan);
      ASSERT_LE(plan.num_stencils, UvStencilPlan::kMaxStencils);
      ASSERT_LE(plan.num_neighbours, UvStencilPlan::kMaxNeighbours);
      for (int i = 0; i < plan.num_stencils; ++i) {
        const UvStencilPlan::Stencil &s = plan.stencils[i];
        for (const int32_t e : {s.l, s.r}) {
          ASSERT_TRUE(e >= 0 && e < num_entries && order.rank[e] < step);
        }
        ASSERT_TRUE(s.b == UvCornerGraph::kNone ||
                    (s.b >= 0 && s.b < num_entries && order.rank[s.b] < step));
      }
      for (int i = 0; i < plan.num_neighbours; ++i) {
        const int32_t e = plan.neighbours[i];
        ASSERT_TRUE(e >= 0 && e < num_entries && order.rank[e] < step);
      }
    }
  }
}

}  // namespace
}  // namespace draco
