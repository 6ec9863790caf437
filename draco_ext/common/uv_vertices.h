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
// UV vertices: the entries Draco codes (and a decoder predicts) one by one
// for a texture coordinate attribute.
#ifndef DRACO_EXT_COMMON_UV_VERTICES_H_
#define DRACO_EXT_COMMON_UV_VERTICES_H_

#include <algorithm>
#include <cstdint>
#include <vector>

#include "draco/mesh/mesh.h"

namespace draco {

// Distinct pairs of position and |uv| value over the points of |mesh|
// (positions alone if the mesh has none).
inline int64_t NumUvVertices(const Mesh &mesh, const PointAttribute &uv) {
  const PointAttribute *const position =
      mesh.GetNamedAttribute(GeometryAttribute::POSITION);
  std::vector<uint64_t> pairs(mesh.num_points());
  for (PointIndex p(0); p < mesh.num_points(); ++p) {
    const uint64_t pos =
        position == nullptr ? 0 : position->mapped_index(p).value();
    pairs[p.value()] = (pos << 32) | uv.mapped_index(p).value();
  }
  std::sort(pairs.begin(), pairs.end());
  return std::unique(pairs.begin(), pairs.end()) - pairs.begin();
}

}  // namespace draco

#endif  // DRACO_EXT_COMMON_UV_VERTICES_H_
