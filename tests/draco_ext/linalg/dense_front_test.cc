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
#include "draco_ext/linalg/dense_front.h"

#include <functional>
#include <thread>
#include <vector>

#include <Eigen/Core>

#include "gtest/gtest.h"
#include "tests/scoped_eigen_cache_sizes.h"

namespace draco {
namespace {

// A random symmetric positive definite m x m front, column-major.
Eigen::MatrixXd MakeFront(int m) {
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(m, m);
  return a * a.transpose() / m + Eigen::MatrixXd::Identity(m, m);
}

struct FactoredFront {
  std::vector<double> panel;
  std::vector<double> update;
};

FactoredFront Factor(DenseKernels kernels, const Eigen::MatrixXd &front, int k,
                     const ForkJoin *fork_join) {
  const int m = static_cast<int>(front.rows());
  FactoredFront f;
  const Eigen::MatrixXd panel = front.leftCols(k);
  const Eigen::MatrixXd update = front.bottomRightCorner(m - k, m - k);
  f.panel.assign(panel.data(), panel.data() + panel.size());
  f.update.assign(update.data(), update.data() + update.size());
  EXPECT_TRUE(FactorDenseFront(kernels, f.panel.data(), m, k, f.update.data(),
                               fork_join));
  return f;
}

// L11 L11^T = F11, L21 L11^T = F21 and update = F22 - L21 L21^T, on the
// lower triangles.
void ExpectPartialFactorisation(const Eigen::MatrixXd &front, int k,
                                const FactoredFront &f) {
  const int m = static_cast<int>(front.rows());
  const Eigen::Map<const Eigen::MatrixXd> panel(f.panel.data(), m, k);
  const Eigen::MatrixXd l11 = panel.topRows(k).triangularView<Eigen::Lower>();
  const Eigen::MatrixXd l21 = panel.bottomRows(m - k);
  const Eigen::Map<const Eigen::MatrixXd> update(f.update.data(), m - k, m - k);
  const Eigen::MatrixXd f11 = l11 * l11.transpose();
  EXPECT_LT((f11 - front.topLeftCorner(k, k))
                .triangularView<Eigen::Lower>()
                .toDenseMatrix()
                .cwiseAbs()
                .maxCoeff(),
            1e-9);
  if (m == k) {
    return;
  }
  EXPECT_LT((l21 * l11.transpose() - front.bottomLeftCorner(m - k, k))
                .cwiseAbs()
                .maxCoeff(),
            1e-9);
  const Eigen::MatrixXd expected_update =
      front.bottomRightCorner(m - k, m - k) - l21 * l21.transpose();
  EXPECT_LT((Eigen::MatrixXd(update) - expected_update)
                .triangularView<Eigen::Lower>()
                .toDenseMatrix()
                .cwiseAbs()
                .maxCoeff(),
            1e-9);
}

TEST(DenseFrontTest, FactorsSmallAndSplitFronts) {
  // k (m - k)^2 below and above the size at which the work is split.
  for (const DenseKernels kernels :
       {DenseKernels::kPortable, DenseKernels::kFastestHere}) {
    for (const int k : {1, 40, 300}) {
      for (const int r : {0, 7, 120, 700}) {
        SCOPED_TRACE(testing::Message() << "k " << k << " r " << r);
        const Eigen::MatrixXd front = MakeFront(k + r);
        ExpectPartialFactorisation(front, k,
                                   Factor(kernels, front, k, nullptr));
      }
    }
  }
}

TEST(DenseFrontTest, SplitFrontsDoNotDependOnHowTheHalvesRun) {
  const ForkJoin on_two_threads = [](const std::function<void()> &a,
                                     const std::function<void()> &b) {
    std::thread other(b);
    a();
    other.join();
  };
  const ForkJoin second_first = [](const std::function<void()> &a,
                                   const std::function<void()> &b) {
    b();
    a();
  };
  const int k = 300, r = 700;
  const Eigen::MatrixXd front = MakeFront(k + r);
  for (const DenseKernels kernels :
       {DenseKernels::kPortable, DenseKernels::kFastestHere}) {
    const FactoredFront expected = Factor(kernels, front, k, nullptr);
    for (const ForkJoin *fork_join : {&on_two_threads, &second_first}) {
      const FactoredFront f = Factor(kernels, front, k, fork_join);
      EXPECT_EQ(f.panel, expected.panel);
      EXPECT_EQ(f.update, expected.update);
    }
  }
}

// Eigen sizes its blocks, and so orders its sums, by the cache sizes it reads
// from the CPU; the dense kernels use fixed ones, so that a front factorises
// the same on every CPU with their instruction set.
TEST(DenseFrontTest, FactorsTheSameWhateverTheCpusCacheSizes) {
  const int k = 600, r = 400;
  const Eigen::MatrixXd front = MakeFront(k + r);
  for (const DenseKernels kernels :
       {DenseKernels::kPortable, DenseKernels::kFastestHere}) {
    const FactoredFront expected = Factor(kernels, front, k, nullptr);
    const ScopedEigenCacheSizes other_cpu;
    const FactoredFront f = Factor(kernels, front, k, nullptr);
    EXPECT_EQ(f.panel, expected.panel);
    EXPECT_EQ(f.update, expected.update);
  }
  // The control: Eigen's own product of the front's panels rounds
  // differently with those cache sizes.
  const Eigen::MatrixXd l = front.leftCols(k);
  const Eigen::MatrixXd product = l.transpose() * l;
  const ScopedEigenCacheSizes other_cpu;
  const Eigen::MatrixXd other_product = l.transpose() * l;
  EXPECT_FALSE((other_product.array() == product.array()).all());
}

}  // namespace
}  // namespace draco
