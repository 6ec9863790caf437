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
// The Laplacian texture coordinate coder of [Váša & Brunnett 2014] section 5
// on its own (uv_laplacian_coder.h) and as Draco's
// MESH_PREDICTION_TEX_COORDS_LAPLACIAN (-uv_pred laplacian_*).
#include "draco_ext/laplacian/uv_laplacian_coder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <random>

#include "draco_ext/common/uv_bitstream_guard.h"
#include "draco_ext/eval/uv_eval.h"
#include "draco_ext/options/uv_laplacian_options.h"
#include "draco_ext/laplacian/uv_laplacian_system.h"
#include "draco_ext/options/uv_prediction_options.h"
#include "gtest/gtest.h"
#include "draco_ext/laplacian/mesh_prediction_scheme_tex_coords_laplacian_shared.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

constexpr UvLaplacianKind kKinds[] = {UvLaplacianKind::kTutte,
                                      UvLaplacianKind::kCotangent,
                                      UvLaplacianKind::kMeanValue};
constexpr const char *kSchemes[] = {"laplacian_tutte", "laplacian_cotan",
                                    "laplacian_mv"};
constexpr int kFrameBits = 20;

struct UvTestCase {
  std::string name;
  UvLaplacianMesh mesh;
  UvValues uv;  // Frame units.
};

// One texture vertex per value of the first TEX_COORD attribute, at the
// position of a point that uses it; UVs scaled to the frame.
UvTestCase FromDracoMesh(const std::string &name, const Mesh &mesh) {
  const PointAttribute &pos =
      *mesh.GetNamedAttribute(GeometryAttribute::POSITION);
  const PointAttribute &tex =
      *mesh.GetNamedAttribute(GeometryAttribute::TEX_COORD);
  UvTestCase c;
  c.name = name;
  const int n = static_cast<int>(tex.size());
  c.mesh.positions.resize(n);
  c.uv.resize(n, 2);
  float lo = std::numeric_limits<float>::max(), hi = -lo;
  for (PointIndex p(0); p < mesh.num_points(); ++p) {
    const int v = tex.mapped_index(p).value();
    std::array<float, 3> xyz;
    std::array<float, 2> uv;
    pos.ConvertValue(pos.mapped_index(p), 3, xyz.data());
    tex.ConvertValue(tex.mapped_index(p), 2, uv.data());
    for (int k = 0; k < 3; ++k) {
      c.mesh.positions[v][k] = xyz[k];
    }
    for (int k = 0; k < 2; ++k) {
      c.uv(v, k) = uv[k];
      lo = std::min(lo, uv[k]);
      hi = std::max(hi, uv[k]);
    }
  }
  const double scale = ((1 << kFrameBits) - 1) / std::max(1e-9f, hi - lo);
  c.uv = ((c.uv.array() - lo) * scale).matrix();
  for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
    std::array<int, 3> face;
    for (int k = 0; k < 3; ++k) {
      face[k] = tex.mapped_index(mesh.face(f)[k]).value();
    }
    c.mesh.faces.push_back(face);
  }
  return c;
}

std::vector<UvTestCase> TestdataCases() {
  std::vector<UvTestCase> cases;
  for (const std::string &name :
       {"cube_att.obj", "Box/glTF/Box.gltf"}) {
    auto mesh = ReadTestMesh(DracoTestdataPath(name));
    if (mesh.ok() &&
        mesh.value()->GetNamedAttribute(GeometryAttribute::TEX_COORD)) {
      cases.push_back(FromDracoMesh(name, *mesh.value()));
    }
  }
  for (const std::string &name : {"bumpy_cube_sphere.obj", "torus_uv.obj"}) {
    auto mesh = ReadTestMesh(UvTestdataPath(name));
    if (mesh.ok()) {
      cases.push_back(FromDracoMesh(name, *mesh.value()));
    }
  }
  return cases;
}

