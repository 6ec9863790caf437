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
// The portable build of FactorDenseFront()'s steps, for the baseline
// instruction set.
//
// Eigen is renamed here so that the fixed cache sizes this build sets
// (dense_front_impl.h) are its own: the application's Eigen, and ours
// elsewhere, keep the sizes they read from the CPU.
#define Eigen DracoUvEigenPortable
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "draco_ext/linalg/dense_front_impl.h"

namespace draco {

extern const DenseFrontSteps kDenseFrontStepsPortable = kEigenDenseFrontSteps;

}  // namespace draco
