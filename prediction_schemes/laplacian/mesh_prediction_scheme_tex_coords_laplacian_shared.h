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
// Constants and helpers shared by the encoder and the decoder of
// MESH_PREDICTION_TEX_COORDS_LAPLACIAN, the Laplacian texture coordinate
// coder of [Váša & Brunnett 2014] L. Váša, G. Brunnett: Efficient encoding
// of texture coordinates guided by mesh geometry. CGF 33(5), section 5.
#ifndef PREDICTION_SCHEMES_LAPLACIAN_MESH_PREDICTION_SCHEME_TEX_COORDS_LAPLACIAN_SHARED_H_
#define PREDICTION_SCHEMES_LAPLACIAN_MESH_PREDICTION_SCHEME_TEX_COORDS_LAPLACIAN_SHARED_H_

#include <array>
#include <cstdint>

#include "draco/attributes/point_attribute.h"
#include "draco_ext/common/uv_corner_graph.h"
#include "prediction_schemes/laplacian/uv_laplacian_mesh.h"

namespace draco {

// Version of the scheme's prediction data; decoders reject other values.
constexpr uint8_t kTexCoordsLaplacianFormatVersion = 4;

// The coder's view of one texture coordinate attribute: one texture vertex
// per attribute entry, at the 3D position of the entry's point, and the
// faces whose three corners have valid entries.
template <class MeshDataT>
UvLaplacianMesh BuildUvLaplacianMesh(const MeshDataT &mesh_data,
                                     const PointAttribute &positions,
                                     const PointIndex *entry_to_point_id_map) {
  UvCornerGraph graph;
  BuildUvCornerGraph(mesh_data, &graph);
  UvLaplacianMesh mesh;
  const int num_entries =
      static_cast<int>(mesh_data.data_to_corner_map()->size());
  mesh.positions.resize(num_entries);
  for (int entry = 0; entry < num_entries; ++entry) {
    std::array<int64_t, 3> value;
    positions.ConvertValue(
        positions.mapped_index(entry_to_point_id_map[entry]), 3,
        value.data());
    for (int c = 0; c < 3; ++c) {
      mesh.positions[entry][c] = static_cast<double>(value[c]);
    }
  }
  for (int f = 0; f < graph.num_faces(); ++f) {
    const std::array<int, 3> face = {graph.entry[3 * f],
                                     graph.entry[3 * f + 1],
                                     graph.entry[3 * f + 2]};
    if (face[0] != UvCornerGraph::kNone && face[1] != UvCornerGraph::kNone &&
        face[2] != UvCornerGraph::kNone) {
      mesh.faces.push_back(face);
    }
  }
  return mesh;
}

// The parent attribute must be the integer (quantised) 3D position.
inline bool IsLaplacianPositionAttribute(const PointAttribute *att) {
  return att != nullptr &&
         att->attribute_type() == GeometryAttribute::POSITION &&
         att->num_components() == 3 && IsDataTypeIntegral(att->data_type());
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_LAPLACIAN_MESH_PREDICTION_SCHEME_TEX_COORDS_LAPLACIAN_SHARED_H_
