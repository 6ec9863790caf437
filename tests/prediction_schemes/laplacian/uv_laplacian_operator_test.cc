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
// (uv_laplacian_operator.h): its pattern, boundary, charts and anchors, and
// the known properties of its weights on generated planar meshes.
#include "prediction_schemes/laplacian/uv_laplacian_operator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "gtest/gtest.h"
#include "tests/prediction_schemes/laplacian/uv_laplacian_test_cases.h"

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

// --- Weights: known properties on generated meshes ---------------------------

constexpr double kPi = 3.14159265358979323846;

// A triangulation of a planar region, counter-clockwise, in plane
// coordinates (x, y).
struct PlanarMesh {
  std::string name;
  std::vector<std::array<double, 2>> xy;
  std::vector<std::array<int, 3>> faces;
};

// A (side + 1)^2 grid of unit cells, sheared by |shear| and scaled by
// |height| in y, each vertex moved by up to |jitter| in x and y; each cell
// split along its (0,0)-(1,1) diagonal, or at random along either one.
PlanarMesh GridMesh(const std::string &name, int side, double shear,
                    double height, double jitter, bool random_diagonals,
                    uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter, jitter);
  PlanarMesh m;
  m.name = name + " seed " + std::to_string(seed);
  for (int j = 0; j <= side; ++j) {
    for (int i = 0; i <= side; ++i) {
      const double x = i + offset(random), y = j + offset(random);
      m.xy.push_back({x + shear * y, height * y});
    }
  }
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      const int v00 = j * (side + 1) + i, v10 = v00 + 1;
      const int v01 = v00 + side + 1, v11 = v01 + 1;
      if (random_diagonals && random() % 2) {
        m.faces.push_back({v00, v10, v01});
        m.faces.push_back({v10, v11, v01});
      } else {
        m.faces.push_back({v00, v10, v11});
        m.faces.push_back({v00, v11, v01});
      }
    }
  }
  return m;
}

// The vertices of a ring around the origin by ascending angle, and those
// angles, in [0, 2 pi).
struct Ring {
  std::vector<int> vertices;
  std::vector<double> angles;
  size_t size() const { return vertices.size(); }
  int vertex(size_t i) const { return vertices[i % size()]; }
  // Angles continue past the last vertex: i = size() is the first again.
  double angle(size_t i) const {
    return angles[i % size()] + (i >= size() ? 2 * kPi : 0.0);
  }
};

// Appends ring |k|: 5k to 5k + 2 vertices at radius k +- 0.15, each within
// a quarter of a step of its evenly spaced angle.
Ring AddRing(int k, std::mt19937 *random, PlanarMesh *m) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int count = 5 * k + static_cast<int>((*random)() % 3);
  const double step = 2 * kPi / count;
  const double start = (0.25 + 0.5 * unit(*random)) * step;
  Ring ring;
  for (int i = 0; i < count; ++i) {
    const double angle = start + (i + 0.5 * (unit(*random) - 0.5)) * step;
    const double radius = k + 0.3 * (unit(*random) - 0.5);
    ring.vertices.push_back(static_cast<int>(m->xy.size()));
    ring.angles.push_back(angle);
    m->xy.push_back({radius * std::cos(angle), radius * std::sin(angle)});
  }
  return ring;
}

// Triangulates the band between two rings, walking both by angle.
void ZipRings(const Ring &inner, const Ring &outer, PlanarMesh *m) {
  size_t a = 0, b = 0;
  while (a < inner.size() || b < outer.size()) {
    const bool advance_outer =
        a == inner.size() ||
        (b < outer.size() && outer.angle(b + 1) <= inner.angle(a + 1));
    if (advance_outer) {
      m->faces.push_back(
          {inner.vertex(a), outer.vertex(b), outer.vertex(b + 1)});
      ++b;
    } else {
      m->faces.push_back(
          {inner.vertex(a), outer.vertex(b), inner.vertex(a + 1)});
      ++a;
    }
  }
}

