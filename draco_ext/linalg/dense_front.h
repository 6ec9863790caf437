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
// The dense kernel of the multifrontal Cholesky factorisation
// (sparse_cholesky.h, after [Duff & Reid 1983]), in two builds: the
// portable one, and on x86-64 one compiled for AVX2 and FMA
// (dense_front_avx2.cc), which factorises the fronts of the 300k-vertex
// benchmark meshes about twice as fast. The AVX2 build rounds differently
// (fused multiply-adds), so it is used only where the result need not be
// the same on every CPU: decoding the lossy Laplacian coder, whose output
// nothing is predicted from. Encoders use the portable build, so that
// their anchors, and so their files, are the same on every CPU of the
// architecture: both builds block their kernels by fixed cache sizes, not by
// those Eigen reads from the CPU (dense_front_impl.h).
#ifndef DRACO_EXT_LINALG_DENSE_FRONT_H_
#define DRACO_EXT_LINALG_DENSE_FRONT_H_

#include <functional>

namespace draco {

enum class DenseKernels {
  kPortable,     // The same result on every CPU of the architecture.
  kFastestHere,  // AVX2 and FMA where the CPU has them, else portable.
};

// Runs two independent jobs, one after the other or at once.
typedef std::function<void(const std::function<void()> &,
                           const std::function<void()> &)>
    ForkJoin;

// Partial factorisation of a front [F11 .; F21 F22] (F11 k x k):
//   L11 L11^T = F11,   L21 = F21 L11^-T,   update += -L21 L21^T.
// |panel| holds [F11; F21] column-major (m x k, lower triangle of F11 used)
// and receives [L11; L21]; |update| is (m - k) x (m - k) column-major, its
// lower triangle updated. False when F11 is not numerically positive
// definite (or a diagonal entry of L11 is not finite).
// Large fronts split the triangular solve by rows and the update by
// columns into two jobs each, which |fork_join| may run at once (without
// it, one after the other). The split depends on m and k alone, so the
// result does not depend on |fork_join|.
bool FactorDenseFront(DenseKernels kernels, double *panel, int m, int k,
                      double *update, const ForkJoin *fork_join = nullptr);

// The steps of FactorDenseFront() in one build of the kernels.
struct DenseFrontSteps {
  // L11 L11^T = F11; false when F11 is not numerically positive definite.
  bool (*factor_diagonal)(double *panel, int m, int k);
  // L21 = F21 L11^-T for the rows begin .. end - 1 of F21.
  void (*solve_rows)(double *panel, int m, int k, int begin, int end);
  // update -= L21 L21^T for the columns begin .. end - 1 of its lower
  // triangle.
  void (*update_columns)(const double *panel, int m, int k, double *update,
                         int begin, int end);
};

// True when kFastestHere uses the AVX2 build on this CPU.
bool DenseKernelsUseAvx2();

}  // namespace draco

#endif  // DRACO_EXT_LINALG_DENSE_FRONT_H_
