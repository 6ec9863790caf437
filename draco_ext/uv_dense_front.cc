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
#include "draco_ext/uv_dense_front.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "draco_ext/uv_dense_front_impl.h"

namespace draco {

#ifdef DRACO_UV_DENSE_FRONT_AVX2
// uv_dense_front_avx2.cc.
bool UvFactorDenseFrontAvx2(double *panel, int m, int k, double *update);
#endif

bool UvDenseKernelsUseAvx2() {
#ifdef DRACO_UV_DENSE_FRONT_AVX2
  static const bool has_avx2 =
      __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return has_avx2;
#else
  return false;
#endif
}

bool UvFactorDenseFront(UvDenseKernels kernels, double *panel, int m, int k,
                        double *update) {
#ifdef DRACO_UV_DENSE_FRONT_AVX2
  if (kernels == UvDenseKernels::kFastestHere && UvDenseKernelsUseAvx2()) {
    return UvFactorDenseFrontAvx2(panel, m, k, update);
  }
#endif
  return FactorDenseFrontWithEigen(panel, m, k, update);
}

}  // namespace draco
