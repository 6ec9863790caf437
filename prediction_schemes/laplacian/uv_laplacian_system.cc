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
#include "prediction_schemes/laplacian/uv_laplacian_system.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "draco/core/macros.h"

namespace draco {

namespace {

// Weight of an anchor row relative to a Laplacian row (the paper's "1").
constexpr double kAnchorWeight = 1.0;

// Rows of L by column: for unknown u, the rows r with L(r, u) != 0.
struct Transposed {
  std::vector<int> start;
  std::vector<int> row;
  std::vector<double> value;
};

Transposed Transpose(const UvLaplacianOperator &op) {
  const int n = op.num_rows();
  Transposed t;
  t.start.assign(n + 1, 0);
  for (int e = 0; e < op.row_start(n); ++e) {
    ++t.start[op.column(e) + 1];
  }
  for (int u = 0; u < n; ++u) {
    t.start[u + 1] += t.start[u];
  }
  t.row.resize(op.row_start(n));
  t.value.resize(op.row_start(n));
  std::vector<int> fill(t.start.begin(), t.start.end() - 1);
  for (int r = 0; r < n; ++r) {
    for (int e = op.row_start(r); e < op.row_start(r + 1); ++e) {
      const int slot = fill[op.column(e)]++;
      t.row[slot] = r;
      t.value[slot] = op.value(e);
    }
  }
  return t;
}

// L^T L, both triangles, by column; every column starts with its diagonal
// entry, zero for vertices without faces, so that anchors can be added.
SymmetricMatrix NormalMatrix(const UvLaplacianOperator &op,
                             const Transposed &t) {
  const int n = op.num_rows();
  SymmetricMatrix m;
  m.size = n;
  m.column_start.reserve(n + 1);
  m.column_start.assign(1, 0);
  // About the two-ring of every vertex (1 + 6 + 12 entries for an interior
  // vertex of valence 6), so that the columns are appended without copying.
  int64_t estimate = 0;
  for (int u = 0; u < n; ++u) {
    estimate += std::max(1, 3 * (op.row_start(u + 1) - op.row_start(u)) - 2);
  }
  m.row.reserve(estimate);
  m.value.reserve(estimate);
  std::vector<double> accumulator(n, 0.0);
  std::vector<int> marker(n, -1);
  std::vector<int> pattern;
  auto touch = [&](int u, int v) {
    if (marker[v] != u) {
      marker[v] = u;
      accumulator[v] = 0.0;
      pattern.push_back(v);
    }
  };
  for (int u = 0; u < n; ++u) {
    pattern.clear();
    touch(u, u);
    for (int e = t.start[u]; e < t.start[u + 1]; ++e) {
      const int r = t.row[e];
      for (int f = op.row_start(r); f < op.row_start(r + 1); ++f) {
        touch(u, op.column(f));
        accumulator[op.column(f)] += t.value[e] * op.value(f);
      }
    }
    for (const int v : pattern) {
      m.row.push_back(v);
      m.value.push_back(accumulator[v]);
    }
    m.column_start.push_back(static_cast<int>(m.row.size()));
  }
  return m;
}

// An upper bound of the entries of L^T L, to refuse pathological
// connectivity before building it; |graph| is the operator's pattern
// without the diagonal.
int64_t NormalMatrixBound(const MatrixGraph &graph) {
  int64_t bound = 0;
  for (int u = 0; u < graph.size(); ++u) {
    const int64_t degree = graph.start[u + 1] - graph.start[u];
    const int64_t entries = degree > 0 ? degree + 1 : 0;
    bound += entries * entries;
  }
  return bound;
}

// Adds |delta| to the diagonal entry of column |u| (NormalMatrix()).
void AddToDiagonalEntry(SymmetricMatrix *m, int u, double delta) {
  DRACO_DCHECK_EQ(m->row[m->column_start[u]], u);
  m->value[m->column_start[u]] += delta;
}

// The factorisation's work is capped at kFlopsScale n^1.5 + kMinFlops: 4-9
// times what the corpus meshes and the 300k-vertex benchmark meshes need
// under nested dissection (at most 255 n^1.5, measured), so that hostile
// connectivity (huge separators) fails instead of decoding for hours.
double MaxFactorFlops(int num_unknowns) {
  constexpr double kFlopsScale = 1024;
  constexpr double kMinFlops = 1e8;
  const double n = std::max(0, num_unknowns);
  return kFlopsScale * n * std::sqrt(n) + kMinFlops;
}

}  // namespace

bool UvLaplacianSystem::Analyze(
    const MatrixGraph &graph, int64_t max_factor_entries,
    const std::function<const UvLaplacianOperator *()> &build_operator) {
  op_ = nullptr;
  if (NormalMatrixBound(graph) > max_factor_entries) {
    return false;
  }
  auto build_normal_matrix = [&] {
    op_ = build_operator();
    if (op_ != nullptr) {
      normal_ = NormalMatrix(*op_, Transpose(*op_));
    }
  };
  return cholesky_.Analyze(graph, max_factor_entries, build_normal_matrix) &&
         op_ != nullptr && op_->num_rows() == graph.size() &&
         cholesky_.factor_flops() <= MaxFactorFlops(graph.size());
}

bool UvLaplacianSystem::FactorWork(const MatrixGraph &graph,
                                   int64_t max_factor_entries,
                                   int64_t *factor_entries,
                                   double *factor_flops) {
  SparseCholesky cholesky;
  if (NormalMatrixBound(graph) > max_factor_entries ||
      !cholesky.Analyze(graph, max_factor_entries)) {
    return false;
  }
  *factor_entries = cholesky.factor_size();
  *factor_flops = cholesky.factor_flops();
  return *factor_flops <= MaxFactorFlops(graph.size());
}

bool UvLaplacianSystem::Factorize(const std::vector<int> &anchors) {
  DRACO_DCHECK(op_ != nullptr);
  anchors_ = anchors;
  SymmetricMatrix m = std::move(normal_);
  for (const int a : anchors) {
    AddToDiagonalEntry(&m, a, kAnchorWeight * kAnchorWeight);
  }
  return cholesky_.Factorize(m);
}

void UvLaplacianSystem::AddAnchor(int vertex) {
  anchors_.push_back(vertex);
  cholesky_.AddToDiagonal(vertex, kAnchorWeight * kAnchorWeight);
}

UvValues UvLaplacianSystem::Solve(const UvValues &residuals,
                                  const UvValues &anchor_values) const {
  UvValues x = op_->ApplyTransposed(residuals);
  for (size_t i = 0; i < anchors_.size(); ++i) {
    x.row(anchors_[i]) += kAnchorWeight * kAnchorWeight * anchor_values.row(i);
  }
  cholesky_.Solve(x);
  return x;
}

}  // namespace draco