// A disc of |rings| rings of irregular vertex counts around a centre:
// vertices of valence 4 to 8 or so.
PlanarMesh RingMesh(int rings, uint32_t seed) {
  std::mt19937 random(seed);
  PlanarMesh m;
  m.name = "rings seed " + std::to_string(seed);
  m.xy.push_back({0.0, 0.0});
  Ring inner = AddRing(1, &random, &m);
  for (size_t i = 0; i < inner.size(); ++i) {
    m.faces.push_back({0, inner.vertex(i), inner.vertex(i + 1)});
  }
  for (int k = 2; k <= rings; ++k) {
    Ring outer = AddRing(k, &random, &m);
    ZipRings(inner, outer, &m);
    inner = outer;
  }
  return m;
}

// Whether every face of |m| is counter-clockwise with an area of at least
// 1e-3: a valid triangulation for the tests below (the generators' jitter
// stays within what keeps it one).
bool IsValidTriangulation(const PlanarMesh &m) {
  for (const auto &f : m.faces) {
    const auto &p = m.xy[f[0]], &q = m.xy[f[1]], &r = m.xy[f[2]];
    const double doubled_area =
        (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    if (!(doubled_area > 2e-3)) {
      return false;
    }
  }
  return true;
}

// Regular, jittered and irregular-valence triangulations of planar
// regions with interior vertices, fixed seeds.
std::vector<PlanarMesh> PlanarMeshes() {
  std::vector<PlanarMesh> meshes = {GridMesh("grid", 8, 0, 1, 0, false, 0)};
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    meshes.push_back(GridMesh("jittered grid", 10, 0, 1, 0.3, false, seed));
    meshes.push_back(GridMesh("random diagonals", 10, 0, 1, 0.3, true, seed));
    meshes.push_back(RingMesh(6, seed));
  }
  return meshes;
}

// Sheared grids whose cells are split along their long diagonal: the two
// angles opposite it are obtuse (about 157 and 135 degrees).
std::vector<PlanarMesh> ObtuseMeshes() {
  std::vector<PlanarMesh> meshes = {
      GridMesh("obtuse grid", 8, 0.7, 0.3, 0, false, 0),
      GridMesh("obtuse grid", 8, 0.5, 0.5, 0, false, 0)};
  for (uint32_t seed = 1; seed <= 3; ++seed) {
    meshes.push_back(
        GridMesh("jittered obtuse grid", 10, 0.7, 0.3, 0.1, false, seed));
  }
  return meshes;
}

// |m| in 3D: its plane coordinates along two random orthonormal axes from
// a random origin, plus |bump| times a random height per vertex along
// their normal (0: the mesh stays planar).
UvLaplacianMesh Embed(const PlanarMesh &m, double bump, uint32_t seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector3d origin, e1, e2;
  for (Eigen::Vector3d *v : {&origin, &e1, &e2}) {
    *v = Eigen::Vector3d(normal(random), normal(random), normal(random));
  }
  e1.normalize();
  e2 = (e2 - e2.dot(e1) * e1).normalized();
  const Eigen::Vector3d e3 = e1.cross(e2);
  UvLaplacianMesh mesh;
  for (const auto &xy : m.xy) {
    const Eigen::Vector3d p =
        10 * origin + xy[0] * e1 + xy[1] * e2 + bump * normal(random) * e3;
    mesh.positions.push_back({p[0], p[1], p[2]});
  }
  mesh.faces = m.faces;
  return mesh;
}

