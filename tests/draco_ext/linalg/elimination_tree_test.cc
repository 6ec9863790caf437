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
#include "draco_ext/linalg/elimination_tree.h"

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "gtest/gtest.h"

namespace draco {
namespace {

MatrixGraph FromEdges(int n, const std::set<std::pair<int, int>> &edges) {
  std::vector<std::vector<int>> adjacency(n);
  for (const auto &[u, v] : edges) {
    adjacency[u].push_back(v);
    adjacency[v].push_back(u);
  }
  MatrixGraph graph;
  graph.start.push_back(0);
  for (const std::vector<int> &neighbours : adjacency) {
    graph.neighbour.insert(graph.neighbour.end(), neighbours.begin(),
                           neighbours.end());
    graph.start.push_back(static_cast<int>(graph.neighbour.size()));
  }
  return graph;
}

// Triangulated grids (the one-ring graphs of meshes), two grids side by
// side (two charts), and random sparse graphs with isolated points.
std::vector<MatrixGraph> TestGraphs() {
  std::vector<MatrixGraph> graphs;
  for (const int side : {1, 2, 5, 9, 14}) {
    for (const int copies : {1, 2}) {
      std::set<std::pair<int, int>> edges;
      const int per_copy = side * side;
      for (int c = 0; c < copies; ++c) {
        for (int y = 0; y < side; ++y) {
          for (int x = 0; x < side; ++x) {
            const int u = c * per_copy + y * side + x;
            if (x + 1 < side) edges.insert({u, u + 1});
            if (y + 1 < side) edges.insert({u, u + side});
            if (x + 1 < side && y + 1 < side) edges.insert({u, u + side + 1});
          }
        }
      }
      graphs.push_back(FromEdges(copies * per_copy, edges));
    }
  }
  std::mt19937 random(7);
  for (const int n : {30, 120, 250}) {
    std::set<std::pair<int, int>> edges;
    for (int i = 0; i < 2 * n; ++i) {
      const int u = random() % n, v = random() % n;
      if (u != v && u % 11 != 0 && v % 11 != 0) {
        edges.insert({std::min(u, v), std::max(u, v)});
      }
    }
    graphs.push_back(FromEdges(n, edges));
  }
  return graphs;
}

// Entries of the Cholesky factor of A^T A (A = graph + diagonal) with the
// columns in |order|, by dense symbolic elimination.
int64_t DenseFactorEntries(const MatrixGraph &graph,
                           const std::vector<int> &order) {
  const int n = graph.size();
  std::vector<int> column_of(n);
  for (int k = 0; k < n; ++k) column_of[order[k]] = k;
  std::vector<std::vector<char>> nonzero(n, std::vector<char>(n, 0));
  for (int r = 0; r < n; ++r) {  // Row r of A is a clique of A^T A.
    std::vector<int> columns{column_of[r]};
    for (int e = graph.start[r]; e < graph.start[r + 1]; ++e) {
      columns.push_back(column_of[graph.neighbour[e]]);
    }
    for (const int i : columns) {
      for (const int j : columns) nonzero[i][j] = 1;
    }
  }
  int64_t entries = 0;
  for (int k = 0; k < n; ++k) {
    for (int i = k; i < n; ++i) {
      if (!nonzero[i][k]) continue;
      ++entries;
      for (int j = k + 1; j <= i; ++j) {
        if (nonzero[j][k]) nonzero[i][j] = nonzero[j][i] = 1;
      }
    }
  }
  return entries;
}

TEST(EliminationTreeTest, ColumnMinimumDegreeOrderIsAPermutation) {
  for (const MatrixGraph &graph : TestGraphs()) {
    std::vector<int> order = ColumnMinimumDegreeOrder(graph);
    ASSERT_EQ(order.size(), static_cast<size_t>(graph.size()));
    std::sort(order.begin(), order.end());
    for (int k = 0; k < graph.size(); ++k) {
      EXPECT_EQ(order[k], k);
    }
  }
}

TEST(EliminationTreeTest, SupernodesCountTheFactorsEntriesExactly) {
  for (const MatrixGraph &graph : TestGraphs()) {
    const std::vector<int> order = ColumnMinimumDegreeOrder(graph);
    Supernodes supernodes;
    ASSERT_TRUE(ComputeSupernodes(graph, order, int64_t{1} << 30, &supernodes));
    // A postorder of the same elimination has the same factor size.
    EXPECT_EQ(supernodes.exact_entries, DenseFactorEntries(graph, order));
    EXPECT_EQ(supernodes.exact_entries,
              DenseFactorEntries(graph, supernodes.order));
  }
}

TEST(EliminationTreeTest, SupernodesPartitionTheColumnsChildrenFirst) {
  for (const MatrixGraph &graph : TestGraphs()) {
    Supernodes s;
    ASSERT_TRUE(ComputeSupernodes(graph, ColumnMinimumDegreeOrder(graph),
                                  int64_t{1} << 30, &s));
    std::vector<int> sorted = s.order;
    std::sort(sorted.begin(), sorted.end());
    for (int k = 0; k < graph.size(); ++k) {
      ASSERT_EQ(sorted[k], k);
    }
    const int num = static_cast<int>(s.parent.size());
    ASSERT_EQ(s.first_column.size(), static_cast<size_t>(num) + 1);
    EXPECT_EQ(s.first_column.front(), 0);
    EXPECT_EQ(s.first_column.back(), graph.size());
    for (int i = 0; i < num; ++i) {
      EXPECT_LT(s.first_column[i], s.first_column[i + 1]);
      EXPECT_TRUE(s.parent[i] == -1 || s.parent[i] > i);
    }
  }
}

TEST(EliminationTreeTest, RejectsFactorsAboveTheCap) {
  for (const MatrixGraph &graph : TestGraphs()) {
    const std::vector<int> order = ColumnMinimumDegreeOrder(graph);
    const int64_t entries = DenseFactorEntries(graph, order);
    Supernodes supernodes;
    EXPECT_TRUE(ComputeSupernodes(graph, order, entries, &supernodes));
    EXPECT_FALSE(ComputeSupernodes(graph, order, entries - 1, &supernodes));
  }
}

}  // namespace
}  // namespace draco