// |triangles| disjoint triangles (single-triangle, boundary-only charts),
// a strip of |strip_quads| quads whose vertices are all on its boundary,
// and one vertex no face uses, with random positions and UVs.
UvTestCase ManyChartsCase(int triangles, int strip_quads) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  UvTestCase c;
  c.name = "many charts";
  auto add_vertex = [&](double x, double y, double z) {
    c.mesh.positions.push_back({x, y, z});
    return c.mesh.num_vertices() - 1;
  };
  for (int t = 0; t < triangles; ++t) {
    const int a = add_vertex(unit(random), unit(random), unit(random));
    const int b = add_vertex(unit(random), unit(random), unit(random));
    const int d = add_vertex(unit(random), unit(random), unit(random));
    c.mesh.faces.push_back({a, b, d});
  }
  const int strip = c.mesh.num_vertices();
  for (int i = 0; i <= strip_quads; ++i) {
    add_vertex(i, 0, 0.1 * i * i);
    add_vertex(i, 1, 0.1 * i * i);
  }
  for (int i = 0; i < strip_quads; ++i) {
    const int v = strip + 2 * i;
    c.mesh.faces.push_back({v, v + 2, v + 1});
    c.mesh.faces.push_back({v + 1, v + 2, v + 3});
  }
  add_vertex(5, 5, 5);
  c.uv.resize(c.mesh.num_vertices(), 2);
  for (int v = 0; v < c.mesh.num_vertices(); ++v) {
    c.uv(v, 0) = unit(random) * ((1 << kFrameBits) - 1);
    c.uv(v, 1) = unit(random) * ((1 << kFrameBits) - 1);
  }
  return c;
}

UvLaplacianEncoderOptions Options(UvLaplacianKind kind, int step_bits,
                                  int anchors = 50) {
  UvLaplacianEncoderOptions options;
  options.kind = kind;
  options.step_bits = step_bits;
  options.frame_bits = kFrameBits;
  options.extra_anchors = anchors;
  return options;
}

double Step(int step_bits) {
  return ((1 << kFrameBits) - 1.0) / ((1 << step_bits) - 1.0);
}

double Rmse(const UvValues &a, const UvValues &b) {
  return std::sqrt((a - b).squaredNorm() / std::max<Eigen::Index>(1, a.rows()));
}

// Encodes and decodes |c|; the decoded values, or an empty matrix on
// failure. |stream| receives the encoded data.
UvValues RoundTrip(const UvTestCase &c,
                   const UvLaplacianEncoderOptions &options,
                   std::vector<char> *stream = nullptr) {
  EncoderBuffer buffer;
  if (!EncodeUvLaplacian(c.mesh, c.uv, options, &buffer)) {
    return UvValues();
  }
  if (stream != nullptr) {
    stream->assign(buffer.data(), buffer.data() + buffer.size());
  }
  DecoderBuffer in;
  in.Init(buffer.data(), buffer.size(), kDracoMeshBitstreamVersion);
  UvValues decoded;
  int frame_bits;
  if (!DecodeUvLaplacian(c.mesh, &in, &decoded, &frame_bits) ||
      frame_bits != kFrameBits) {
    return UvValues();
  }
  return decoded;
}

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

// Analyze() and Factorize() of the system of |op| with |anchors|.
bool SetUpSystem(const UvLaplacianMesh &mesh, const UvLaplacianOperator &op,
                 const std::vector<int> &anchors, UvLaplacianSystem *system) {
  return system->Analyze(UvTextureGraph(mesh), int64_t{1} << 26, [&] {
    return &op;
  }) && system->Factorize(anchors);
}

TEST(UvLaplacianSystemTest, FailsWhenTheOperatorCannotBeBuilt) {
  const UvTestCase c = TestdataCases().back();
  UvLaplacianSystem system;
  EXPECT_FALSE(system.Analyze(UvTextureGraph(c.mesh), int64_t{1} << 26,
                              [] { return nullptr; }));
}

TEST(UvLaplacianSystemTest, SolvesExactlyWithoutQuantization) {
  for (const UvTestCase &c : TestdataCases()) {
    for (const UvLaplacianKind kind : kKinds) {
      UvLaplacianOperator op;
      op.Build(c.mesh, UvTextureGraph(c.mesh), kind);
      const UvCharts charts =
          ComputeUvCharts(c.mesh, UvMinChartSizeForSecondAnchor(kind));
      UvLaplacianSystem system;
      ASSERT_TRUE(SetUpSystem(c.mesh, op, charts.anchors, &system)) << c.name;
      UvValues anchor_values(charts.anchors.size(), 2);
      for (size_t i = 0; i < charts.anchors.size(); ++i) {
        anchor_values.row(i) = c.uv.row(charts.anchors[i]);
      }
      const UvValues x = system.Solve(op.Apply(c.uv), anchor_values);
      EXPECT_LT((x - c.uv).cwiseAbs().maxCoeff(), 1e-6 * (1 << kFrameBits))
          << c.name << " kind " << static_cast<int>(kind);
    }
  }
}