// The largest |(L f)_i| over the interior rows i of |op| for
// f = a x + b y + c on the vertices of |m|, relative to max |f|.
double WorstInteriorResidual(const PlanarMesh &m, const UvLaplacianMesh &mesh,
                             const UvLaplacianOperator &op, double a, double b,
                             double c) {
  std::vector<bool> boundary;
  UvTextureGraph(mesh, &boundary);
  UvValues f = UvValues::Zero(mesh.num_vertices(), 2);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    f(v, 0) = a * m.xy[v][0] + b * m.xy[v][1] + c;
  }
  const UvValues residual = op.Apply(f);
  double worst = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (!boundary[v] && !op.empty_row(v)) {
      worst = std::max(worst, std::abs(residual(v, 0)));
    }
  }
  return worst / std::max(1e-300, f.cwiseAbs().maxCoeff());
}

int NumInteriorVertices(const UvLaplacianMesh &mesh) {
  std::vector<bool> boundary;
  UvTextureGraph(mesh, &boundary);
  return static_cast<int>(std::count(boundary.begin(), boundary.end(), false));
}

// Linear precision: for every interior vertex, the weighted mean of the
// neighbours' values of a linear function is its value at the vertex, for
// 20 random linear functions on every mesh, in a random plane of 3D.
void ExpectLinearPrecision(UvLaplacianKind kind,
                           const std::vector<PlanarMesh> &meshes) {
  std::mt19937 random(17);
  std::uniform_real_distribution<double> coefficient(-10.0, 10.0);
  for (const PlanarMesh &m : meshes) {
    SCOPED_TRACE(m.name);
    ASSERT_TRUE(IsValidTriangulation(m));
    const UvLaplacianMesh mesh = Embed(m, 0, random());
    ASSERT_GE(NumInteriorVertices(mesh), 20);
    UvLaplacianOperator op;
    op.Build(mesh, UvTextureGraph(mesh), kind);
    // Fallback rows have Tutte weights, which are not linearly precise.
    ASSERT_EQ(op.num_fallback_rows(), 0);
    for (int trial = 0; trial < 20; ++trial) {
      const double a = coefficient(random), b = coefficient(random),
                   c = coefficient(random);
      EXPECT_LT(WorstInteriorResidual(m, mesh, op, a, b, c), 1e-10)
          << a << " x + " << b << " y + " << c;
    }
  }
}

// The weights of row |v|, without the diagonal.
std::vector<double> RowWeights(const UvLaplacianOperator &op, int v) {
  std::vector<double> weights;
  for (int e = op.row_start(v) + 1; e < op.row_start(v + 1); ++e) {
    weights.push_back(op.value(e));
  }
  return weights;
}

TEST(UvLaplacianOperatorTest,
     CotangentWeightsReproduceLinearFunctionsOnPlanarMeshes) {
  ExpectLinearPrecision(UvLaplacianKind::kCotangent, PlanarMeshes());
}

// Also with negative weights: linear precision does not need them
// positive.
TEST(UvLaplacianOperatorTest,
     CotangentWeightsReproduceLinearFunctionsOnObtuseMeshes) {
  ExpectLinearPrecision(UvLaplacianKind::kCotangent, ObtuseMeshes());
}

TEST(UvLaplacianOperatorTest,
     MeanValueWeightsReproduceLinearFunctionsOnPlanarMeshes) {
  ExpectLinearPrecision(UvLaplacianKind::kMeanValue, PlanarMeshes());
  ExpectLinearPrecision(UvLaplacianKind::kMeanValue, ObtuseMeshes());
}

// Tutte weights are not linearly precise on irregular meshes: the property
// above is one the geometry-aware weights have, not every Laplacian.
TEST(UvLaplacianOperatorTest,
     TutteWeightsMissLinearFunctionsOnIrregularMeshes) {
  for (const PlanarMesh &m : PlanarMeshes()) {
    if (m.name == "grid seed 0") {
      continue;  // Regular: uniform weights are linearly precise there.
    }
    const UvLaplacianMesh mesh = Embed(m, 0, 1);
    UvLaplacianOperator op;
    op.Build(mesh, UvTextureGraph(mesh), UvLaplacianKind::kTutte);
    EXPECT_GT(WorstInteriorResidual(m, mesh, op, 1, 0, 0), 1e-3) << m.name;
  }
}

