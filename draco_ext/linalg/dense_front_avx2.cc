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
// The AVX2 and FMA build of FactorDenseFront()'s steps, compiled with -mavx2
// -mfma (cmake/draco_uv_extension.cmake) and called only on CPUs that have
// both.
//
// Eigen is renamed here: its templates are instantiated in other files for
// the baseline instruction set under the same names, and the linker keeps
// one copy of each, which must not be this file's AVX2 code. Every symbol
// this object shares with others must therefore be Eigen's, renamed
// (tools.dense_front_avx2_symbols checks the object file).
#define Eigen DracoUvEigenAvx2
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "draco_ext/linalg/dense_front_impl.h"

namespace draco {

extern const DenseFrontSteps kDenseFrontStepsAvx2 = kEigenDenseFrontSteps;

}  // namespace draco
