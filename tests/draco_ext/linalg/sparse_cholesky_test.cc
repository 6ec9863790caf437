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
#include "draco_ext/linalg/sparse_cholesky.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include <Eigen/SparseCore>

#include "gtest/gtest.h"
#include "tests/scoped_eigen_cache_sizes.h"

namespace draco {
namespace {

// The 9-point graph Laplacian of a side x side grid plus the identity: a
// positive definite matrix with a two-dimensional pattern, like the normal
// equations of a mesh. Its graph is the 8-neighbour grid graph (the
// matrix couples only a third of the unknowns two edges apart in it).
struct GridSystem {
  MatrixGraph graph;
  SymmetricMatrix matrix;
};

GridSystem MakeGridSystem(int side) {
  GridSystem s;
  const int n = side * side;
  s.matrix.size = n;
  s.matrix.column_start.push_back(0);
  s.graph.start.push_back(0);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const int u = y * side + x;
      int degree = 0;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= side ||
              ny >= side) {
            continue;
          }
          s.graph.neighbour.push_back(ny * side + nx);
          s.matrix.row.push_back(ny * side + nx);
          s.matrix.value.push_back(-1.0 - 0.01 * ((u + nx + ny) % 7));
          ++degree;
        }
      }
      s.matrix.row.push_back(u);
      s.matrix.value.push_back(12.0 + degree);
      s.graph.start.push_back(static_cast<int>(s.graph.neighbour.size()));
      s.matrix.column_start.push_back(static_cast<int>(s.matrix.row.size()));
    }
  }
  // Symmetric values: average the two triangles' entries.
  for (int u = 0; u < n; ++u) {
    for (int e = s.matrix.column_start[u]; e < s.matrix.column_start[u + 1];
         ++e) {
      const int v = s.matrix.row[e];
      if (v <= u) {
        continue;
      }
      for (int f = s.matrix.column_start[v]; f < s.matrix.column_start[v + 1];
           ++f) {
        if (s.matrix.row[f] == u) {
          s.matrix.value[e] = s.matrix.value[f] =
              0.5 * (s.matrix.value[e] + s.matrix.value[f]);
        }
      }
    }
  }
  return s;
}

Eigen::MatrixXd Multiply(const SymmetricMatrix &m, const Eigen::MatrixXd &x) {
  Eigen::MatrixXd y = Eigen::MatrixXd::Zero(x.rows(), x.cols());
  for (int u = 0; u < m.size; ++u) {
    for (int e = m.column_start[u]; e < m.column_start[u + 1]; ++e) {
      y.row(m.row[e]) += m.value[e] * x.row(u);
    }
  }
  return y;
}

// A^T A + I for a random A with the 8-neighbour grid pattern: every pair
// of unknowns two edges apart in the grid graph is coupled, the pattern
// that Analyze() must separate with two-edge-wide separators, also where
// two subsets touch only through an ancestor's separator.
GridSystem MakeGridNormalSystem(int side) {
  GridSystem s = MakeGridSystem(side);
  const int n = side * side;
  Eigen::SparseMatrix<double> a(n, n);
  std::vector<Eigen::Triplet<double>> entries;
  for (int u = 0; u < n; ++u) {
    entries.emplace_back(u, u, 8.0 + (u % 3));
    for (int e = s.graph.start[u]; e < s.graph.start[u + 1]; ++e) {
      entries.emplace_back(u, s.graph.neighbour[e],
                           -1.0 - 0.1 * ((u * 7 + e) % 5));
    }
  }
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseMatrix<double> identity(n, n);
  identity.setIdentity();
  const Eigen::SparseMatrix<double> normal =
      Eigen::SparseMatrix<double>(a.transpose() * a) + identity;
  s.matrix.column_start.assign(1, 0);
  s.matrix.row.clear();
  s.matrix.value.clear();
  for (int u = 0; u < n; ++u) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(normal, u); it; ++it) {
      s.matrix.row.push_back(static_cast<int>(it.row()));
      s.matrix.value.push_back(it.value());
    }
    s.matrix.column_start.push_back(static_cast<int>(s.matrix.row.size()));
  }
  return s;
}