TEST(UvLaplacianSystemTest, RankOneAnchorsMatchAFreshFactorization) {
  const UvTestCase c = TestdataCases().back();
  UvLaplacianOperator op;
  op.Build(c.mesh, UvTextureGraph(c.mesh), UvLaplacianKind::kCotangent);
  std::vector<int> anchors =
      ComputeUvCharts(
          c.mesh, UvMinChartSizeForSecondAnchor(UvLaplacianKind::kCotangent))
          .anchors;
  UvLaplacianSystem updated;
  ASSERT_TRUE(SetUpSystem(c.mesh, op, anchors, &updated));
  for (int v = 3; v < c.mesh.num_vertices(); v += c.mesh.num_vertices() / 7) {
    if (std::find(anchors.begin(), anchors.end(), v) == anchors.end()) {
      updated.AddAnchor(v);
      anchors.push_back(v);
    }
  }
  UvLaplacianSystem fresh;
  ASSERT_TRUE(SetUpSystem(c.mesh, op, anchors, &fresh));
  UvValues residuals = op.Apply(c.uv);
  residuals.array() += 100.0;  // Inconsistent: anchors matter.
  UvValues anchor_values(anchors.size(), 2);
  for (size_t i = 0; i < anchors.size(); ++i) {
    anchor_values.row(i) = c.uv.row(anchors[i]);
  }
  const UvValues a = updated.Solve(residuals, anchor_values);
  const UvValues b = fresh.Solve(residuals, anchor_values);
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-6 * (1 << kFrameBits));
}

TEST(UvLaplacianCoderTest, ErrorFallsAsTheStepShrinks) {
  for (const UvTestCase &c : TestdataCases()) {
    if (c.mesh.num_vertices() < 100) {
      continue;  // Too few residuals for a trend (cube_att: 4 UVs).
    }
    for (const UvLaplacianKind kind : kKinds) {
      double previous = std::numeric_limits<double>::max();
      for (const int step_bits : {6, 10, 14}) {
        const UvValues decoded = RoundTrip(c, Options(kind, step_bits));
        ASSERT_EQ(decoded.rows(), c.uv.rows()) << c.name;
        const double rmse = Rmse(decoded, c.uv);
        EXPECT_LT(rmse, previous) << c.name << " step bits " << step_bits;
        previous = rmse;
      }
    }
  }
}

TEST(UvLaplacianCoderTest, DecoderReproducesTheEncodersReconstruction) {
  std::vector<UvTestCase> cases = TestdataCases();
  cases.push_back(ManyChartsCase(30, 20));
  for (const UvTestCase &c : cases) {
    for (const UvLaplacianKind kind : kKinds) {
      EncoderBuffer buffer;
      UvValues expected;
      ASSERT_TRUE(EncodeUvLaplacian(c.mesh, c.uv, Options(kind, 10), &buffer,
                                    &expected));
      const UvValues decoded = RoundTrip(c, Options(kind, 10));
      ASSERT_EQ(decoded.rows(), expected.rows());
      EXPECT_LT((decoded - expected).cwiseAbs().maxCoeff(), 1e-6)
          << c.name << " kind " << static_cast<int>(kind);
    }
  }
}

TEST(UvLaplacianCoderTest, CodesManySmallAndBoundaryOnlyCharts) {
  const UvTestCase c = ManyChartsCase(300, 20);
  for (const UvLaplacianKind kind : kKinds) {
    for (const int anchors : {0, 50}) {
      const UvValues decoded = RoundTrip(c, Options(kind, 12, anchors));
      ASSERT_EQ(decoded.rows(), c.uv.rows());
      // Errors stay within a small multiple of the step: the charts are
      // tiny, so the inverse Laplacian cannot accumulate much quantisation
      // error.
      EXPECT_LT(Rmse(decoded, c.uv), 2 * Step(12)) << static_cast<int>(kind);
      EXPECT_LT((decoded - c.uv).cwiseAbs().maxCoeff(), 16 * Step(12))
          << static_cast<int>(kind);
    }
  }
}

