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
// The Laplacian operator of [Váša & Brunnett 2014] section 5
// (uv_laplacian_operator.h): its pattern, boundary, charts and anchors.
#include "draco_ext/laplacian/uv_laplacian_operator.h"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "gtest/gtest.h"
#include "tests/draco_ext/laplacian/uv_laplacian_test_cases.h"

namespace draco {
namespace {

TEST(UvChartsTest, OnlyChartsOfTheMinimumSizeGetASecondAnchor) {
  std::vector<UvTestCase> cases = TestdataCases();
  // Beside single triangles, strips of 16 vertices and of 14.
  cases.push_back(ManyChartsCase(4, 7));
  cases.push_back(ManyChartsCase(4, 6));
  for (const UvTestCase &c : cases) {
    for (const UvLaplacianKind kind : kKinds) {
      const int min_size = UvMinChartSizeForSecondAnchor(kind);
      const UvCharts charts = ComputeUvCharts(c.mesh, min_size);
      std::vector<int> size(charts.num_charts, 0);
      std::vector<int> num_anchors(charts.num_charts, 0);
      for (int v = 0; v < c.mesh.num_vertices(); ++v) {
        ++size[charts.chart_of_vertex[v]];
      }
      for (const int a : charts.anchors) {
        ++num_anchors[charts.chart_of_vertex[a]];
      }
      for (int chart = 0; chart < charts.num_charts; ++chart) {
        EXPECT_EQ(num_anchors[chart], size[chart] >= min_size ? 2 : 1)
            << c.name << " chart " << chart << " of " << size[chart];
      }
    }
  }
}

TEST(UvLaplacianOperatorTest, TextureGraphIsThePatternWithoutTheDiagonal) {
  std::vector<UvTestCase> cases = TestdataCases();
  cases.push_back(ManyChartsCase(4, 7));
  for (const UvTestCase &c : cases) {
    const MatrixGraph graph = UvTextureGraph(c.mesh);
    ASSERT_EQ(graph.size(), c.mesh.num_vertices()) << c.name;
    for (const UvLaplacianKind kind : kKinds) {
      UvLaplacianOperator op;
      op.Build(c.mesh, graph, kind);
      for (int v = 0; v < c.mesh.num_vertices(); ++v) {
        std::vector<int> expected(graph.neighbour.begin() + graph.start[v],
                                  graph.neighbour.begin() + graph.start[v + 1]);
        if (!expected.empty()) {
          expected.insert(expected.begin(), v);
        }
        std::vector<int> row;
        for (int e = op.row_start(v); e < op.row_start(v + 1); ++e) {
          row.push_back(op.column(e));
        }
        EXPECT_EQ(row, expected) << c.name << " vertex " << v;
      }
    }
  }
}

// Per vertex: whether an edge of |graph| at it has other than two faces
// with distinct corners.
std::vector<bool> BruteForceBoundary(const UvLaplacianMesh &mesh,
                                     const MatrixGraph &graph) {
  std::map<std::pair<int, int>, int> faces_of_edge;
  for (const auto &f : mesh.faces) {
    if (f[0] != f[1] && f[1] != f[2] && f[2] != f[0]) {
      for (int k = 0; k < 3; ++k) {
        ++faces_of_edge[std::minmax(f[k], f[(k + 1) % 3])];
      }
    }
  }
  std::vector<bool> boundary(mesh.num_vertices(), false);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    for (int e = graph.start[v]; e < graph.start[v + 1]; ++e) {
      const auto it = faces_of_edge.find(std::minmax(v, graph.neighbour[e]));
      boundary[v] = boundary[v] || it == faces_of_edge.end() || it->second != 2;
    }
  }
  return boundary;
}

TEST(UvLaplacianOperatorTest, BoundaryVerticesHaveAnEdgeOfOtherThanTwoFaces) {
  std::vector<UvTestCase> cases = TestdataCases();
  cases.push_back(ManyChartsCase(4, 7));
  // Faces with repeated corners (no faces of the texture connectivity) on
  // an edge between interior vertices, and a third face on another.
  UvTestCase odd = TestdataCases().back();
  const std::vector<bool> before =
      BruteForceBoundary(odd.mesh, UvTextureGraph(odd.mesh));
  std::vector<std::array<int, 3>> interior_faces;
  for (const auto &f : odd.mesh.faces) {
    if (!before[f[0]] && !before[f[1]] && !before[f[2]]) {
      interior_faces.push_back(f);
    }
  }
  ASSERT_GE(interior_faces.size(), 2u);
  const auto &f = interior_faces.front();
  odd.mesh.faces.push_back({f[0], f[0], f[1]});
  odd.mesh.faces.push_back({f[2], f[2], f[2]});
  const auto &g = interior_faces.back();
  odd.mesh.faces.push_back({g[0], g[1], f[2]});
  odd.name += " with odd faces";
  cases.push_back(odd);
  for (const UvTestCase &c : cases) {
    std::vector<bool> boundary;
    const MatrixGraph graph = UvTextureGraph(c.mesh, &boundary);
    const std::vector<bool> expected = BruteForceBoundary(c.mesh, graph);
    ASSERT_EQ(boundary.size(), expected.size()) << c.name;
    for (int v = 0; v < c.mesh.num_vertices(); ++v) {
      EXPECT_EQ(boundary[v], expected[v]) << c.name << " vertex " << v;
    }
  }
}

}  // namespace
}  // namespace draco