TEST(SparseCholeskyTest, SolvesNormalEquationsOrderedOnTheSquareRootGraph) {
  for (const int side : {7, 40, 150}) {
    const GridSystem s = MakeGridNormalSystem(side);
    SparseCholesky cholesky;
    ASSERT_TRUE(cholesky.Analyze(s.graph, int64_t{1} << 26)) << side;
    ASSERT_TRUE(cholesky.Factorize(s.matrix)) << side;
    const Eigen::MatrixXd x = Eigen::MatrixXd::Random(s.matrix.size, 2);
    Eigen::MatrixXd b = Multiply(s.matrix, x);
    cholesky.Solve(b);
    EXPECT_LT((b - x).cwiseAbs().maxCoeff(), 1e-8) << side;
  }
}

TEST(SparseCholeskyTest, SolvesALargeGridSystem) {
  const GridSystem s = MakeGridSystem(200);
  SparseCholesky cholesky;
  ASSERT_TRUE(cholesky.Analyze(s.graph, int64_t{1} << 26));
  ASSERT_TRUE(cholesky.Factorize(s.matrix));
  const Eigen::MatrixXd x = Eigen::MatrixXd::Random(s.matrix.size, 2);
  Eigen::MatrixXd b = Multiply(s.matrix, x);
  cholesky.Solve(b);
  EXPECT_LT((b - x).cwiseAbs().maxCoeff(), 1e-9);
}

// A random graph of degree about 6 (an expander, unlike a mesh): its
// factor is nearly dense, as a hostile file's would be.
MatrixGraph MakeRandomGraph(int n) {
  std::vector<std::vector<int>> adjacency(n);
  uint32_t state = 12345;
  for (int i = 0; i < 3 * n; ++i) {
    state = state * 1664525u + 1013904223u;
    const int u = static_cast<int>(state % n);
    state = state * 1664525u + 1013904223u;
    const int v = static_cast<int>(state % n);
    if (u != v) {
      adjacency[u].push_back(v);
      adjacency[v].push_back(u);
    }
  }
  MatrixGraph graph;
  graph.start.push_back(0);
  for (std::vector<int> &neighbours : adjacency) {
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()),
                     neighbours.end());
    graph.neighbour.insert(graph.neighbour.end(), neighbours.begin(),
                           neighbours.end());
    graph.start.push_back(static_cast<int>(graph.neighbour.size()));
  }
  return graph;
}

TEST(SparseCholeskyTest, RejectsFactorsAboveTheCap) {
  for (const int side : {10, 60}) {
    const GridSystem s = MakeGridNormalSystem(side);
    SparseCholesky cholesky;
    ASSERT_TRUE(cholesky.Analyze(s.graph, int64_t{1} << 26));
    const int64_t entries = cholesky.factor_size();
    EXPECT_TRUE(cholesky.Analyze(s.graph, entries));
    EXPECT_FALSE(cholesky.Analyze(s.graph, entries - 1));
  }
  // A cap linear in the unknowns, as the Laplacian decoder's, holds mesh
  // factors (above) but not an expander's.
  const int n = 20000;
  SparseCholesky cholesky;
  EXPECT_FALSE(cholesky.Analyze(MakeRandomGraph(n), 256 * int64_t{n}));
  ASSERT_TRUE(cholesky.Analyze(MakeGridNormalSystem(141).graph,
                               256 * int64_t{141 * 141}));
}

TEST(SparseCholeskyTest, TwoThreadsGiveTheSameFactorAsOne) {
  // Large enough for Factorize() and Solve() to use a second thread, and
  // for the fronts below the root to be split between the threads
  // (k r^2 > 2^25).
  const GridSystem s = MakeGridSystem(300);
  SparseCholesky one, two;
  one.set_max_threads(1);
  ASSERT_TRUE(one.Analyze(s.graph, int64_t{1} << 26));
  ASSERT_TRUE(two.Analyze(s.graph, int64_t{1} << 26));
  ASSERT_GT(one.factor_flops(), 1e8);
  ASSERT_GT(one.factor_size(), 1 << 20);
  ASSERT_TRUE(one.Factorize(s.matrix));
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(s.matrix.size, 2);
  Eigen::MatrixXd expected = rhs;
  one.Solve(expected);
  for (int run = 0; run < 3; ++run) {
    ASSERT_TRUE(two.Factorize(s.matrix));
    Eigen::MatrixXd x = rhs;
    two.Solve(x);
    EXPECT_TRUE((x.array() == expected.array()).all()) << "run " << run;
  }
}