TEST(UvLaplacianCoderTest, DegenerateGeometryStillCodes) {
  // All 3D positions coincide: no cotangent or mean-value weight is usable,
  // and every chart has a single anchor.
  UvTestCase c = TestdataCases().back();
  for (auto &p : c.mesh.positions) {
    p = {1.0, 2.0, 3.0};
  }
  for (const UvLaplacianKind kind : kKinds) {
    const UvValues decoded = RoundTrip(c, Options(kind, 12));
    ASSERT_EQ(decoded.rows(), c.uv.rows()) << static_cast<int>(kind);
    EXPECT_LT(Rmse(decoded, c.uv), 0.01 * (1 << kFrameBits));
  }
}

TEST(UvLaplacianCoderTest, GreedyAnchorsLowerTheError) {
  // Paper section 5: extra anchors where the reconstruction error is
  // largest. (Greedy against random anchors, fig. 9, is measured on the
  // corpus in benchmarks/laplacian.md: greedy wins on most meshes, not all.)
  for (const UvTestCase &c : TestdataCases()) {
    if (c.mesh.num_vertices() < 200) {
      continue;
    }
    for (const UvLaplacianKind kind : kKinds) {
      const UvValues none = RoundTrip(c, Options(kind, 8, 0));
      const UvValues greedy = RoundTrip(c, Options(kind, 8, 50));
      ASSERT_EQ(none.rows(), c.uv.rows()) << c.name;
      ASSERT_EQ(greedy.rows(), c.uv.rows()) << c.name;
      EXPECT_LT(Rmse(greedy, c.uv), Rmse(none, c.uv))
          << c.name << " kind " << static_cast<int>(kind);
    }
  }
}

TEST(UvLaplacianCoderTest, RandomAnchorsAreDeterministic) {
  const UvTestCase c = TestdataCases().back();
  UvLaplacianEncoderOptions options = Options(UvLaplacianKind::kTutte, 8);
  options.selection = UvAnchorSelection::kRandom;
  std::vector<char> a, b;
  ASSERT_EQ(RoundTrip(c, options, &a).rows(), c.uv.rows());
  ASSERT_EQ(RoundTrip(c, options, &b).rows(), c.uv.rows());
  EXPECT_EQ(a, b);
}

TEST(UvLaplacianCoderTest, RejectsEveryTruncation) {
  const UvTestCase c = TestdataCases().back();
  std::vector<char> stream;
  ASSERT_GT(RoundTrip(c, Options(UvLaplacianKind::kCotangent, 10), &stream)
                .rows(),
            0);
  for (size_t size = 0; size < stream.size(); ++size) {
    DecoderBuffer in;
    in.Init(stream.data(), size, kDracoMeshBitstreamVersion);
    UvValues decoded;
    int frame_bits;
    EXPECT_FALSE(DecodeUvLaplacian(c.mesh, &in, &decoded, &frame_bits))
        << size << " of " << stream.size() << " bytes";
  }
}

TEST(UvLaplacianCoderTest, CorruptStreamsFailOrDecodeFiniteValues) {
  const UvTestCase c = TestdataCases().back();
  std::vector<char> stream;
  ASSERT_GT(RoundTrip(c, Options(UvLaplacianKind::kTutte, 10), &stream).rows(),
            0);
  std::mt19937 random(3);
  int rejected = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<char> corrupt = stream;
    for (int flips = 0; flips < 3; ++flips) {
      corrupt[random() % corrupt.size()] ^= static_cast<char>(1 + random() % 255);
    }
    DecoderBuffer in;
    in.Init(corrupt.data(), corrupt.size(), kDracoMeshBitstreamVersion);
    UvValues decoded;
    int frame_bits;
    if (DecodeUvLaplacian(c.mesh, &in, &decoded, &frame_bits)) {
      EXPECT_TRUE(decoded.allFinite());
    } else {
      ++rejected;
    }
  }
  EXPECT_GT(rejected, 0);
}

