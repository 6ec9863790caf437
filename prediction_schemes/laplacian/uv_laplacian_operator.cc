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
#include "prediction_schemes/laplacian/uv_laplacian_operator.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace draco {

namespace {

// A triangle is degenerate when sin(angle) is below this at some corner.
constexpr double kMinSine = 1e-9;
// A row's weights are usable when their sum is at least this fraction of
// the sum of their magnitudes (cotangent weights can be negative).
constexpr double kMinWeightSumRatio = 0.1;

bool HasDistinctCorners(const std::array<int, 3> &face) {
  return face[0] != face[1] && face[1] != face[2] && face[2] != face[0];
}

// Slot of neighbour |j| of |i| in |graph| (sorted rows); j must be a
// neighbour.
int Slot(const MatrixGraph &graph, int i, int j) {
  const auto begin = graph.neighbour.begin();
  return static_cast<int>(
      std::lower_bound(begin + graph.start[i], begin + graph.start[i + 1], j) -
      begin);
}

struct CornerAngle {
  double cotangent = 0;
  double tan_half = 0;
  double length_next = 0;  // |p_next - p|.
  double length_prev = 0;  // |p_prev - p|.
};

// Angles at corner |k| of |face|; false for a degenerate triangle.
bool ComputeCornerAngle(const UvLaplacianMesh &mesh,
                        const std::array<int, 3> &face, int k,
                        CornerAngle *angle) {
  const auto &p = mesh.positions[face[k]];
  const auto &q = mesh.positions[face[(k + 1) % 3]];
  const auto &r = mesh.positions[face[(k + 2) % 3]];
  const double e1[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  const double e2[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
  const double dot = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
  const double cross[3] = {e1[1] * e2[2] - e1[2] * e2[1],
                           e1[2] * e2[0] - e1[0] * e2[2],
                           e1[0] * e2[1] - e1[1] * e2[0]};
  const double sine_area = std::sqrt(
      cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
  angle->length_next = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  angle->length_prev = std::sqrt(e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2]);
  const double lengths = angle->length_next * angle->length_prev;
  if (!(sine_area > kMinSine * lengths)) {
    return false;
  }
  angle->cotangent = dot / sine_area;
  // tan(a / 2) = sin(a) / (1 + cos(a)).
  angle->tan_half = sine_area / (lengths + dot);
  return std::isfinite(angle->cotangent) && std::isfinite(angle->tan_half);
}

class UnionFind {
 public:
  explicit UnionFind(int n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int Find(int x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void Union(int a, int b) {
    a = Find(a);
    b = Find(b);
    if (a != b) {
      parent_[std::max(a, b)] = std::min(a, b);
    }
  }

 private:
  std::vector<int> parent_;
};

double SquaredDistance(const std::array<double, 3> &a,
                       const std::array<double, 3> &b) {
  const double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

// Weights of the rows of one kind, per neighbour slot, before scaling.
struct RowWeights {
  std::vector<double> weight;    // w_ij, eq. 6-8.
  std::vector<bool> degenerate;  // Per vertex: next to a degenerate face.
};

RowWeights ComputeRowWeights(const UvLaplacianMesh &mesh,
                             const MatrixGraph &graph, UvLaplacianKind kind) {
  RowWeights rows;
  rows.weight.assign(graph.neighbour.size(),
                     kind == UvLaplacianKind::kTutte ? 1.0 : 0.0);
  rows.degenerate.assign(mesh.num_vertices(), false);
  if (kind == UvLaplacianKind::kTutte) {
    return rows;
  }
  for (const auto &face : mesh.faces) {
    if (!HasDistinctCorners(face)) {
      continue;
    }
    std::array<CornerAngle, 3> angles;
    bool valid = true;
    for (int k = 0; k < 3; ++k) {
      valid = valid && ComputeCornerAngle(mesh, face, k, &angles[k]);
    }
    if (!valid) {
      for (const int v : face) {
        rows.degenerate[v] = true;
      }
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const int i = face[k];
      const int j = face[(k + 1) % 3];
      const int l = face[(k + 2) % 3];
      if (kind == UvLaplacianKind::kMeanValue) {
        rows.weight[Slot(graph, i, j)] +=
            angles[k].tan_half / angles[k].length_next;
        rows.weight[Slot(graph, i, l)] +=
            angles[k].tan_half / angles[k].length_prev;
      } else {
        rows.weight[Slot(graph, j, l)] += angles[k].cotangent;
        rows.weight[Slot(graph, l, j)] += angles[k].cotangent;
      }
    }
  }
  return rows;
}

// Vertices with an edge of other than two faces; |uses| counts the faces
// of every edge slot of |graph|, faces with repeated corners included,
// which are taken out here (they are not part of the texture connectivity).
std::vector<bool> BoundaryFromEdgeUses(const UvLaplacianMesh &mesh,
                                       const MatrixGraph &graph,
                                       std::vector<int> uses) {
  for (const auto &face : mesh.faces) {
    if (HasDistinctCorners(face)) {
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      for (const int other : {face[(k + 1) % 3], face[(k + 2) % 3]}) {
        if (other != face[k]) {
          --uses[Slot(graph, face[k], other)];
        }
      }
    }
  }
  std::vector<bool> boundary(mesh.num_vertices(), false);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    for (int s = graph.start[v]; s < graph.start[v + 1]; ++s) {
      if (uses[s] != 2) {
        boundary[v] = true;
      }
    }
  }
  return boundary;
}

}  // namespace

MatrixGraph UvTextureGraph(const UvLaplacianMesh &mesh,
                           std::vector<bool> *boundary) {
  const int n = mesh.num_vertices();
  MatrixGraph graph;
  std::vector<int> &start = graph.start;
  std::vector<int> &neighbour = graph.neighbour;
  start.assign(n + 1, 0);
  for (const auto &face : mesh.faces) {
    for (int k = 0; k < 3; ++k) {
      start[face[k] + 1] += 2;
    }
  }
  std::partial_sum(start.begin(), start.end(), start.begin());
  neighbour.resize(start[n]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (const auto &face : mesh.faces) {
    for (int k = 0; k < 3; ++k) {
      neighbour[fill[face[k]]++] = face[(k + 1) % 3];
      neighbour[fill[face[k]]++] = face[(k + 2) % 3];
    }
  }
  // Sort, drop duplicates and self references, compact. Every face of v
  // lists each of its other two corners once, so a neighbour's count is the
  // number of faces of the edge.
  std::vector<int> uses(neighbour.size(), 0);
  int out = 0;
  for (int v = 0; v < n; ++v) {
    const auto begin = neighbour.begin() + start[v];
    const auto end = neighbour.begin() + start[v + 1];
    std::sort(begin, end);
    const int row_begin = out;
    for (auto it = begin; it != end; ++it) {
      if (*it == v) {
        continue;
      }
      if (out == row_begin || neighbour[out - 1] != *it) {
        neighbour[out++] = *it;
      }
      ++uses[out - 1];
    }
    start[v] = row_begin;
  }
  start[n] = out;
  neighbour.resize(out);
  if (boundary != nullptr) {
    uses.resize(out);
    *boundary = BoundaryFromEdgeUses(mesh, graph, std::move(uses));
  }
  return graph;
}

int UvMinChartSizeForSecondAnchor(UvLaplacianKind kind) {
  return kind == UvLaplacianKind::kCotangent ? 2 : 16;
}

UvCharts ComputeUvCharts(const UvLaplacianMesh &mesh,
                         int min_size_for_second_anchor) {
  const int n = mesh.num_vertices();
  UnionFind components(n);
  for (const auto &face : mesh.faces) {
    components.Union(face[0], face[1]);
    components.Union(face[1], face[2]);
  }
  // Roots are the smallest vertices of their charts; number charts in that
  // order.
  UvCharts charts;
  charts.chart_of_vertex.resize(n);
  std::vector<int> first_vertex;
  for (int v = 0; v < n; ++v) {
    const int root = components.Find(v);
    if (root == v) {
      charts.chart_of_vertex[v] = static_cast<int>(first_vertex.size());
      first_vertex.push_back(v);
    } else {
      charts.chart_of_vertex[v] = charts.chart_of_vertex[root];
    }
  }
  charts.num_charts = static_cast<int>(first_vertex.size());
  std::vector<int> farthest(first_vertex);
  std::vector<double> distance(charts.num_charts, 0.0);
  std::vector<int> size(charts.num_charts, 0);
  for (int v = 0; v < n; ++v) {
    const int chart = charts.chart_of_vertex[v];
    ++size[chart];
    const double d =
        SquaredDistance(mesh.positions[v], mesh.positions[first_vertex[chart]]);
    if (d > distance[chart]) {
      distance[chart] = d;
      farthest[chart] = v;
    }
  }
  for (int chart = 0; chart < charts.num_charts; ++chart) {
    charts.anchors.push_back(first_vertex[chart]);
    if (size[chart] >= min_size_for_second_anchor &&
        farthest[chart] != first_vertex[chart]) {
      charts.anchors.push_back(farthest[chart]);
    }
  }
  return charts;
}

void UvLaplacianOperator::Build(const UvLaplacianMesh &mesh,
                                const MatrixGraph &graph,
                                UvLaplacianKind kind) {
  const RowWeights rows = ComputeRowWeights(mesh, graph, kind);
  num_fallback_rows_ = 0;
  row_start_.assign(1, 0);
  row_start_.reserve(graph.start.size());
  column_.clear();
  column_.reserve(graph.neighbour.size() + graph.start.size());
  value_.clear();
  value_.reserve(column_.capacity());
  for (int i = 0; i < mesh.num_vertices(); ++i) {
    const int begin = graph.start[i];
    const int end = graph.start[i + 1];
    const int degree = end - begin;
    if (degree == 0) {
      row_start_.push_back(static_cast<int>(column_.size()));
      continue;
    }
    // Eq. 7 with the diagonal scaled to -1, or Tutte weights when the row's
    // weights are unusable.
    double sum = 0, magnitude = 0;
    for (int s = begin; s < end; ++s) {
      sum += rows.weight[s];
      magnitude += std::abs(rows.weight[s]);
    }
    const bool usable = !rows.degenerate[i] && std::isfinite(sum) &&
                        sum > kMinWeightSumRatio * magnitude;
    if (!usable) {
      ++num_fallback_rows_;
    }
    column_.push_back(i);
    value_.push_back(-1.0);
    for (int s = begin; s < end; ++s) {
      column_.push_back(graph.neighbour[s]);
      value_.push_back(usable ? rows.weight[s] / sum : 1.0 / degree);
    }
    row_start_.push_back(static_cast<int>(column_.size()));
  }
}

UvValues UvLaplacianOperator::Apply(const UvValues &x) const {
  UvValues r = UvValues::Zero(num_rows(), 2);
  for (int row = 0; row < num_rows(); ++row) {
    for (int e = row_start_[row]; e < row_start_[row + 1]; ++e) {
      r.row(row) += value_[e] * x.row(column_[e]);
    }
  }
  return r;
}

UvValues UvLaplacianOperator::ApplyTransposed(const UvValues &r) const {
  UvValues x = UvValues::Zero(num_rows(), 2);
  for (int row = 0; row < num_rows(); ++row) {
    for (int e = row_start_[row]; e < row_start_[row + 1]; ++e) {
      x.row(column_[e]) += value_[e] * r.row(row);
    }
  }
  return x;
}

}  // namespace draco