TEST(SparseCholeskyTest, RejectsIndefiniteMatricesInAnySubtree) {
  GridSystem s = MakeGridSystem(200);
  for (const DenseKernels kernels :
       {DenseKernels::kPortable, DenseKernels::kFastestHere}) {
    SparseCholesky cholesky;
    cholesky.set_dense_kernels(kernels);
    ASSERT_TRUE(cholesky.Analyze(s.graph, int64_t{1} << 26));
    // Negative diagonals at both ends of the grid, in different subtrees.
    for (const int u : {0, s.matrix.size - 1}) {
      GridSystem bad = s;
      for (int e = bad.matrix.column_start[u];
           e < bad.matrix.column_start[u + 1]; ++e) {
        if (bad.matrix.row[e] == u) {
          bad.matrix.value[e] = -1.0;
        }
      }
      EXPECT_FALSE(cholesky.Factorize(bad.matrix)) << "unknown " << u;
    }
  }
}

// On CPUs with AVX2 and FMA the fastest kernels are another build of the
// same algorithm, which rounds differently (dense_front.h); elsewhere
// they are the portable ones and this compares them with themselves.
TEST(SparseCholeskyTest, FastestDenseKernelsSolveAsWellAndDeterministically) {
  RecordProperty("avx2", DenseKernelsUseAvx2() ? "yes" : "no");
  const GridSystem s = MakeGridNormalSystem(150);
  SparseCholesky portable, fastest;
  fastest.set_dense_kernels(DenseKernels::kFastestHere);
  ASSERT_TRUE(portable.Analyze(s.graph, int64_t{1} << 26));
  ASSERT_TRUE(fastest.Analyze(s.graph, int64_t{1} << 26));
  ASSERT_TRUE(portable.Factorize(s.matrix));
  const Eigen::MatrixXd x = Eigen::MatrixXd::Random(s.matrix.size, 2);
  Eigen::MatrixXd expected = Multiply(s.matrix, x);
  portable.Solve(expected);
  Eigen::MatrixXd first;
  for (int run = 0; run < 2; ++run) {
    ASSERT_TRUE(fastest.Factorize(s.matrix));
    Eigen::MatrixXd b = Multiply(s.matrix, x);
    fastest.Solve(b);
    EXPECT_LT((b - x).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_LT((b - expected).cwiseAbs().maxCoeff(), 1e-10);
    if (run == 0) {
      first = b;
    } else {
      EXPECT_TRUE((b.array() == first.array()).all());
    }
  }
}

// The factor and the solution do not depend on the cache sizes by which Eigen
// blocks its matrix kernels (dense_front_impl.h, Solve()), so that an
// encoder picks the same anchors on every CPU with its instruction set.
TEST(SparseCholeskyTest, SolvesTheSameWhateverTheCpusCacheSizes) {
  const GridSystem s = MakeGridNormalSystem(150);
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(s.matrix.size, 2);
  for (const DenseKernels kernels :
       {DenseKernels::kPortable, DenseKernels::kFastestHere}) {
    SparseCholesky cholesky;
    cholesky.set_dense_kernels(kernels);
    ASSERT_TRUE(cholesky.Analyze(s.graph, int64_t{1} << 26));
    ASSERT_TRUE(cholesky.Factorize(s.matrix));
    Eigen::MatrixXd expected = rhs;
    cholesky.Solve(expected);
    const ScopedEigenCacheSizes other_cpu;
    ASSERT_TRUE(cholesky.Factorize(s.matrix));
    Eigen::MatrixXd x = rhs;
    cholesky.Solve(x);
    EXPECT_TRUE((x.array() == expected.array()).all());
  }
}

}  // namespace
}  // namespace draco
