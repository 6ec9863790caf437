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

#include <cstdint>
#include <functional>

namespace draco {

// dense_front_portable.cc.
extern const DenseFrontSteps kDenseFrontStepsPortable;
#ifdef DRACO_UV_DENSE_FRONT_AVX2
// dense_front_avx2.cc.
extern const DenseFrontSteps kDenseFrontStepsAvx2;
#endif

namespace {

// Fronts whose solve and update take at least this many flops (k r^2 with
// r = m - k) are split in two jobs each: 2^25, about 2 ms.
constexpr double kMinSplitFlops = 33554432.0;

const DenseFrontSteps &ChooseSteps(DenseKernels kernels) {
#ifdef DRACO_UV_DENSE_FRONT_AVX2
  if (kernels == DenseKernels::kFastestHere && DenseKernelsUseAvx2()) {
    return kDenseFrontStepsAvx2;
  }
#endif
  return kDenseFrontStepsPortable;
}

}  // namespace

bool DenseKernelsUseAvx2() {
#ifdef DRACO_UV_DENSE_FRONT_AVX2
  static const bool has_avx2 =
      __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return has_avx2;
#else
  return false;
#endif
}

bool FactorDenseFront(DenseKernels kernels, double *panel, int m, int k,
                      double *update, const ForkJoin *fork_join) {
  const DenseFrontSteps &steps = ChooseSteps(kernels);
  if (k == 0) {
    return true;
  }
  if (!steps.factor_diagonal(panel, m, k)) {
    return false;
  }
  const int r = m - k;
  if (r == 0) {
    return true;
  }
  if (static_cast<double>(k) * r * r < kMinSplitFlops) {
    steps.solve_rows(panel, m, k, 0, r);
    steps.update_columns(panel, m, k, update, 0, r);
    return true;
  }
  auto run = [fork_join](const std::function<void()> &a,
                         const std::function<void()> &b) {
    if (fork_join != nullptr) {
      (*fork_join)(a, b);
    } else {
      a();
      b();
    }
  };
  // Halves of the rows; the columns split where the lower triangle's left
  // part has half the entries: c (r - c / 2) = r^2 / 4, c ~ r (1 - 1/sqrt 2).
  const int half = r / 2;
  const int split = static_cast<int>(static_cast<int64_t>(r) * 293 / 1000);
  run([&] { steps.solve_rows(panel, m, k, 0, half); },
      [&] { steps.solve_rows(panel, m, k, half, r); });
  run([&] { steps.update_columns(panel, m, k, update, 0, split); },
      [&] { steps.update_columns(panel, m, k, update, split, r); });
  return true;
}

}  // namespace draco