// On obtuse meshes cotangent weights go negative; mean-value weights stay
// positive there and on bumpy (non-planar) versions of every mesh.
TEST(UvLaplacianOperatorTest,
     MeanValueWeightsArePositiveWhereCotangentsAreNot) {
  for (const PlanarMesh &m : ObtuseMeshes()) {
    const UvLaplacianMesh mesh = Embed(m, 0, 2);
    UvLaplacianOperator cotangent;
    cotangent.Build(mesh, UvTextureGraph(mesh), UvLaplacianKind::kCotangent);
    double smallest = 0;
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      for (const double w : RowWeights(cotangent, v)) {
        smallest = std::min(smallest, w);
      }
    }
    EXPECT_LT(smallest, 0) << m.name;
  }
  std::vector<PlanarMesh> meshes = PlanarMeshes();
  const std::vector<PlanarMesh> obtuse = ObtuseMeshes();
  meshes.insert(meshes.end(), obtuse.begin(), obtuse.end());
  for (const PlanarMesh &m : meshes) {
    for (const double bump : {0.0, 0.5}) {
      const UvLaplacianMesh mesh = Embed(m, bump, 3);
      UvLaplacianOperator op;
      op.Build(mesh, UvTextureGraph(mesh), UvLaplacianKind::kMeanValue);
      EXPECT_EQ(op.num_fallback_rows(), 0) << m.name;
      for (int v = 0; v < mesh.num_vertices(); ++v) {
        for (const double w : RowWeights(op, v)) {
          EXPECT_GT(w, 0) << m.name << " bump " << bump << " vertex " << v;
        }
      }
    }
  }
}

TEST(UvLaplacianOperatorTest, TutteWeightsAreUniform) {
  std::vector<UvLaplacianMesh> meshes;
  for (const PlanarMesh &m : PlanarMeshes()) {
    meshes.push_back(Embed(m, 0.5, 4));
  }
  for (const UvTestCase &c : TestdataCases()) {
    meshes.push_back(c.mesh);
  }
  meshes.push_back(ManyChartsCase(20, 7).mesh);
  for (const UvLaplacianMesh &mesh : meshes) {
    UvLaplacianOperator op;
    op.Build(mesh, UvTextureGraph(mesh), UvLaplacianKind::kTutte);
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      const std::vector<double> weights = RowWeights(op, v);
      for (const double w : weights) {
        EXPECT_EQ(w, 1.0 / weights.size()) << "vertex " << v;
      }
    }
  }
}

// Rows are scaled to diagonal -1 and their weights sum to one, so that L
// vanishes on constants (one anchor per chart makes the system regular).
TEST(UvLaplacianOperatorTest,
     EveryRowHasDiagonalMinusOneAndVanishesOnConstants) {
  std::vector<UvLaplacianMesh> meshes;
  for (const PlanarMesh &m : ObtuseMeshes()) {
    meshes.push_back(Embed(m, 0.5, 5));
  }
  for (const UvTestCase &c : TestdataCases()) {
    meshes.push_back(c.mesh);
  }
  meshes.push_back(ManyChartsCase(20, 7).mesh);
  for (const UvLaplacianMesh &mesh : meshes) {
    for (const UvLaplacianKind kind : kKinds) {
      UvLaplacianOperator op;
      op.Build(mesh, UvTextureGraph(mesh), kind);
      for (int v = 0; v < mesh.num_vertices(); ++v) {
        if (op.empty_row(v)) {
          continue;
        }
        EXPECT_EQ(op.column(op.row_start(v)), v);
        EXPECT_EQ(op.value(op.row_start(v)), -1.0);
        const std::vector<double> weights = RowWeights(op, v);
        EXPECT_NEAR(std::accumulate(weights.begin(), weights.end(), 0.0), 1.0,
                    1e-12)
            << "kind " << static_cast<int>(kind) << " vertex " << v;
      }
    }
  }
}

}  // namespace
}  // namespace draco