// --- Through Draco (-uv_pred laplacian_*) -----------------------------------

std::vector<std::string> PipelineMeshes() {
  std::vector<std::string> paths = {UvTestdataPath("torus_uv.obj"),
                                    UvTestdataPath("bumpy_cube_sphere.obj")};
  for (const std::string &path : CorpusMeshPaths()) {
    // The small corpus meshes keep the test quick.
    if (path.find("spot") != std::string::npos ||
        path.find("suzanne") != std::string::npos ||
        path.find("milktruck") != std::string::npos) {
      paths.push_back(path);
    }
  }
  return paths;
}

double UvRange(const Mesh &mesh) {
  const PointAttribute &tex =
      *mesh.GetNamedAttribute(GeometryAttribute::TEX_COORD);
  float lo = std::numeric_limits<float>::max(), hi = -lo;
  for (AttributeValueIndex i(0); i < tex.size(); ++i) {
    std::array<float, 2> uv;
    tex.GetValue(i, uv.data());
    lo = std::min({lo, uv[0], uv[1]});
    hi = std::max({hi, uv[0], uv[1]});
  }
  return hi - lo;
}

TEST(UvLaplacianSchemeTest, RmseFallsWithQtForEveryLaplacian) {
  for (const std::string &path : PipelineMeshes()) {
    auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    ASSERT_NE(mesh.value()->GetNamedAttribute(GeometryAttribute::TEX_COORD),
              nullptr)
        << path;
    for (const char *scheme : kSchemes) {
      double previous = std::numeric_limits<double>::max();
      for (const int qt : {7, 10, 13}) {
        const auto bytes = EncodeMeshToBytes(*mesh.value(), {14, qt, 10, scheme, ""});
        ASSERT_TRUE(bytes.ok()) << path << " " << scheme << ": "
                                << bytes.status().error_msg_string();
        const auto decoded = DecodeDracoMesh(bytes.value());
        ASSERT_TRUE(decoded.ok()) << path << " " << scheme;
        const auto rmse = UvRmse(*mesh.value(), *decoded.value(), 14);
        ASSERT_TRUE(rmse.ok()) << path;
        EXPECT_LT(rmse.value(), previous) << path << " " << scheme << " qt " << qt;
        // Within a few -qt steps of the UV range.
        EXPECT_LT(rmse.value(), 8 * UvRange(*mesh.value()) / ((1 << qt) - 1))
            << path << " " << scheme << " qt " << qt;
        previous = rmse.value();
      }
    }
  }
}

TEST(UvLaplacianSchemeTest, DecodingIsDeterministic) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  const auto bytes =
      EncodeMeshToBytes(*mesh.value(), {14, 10, 10, "laplacian_mv", "", ""});
  ASSERT_TRUE(bytes.ok());
  const auto a = DecodeDracoMesh(bytes.value());
  const auto b = DecodeDracoMesh(bytes.value());
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(CornerValues(*a.value(), GeometryAttribute::TEX_COORD),
            CornerValues(*b.value(), GeometryAttribute::TEX_COORD));
  const auto again =
      EncodeMeshToBytes(*mesh.value(), {14, 10, 10, "laplacian_mv", "", ""});
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(bytes.value(), again.value());
}

TEST(UvLaplacianSchemeTest, AnchorOptionChangesTheStream) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  std::map<std::string, size_t> sizes;
  for (const std::string anchors : {"", "50", "0", "random:50"}) {
    const auto bytes = EncodeMeshToBytes(
        *mesh.value(), {14, 10, 10, "laplacian_cotan", "", anchors});
    ASSERT_TRUE(bytes.ok()) << anchors;
    ASSERT_TRUE(DecodeDracoMesh(bytes.value()).ok()) << anchors;
    sizes[anchors] = bytes.value().size();
  }
  EXPECT_EQ(sizes[""], sizes["50"]);  // 50 greedy anchors is the default.
  EXPECT_LT(sizes["0"], sizes["50"]);
}

