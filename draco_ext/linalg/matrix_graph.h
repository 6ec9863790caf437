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
// The graph of a sparse symmetric matrix's pattern, the common input of the
// code that builds such matrices (uv_laplacian_operator.h) and the code that
// orders and factorises them (sparse_cholesky.h).
#ifndef DRACO_EXT_LINALG_MATRIX_GRAPH_H_
#define DRACO_EXT_LINALG_MATRIX_GRAPH_H_

#include <vector>

namespace draco {

// The graph of a symmetric matrix's pattern, compressed: the neighbours of
// unknown u are neighbour[start[u]] .. neighbour[start[u + 1] - 1], and
// |start| holds size() + 1 ascending offsets (an empty graph is start {0}).
// A plain container: nothing checks that the pattern is symmetric, which
// its users require.
struct MatrixGraph {
  std::vector<int> start;
  std::vector<int> neighbour;
  int size() const { return static_cast<int>(start.size()) - 1; }
};

}  // namespace draco

#endif  // DRACO_EXT_LINALG_MATRIX_GRAPH_H_
