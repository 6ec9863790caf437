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
// The steps of FactorDenseFront() (dense_front.h), included by each
// of its builds after Eigen, which each build renames. Internal linkage, so
// that every build keeps its own copy.
#ifndef DRACO_EXT_LINALG_DENSE_FRONT_IMPL_H_
#define DRACO_EXT_LINALG_DENSE_FRONT_IMPL_H_

#include <cstddef>
#include <mutex>

#include "draco_ext/linalg/dense_front.h"

// UseFixedCacheSizes() below must not change the cache sizes of the
// application's Eigen.
#ifndef Eigen
#error "Rename Eigen (#define Eigen DracoUvEigen...) before including it."
#endif

namespace draco {
namespace {

// Eigen sizes its blocks from the cache sizes it reads from the CPU, and the
// blocks set the order of its sums: an L1 of 48 KB instead of 32 KB factors
// the 300k-vertex benchmark meshes with other rounding. This build's own
// (renamed) Eigen uses fixed sizes instead, so that its results depend on
// the instruction set alone: the sizes Eigen reads on the x86-64 machine of
// the benchmarks (AMD EPYC: 32 KB, 512 KB, and its L3 reported as 256 MB),
// so that the files encoded there are unchanged.
constexpr std::ptrdiff_t kFixedL1CacheSize = std::ptrdiff_t{32} << 10;
constexpr std::ptrdiff_t kFixedL2CacheSize = std::ptrdiff_t{512} << 10;
constexpr std::ptrdiff_t kFixedL3CacheSize = std::ptrdiff_t{256} << 20;

// Sets the fixed cache sizes before this build's Eigen first sizes a block.
void UseFixedCacheSizes() {
  static std::once_flag once;
  std::call_once(once, [] {
    Eigen::setCpuCacheSizes(kFixedL1CacheSize, kFixedL2CacheSize,
                            kFixedL3CacheSize);
  });
}

// Eigen's blocked dense kernels on the front [F11 .; F21 F22] of
// dense_front.h, with r = m - k rows below F11.

// L11 L11^T = F11 in place (LLT). False when F11 is not numerically
// positive definite.
bool FactorDenseDiagonal(double *panel_data, int m, int k) {
  UseFixedCacheSizes();
  Eigen::Map<Eigen::MatrixXd> panel(panel_data, m, k);
  Eigen::Ref<Eigen::MatrixXd> diagonal = panel.topRows(k);
  Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(diagonal);
  return llt.info() == Eigen::Success && diagonal.diagonal().allFinite();
}

// L21 = F21 L11^-T for the rows |begin| .. |end| - 1 of F21.
void SolveDenseRows(double *panel_data, int m, int k, int begin, int end) {
  UseFixedCacheSizes();
  Eigen::Map<Eigen::MatrixXd> panel(panel_data, m, k);
  auto rows = panel.middleRows(k + begin, end - begin);
  panel.topRows(k)
      .transpose()
      .triangularView<Eigen::Upper>()
      .solveInPlace<Eigen::OnTheRight>(rows);
}

// update -= L21 L21^T for the columns |begin| .. |end| - 1 of the lower
// triangle: a rank-k update of their diagonal block and, below it, a
// matrix product.
void UpdateDenseColumns(const double *panel_data, int m, int k,
                        double *update_data, int begin, int end) {
  UseFixedCacheSizes();
  const int r = m - k;
  Eigen::Map<const Eigen::MatrixXd> panel(panel_data, m, k);
  const auto l21 = panel.bottomRows(r);
  Eigen::Map<Eigen::MatrixXd> update(update_data, r, r);
  const int width = end - begin;
  update.block(begin, begin, width, width)
      .selfadjointView<Eigen::Lower>()
      .rankUpdate(l21.middleRows(begin, width), -1.0);
  if (end < r) {
    update.block(end, begin, r - end, width).noalias() -=
        l21.bottomRows(r - end) * l21.middleRows(begin, width).transpose();
  }
}

constexpr DenseFrontSteps kEigenDenseFrontSteps = {
    FactorDenseDiagonal, SolveDenseRows, UpdateDenseColumns};

}  // namespace
}  // namespace draco

#endif  // DRACO_EXT_LINALG_DENSE_FRONT_IMPL_H_