// P% means ceil(P / 100 * the attribute's texture coordinates) anchors.
TEST(UvLaplacianSchemeTest, PercentAnchorsScaleWithTheMesh) {
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

TEST(UvLaplacianSchemeTest, RejectsBadOptions) {
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

TEST(UvLaplacianSchemeTest, AutoNeverPicksALossyScheme) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  std::string summary;
  EncoderBuffer buffer;
  ASSERT_TRUE(EncodeMeshWithSettings(*mesh.value(), {14, 6, 10, "auto", "", ""},
                                     &buffer, &summary)
                  .ok());
  EXPECT_EQ(summary.find("laplacian"), std::string::npos) << summary;
}

TEST(UvLaplacianSchemeTest, TruncatedFilesFailToDecode) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  const auto bytes =
      EncodeMeshToBytes(*mesh.value(), {14, 10, 10, "laplacian_tutte", "", ""});
  ASSERT_TRUE(bytes.ok());
  for (size_t size = 0; size < bytes.value().size(); size += 7) {
    const std::vector<char> truncated(bytes.value().begin(),
                                      bytes.value().begin() + size);
    EXPECT_FALSE(DecodeDracoMesh(truncated).ok()) << size;
  }
}

TEST(UvLaplacianSchemeTest, RejectsOtherFormatVersions) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  const auto bytes =
      EncodeMeshToBytes(*mesh.value(), {14, 10, 10, "laplacian_mv", "", ""});
  ASSERT_TRUE(bytes.ok());
  ASSERT_TRUE(DecodeDracoMesh(bytes.value()).ok());
  // The scheme's data start with the 8-byte guard, then the version.
  char guard[8];
  const int32_t words[2] = {kUvGuardFirst, kUvGuardSecond};
  std::memcpy(guard, words, sizeof(guard));
  const auto it = std::search(bytes.value().begin(), bytes.value().end(), guard,
                              guard + sizeof(guard));
  ASSERT_NE(it, bytes.value().end());
  const size_t version = (it - bytes.value().begin()) + sizeof(guard);
  ASSERT_EQ(bytes.value()[version], kTexCoordsLaplacianFormatVersion);
  for (int value = 0; value < 256; ++value) {
    if (value == kTexCoordsLaplacianFormatVersion) {
      continue;
    }
    std::vector<char> other = bytes.value();
    other[version] = static_cast<char>(value);
    EXPECT_FALSE(DecodeDracoMesh(other).ok()) << value;
  }
}

TEST(UvLaplacianSchemeTest, CorruptFilesFailOrDecodeFiniteUvs) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  const auto bytes =
      EncodeMeshToBytes(*mesh.value(), {14, 10, 10, "laplacian_cotan", "", ""});
  ASSERT_TRUE(bytes.ok());
  std::mt19937 random(11);
  int rejected = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<char> corrupt = bytes.value();
    corrupt[random() % corrupt.size()] ^= static_cast<char>(1 + random() % 255);
    const auto decoded = DecodeDracoMesh(corrupt);
    if (!decoded.ok()) {
      ++rejected;
      continue;
    }
    for (const float value :
         CornerValues(*decoded.value(), GeometryAttribute::TEX_COORD)) {
      ASSERT_TRUE(std::isfinite(value));
    }
  }
  EXPECT_GT(rejected, 0);
}

// The lossy golden files pin the encoder's bytes (scripts/make-golden.sh
// --check-encode) and seed scripts/fuzz.sh's decode:laplacian target; a
// format change must renew them, and they must decode.
TEST(UvLaplacianSchemeTest, LossyGoldenFilesDecode) {
  namespace fs = std::filesystem;
  const fs::path folder = UvTestdataPath("golden/lossy");
  ASSERT_TRUE(fs::is_directory(folder)) << folder;
  int seeds = 0;
  for (const auto &entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".drc") {
      continue;
    }
    std::ifstream stream(entry.path(), std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(stream)),
                                  std::istreambuf_iterator<char>());
    const auto decoded = DecodeDracoMesh(bytes);
    ASSERT_TRUE(decoded.ok()) << entry.path();
    const auto uvs =
        CornerValues(*decoded.value(), GeometryAttribute::TEX_COORD);
    EXPECT_FALSE(uvs.empty()) << entry.path();
    for (const float value : uvs) {
      ASSERT_TRUE(std::isfinite(value)) << entry.path();
    }
    ++seeds;
  }
  EXPECT_GE(seeds, 12);
}

}  // namespace
}  // namespace draco
