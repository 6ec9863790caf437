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
// The input of the Laplacian texture coordinate coder: plain arrays, no
// Eigen, so that a decoder can build it without linking the solver (the web
// decoder hands it to the separately loaded Laplacian part).
#ifndef PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_MESH_H_
#define PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_MESH_H_

#include <array>
#include <vector>

namespace draco {

// The texture connectivity of one texture coordinate attribute together with
// the 3D geometry the decoder already has.
struct UvLaplacianMesh {
  // 3D position of every texture vertex.
  std::vector<std::array<double, 3>> positions;
  // Texture vertices of every face; every index is below positions.size().
  std::vector<std::array<int, 3>> faces;
  int num_vertices() const { return static_cast<int>(positions.size()); }
};

}  // namespace draco

#endif  // PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_MESH_H_
