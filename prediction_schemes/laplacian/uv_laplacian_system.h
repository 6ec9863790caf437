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
// The least-squares reconstruction of [Váša & Brunnett 2014] section 5
// (steps 4-7, after [Sorkine et al. 2003] high-pass mesh encoding): the
// texture coordinates x (u and v alike) minimise
//     |L x - r|^2 + sum over anchors a of |x_a - x^_a|^2,
// the Laplacian rows L (uv_laplacian_operator.h) stacked on one identity
// row per anchor (the rectangular L* of the paper). Solved through
// the normal equations (L^T L + E E^T) x = L^T r + E x^, factorised once by
// SparseCholesky.
//
// Normal equations rather than a sparse QR of L*: on the corpus meshes
// Eigen's SparseQR was 20-60 times slower than Cholesky of L^T L for the
// same solution (the R factor has the fill of the Cholesky factor, plus
// Householder work); the squared condition number is harmless here because
// the anchors bound the smallest eigenvalue (relative residuals 1e-8 on the
// 300k-vertex benchmark mesh, far below the quantisation).
#ifndef PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_SYSTEM_H_
#define PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_SYSTEM_H_

#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "draco_ext/linalg/sparse_cholesky.h"
#include "prediction_schemes/laplacian/uv_laplacian_operator.h"

namespace draco {

class UvLaplacianSystem {
 public:
  // Orders the unknowns for |graph|, the texture graph of the operator
  // (UvTextureGraph()), while |build_operator| runs, on a second thread
  // when allowed: it returns the operator (kept by the caller until the
  // last Solve()), or null when it cannot be built; then L^T L is built on
  // that thread too. The ordering needs no weights, so the two take about
  // equally long (300k-vertex benchmark mesh) instead of one after the
  // other. False when building failed, or the factor would exceed
  // |max_factor_entries| or its factorisation would take more than about
  // 1024 n^1.5 flops (n unknowns; see uv_laplacian_system.cc).
  bool Analyze(
      const MatrixGraph &graph, int64_t max_factor_entries,
      const std::function<const UvLaplacianOperator *()> &build_operator);

  // Factorises the normal equations with anchors at the distinct texture
  // vertices |anchors|, after a successful Analyze(). False when the system
  // is singular (a chart whose Laplacian has more null space than its
  // anchors remove).
  bool Factorize(const std::vector<int> &anchors);

  // The factorisation's dense kernels (dense_front.h): portable by
  // default; decoders may take the fastest, as their output is not
  // predicted from.
  void set_dense_kernels(DenseKernels kernels) {
    cholesky_.set_dense_kernels(kernels);
  }

  // Anchors texture vertex |vertex| too, by rank-one updates of the factor.
  void AddAnchor(int vertex);

  // The least-squares texture coordinates for residuals |residuals| (one
  // row per row of the operator) and the values |anchor_values| of the
  // anchors in the order they were given to Factorize() and AddAnchor().
  UvValues Solve(const UvValues &residuals,
                 const UvValues &anchor_values) const;

  const std::vector<int> &anchors() const { return anchors_; }

  // The entries and floating point operations of the factor Factorize()
  // computes for |graph| (as ordered by Analyze()), without building or
  // factorising anything; false where Analyze() would refuse |graph|.
  // Encoders estimate what decoding will cost from it.
  static bool FactorWork(const MatrixGraph &graph, int64_t max_factor_entries,
                         int64_t *factor_entries, double *factor_flops);

 private:
  const UvLaplacianOperator *op_ = nullptr;
  SymmetricMatrix normal_;  // L^T L between Analyze() and Factorize().
  std::vector<int> anchors_;
  SparseCholesky cholesky_;
};

}  // namespace draco

#endif  // PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_SYSTEM_H_
