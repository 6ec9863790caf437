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
// Texture connectivities with 3D positions and UVs for the tests of the
// Laplacian operator, system and coder: meshes of Draco's and draco-uv's
// testdata, and a generated mesh of many small charts.
#ifndef DRACO_UV_TESTS_PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_TEST_CASES_H_
#define DRACO_UV_TESTS_PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_TEST_CASES_H_

#include <algorithm>
#include <array>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "draco/mesh/mesh.h"
#include "prediction_schemes/laplacian/uv_laplacian_operator.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {

// Every weighting of the operator.
inline constexpr UvLaplacianKind kKinds[] = {UvLaplacianKind::kTutte,
                                             UvLaplacianKind::kCotangent,
                                             UvLaplacianKind::kMeanValue};
// The cases' UVs are in units of a grid of 2^kFrameBits - 1 steps over
// their range ("frame units").
inline constexpr int kFrameBits = 20;

struct UvTestCase {
  std::string name;
  UvLaplacianMesh mesh;
  UvValues uv;  // Frame units.
};

// One texture vertex per value of the first TEX_COORD attribute, at the
// position of a point that uses it; UVs scaled to the frame.
inline UvTestCase FromDracoMesh(const std::string &name, const Mesh &mesh) {
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

inline std::vector<UvTestCase> TestdataCases() {
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
inline UvTestCase ManyChartsCase(int triangles, int strip_quads) {
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

}  // namespace draco

#endif  // DRACO_UV_TESTS_PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_TEST_CASES_H_
