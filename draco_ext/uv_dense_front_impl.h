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
// The body of UvFactorDenseFront() (uv_dense_front.h), included by each of
// its builds after Eigen. Internal linkage, so that every build keeps its
// own copy.
#ifndef DRACO_EXT_UV_DENSE_FRONT_IMPL_H_
#define DRACO_EXT_UV_DENSE_FRONT_IMPL_H_

namespace draco {
namespace {

// Eigen's blocked dense kernels: LLT, triangular solve and a symmetric
// rank-k update of the lower triangle.
bool FactorDenseFrontWithEigen(double *panel_data, int m, int k,
                               double *update_data) {
  if (k == 0) {
    return true;
  }
  Eigen::Map<Eigen::MatrixXd> panel(panel_data, m, k);
  Eigen::Ref<Eigen::MatrixXd> diagonal = panel.topRows(k);
  Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(diagonal);
  if (llt.info() != Eigen::Success || !diagonal.diagonal().allFinite()) {
    return false;
  }
  if (m > k) {
    Eigen::Map<Eigen::MatrixXd> update(update_data, m - k, m - k);
    auto below = panel.bottomRows(m - k);
    diagonal.transpose()
        .triangularView<Eigen::Upper>()
        .solveInPlace<Eigen::OnTheRight>(below);
    update.selfadjointView<Eigen::Lower>().rankUpdate(below, -1.0);
  }
  return true;
}

}  // namespace
}  // namespace draco

#endif  // DRACO_EXT_UV_DENSE_FRONT_IMPL_H_
