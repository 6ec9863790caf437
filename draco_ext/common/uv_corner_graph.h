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
// A flat copy of an attribute's texture connectivity for the hot loops of
// the draco-uv prediction schemes: per corner the attribute entry of its
// vertex and its opposite corner (none across seams and boundaries), read
// once from the scheme's corner table. Walking these arrays is several
// times cheaper than the generic corner table interface.
#ifndef DRACO_EXT_COMMON_UV_CORNER_GRAPH_H_
#define DRACO_EXT_COMMON_UV_CORNER_GRAPH_H_

#include <cstdint>
#include <vector>

#include "draco/attributes/geometry_indices.h"
#include "draco/mesh/corner_table.h"
#include "draco/mesh/mesh_attribute_corner_table.h"

namespace draco {

struct UvCornerGraph {
  static constexpr int32_t kNone = -1;

  std::vector<int32_t> entry;     // Attribute entry of the corner's vertex.
  std::vector<int32_t> opposite;  // Opposite corner, kNone if absent.

  int num_corners() const { return static_cast<int>(entry.size()); }
  int num_faces() const { return num_corners() / 3; }
  static int32_t Next(int32_t corner) {
    return corner % 3 == 2 ? corner - 2 : corner + 1;
  }
  static int32_t Previous(int32_t corner) {
    return corner % 3 == 0 ? corner + 2 : corner - 1;
  }
  int32_t Opposite(int32_t corner) const {
    return corner == kNone ? kNone : opposite[corner];
  }
  // Draco's CornerTable::SwingLeft() / SwingRight() around the corner's
  // vertex; kNone at a boundary or seam.
  int32_t SwingLeft(int32_t corner) const {
    const int32_t o = opposite[Next(corner)];
    return o == kNone ? kNone : Next(o);
  }
  int32_t SwingRight(int32_t corner) const {
    const int32_t o = opposite[Previous(corner)];
    return o == kNone ? kNone : Previous(o);
  }
  // Draco's GetLeftCorner() / GetRightCorner().
  int32_t LeftCorner(int32_t corner) const {
    return opposite[Previous(corner)];
  }
  int32_t RightCorner(int32_t corner) const { return opposite[Next(corner)]; }
};

namespace uv_corner_graph_internal {

// The position connectivity, in which Draco's encoder drops degenerate faces.
inline const CornerTable &PositionTable(const CornerTable &table) {
  return table;
}
inline const CornerTable &PositionTable(const MeshAttributeCornerTable &table) {
  return *table.corner_table();
}

}  // namespace uv_corner_graph_internal

// Copies the connectivity of |mesh_data| (a MeshPredictionSchemeData).
// Entries outside [0, number of entries) become kNone. So do all corners of
// faces that are degenerate in the position connectivity (two corners on one
// position vertex): Draco's edgebreaker encoder drops those faces, so the
// decoder never sees them, and neither may the encoder's predictions.
template <class MeshDataT>
void BuildUvCornerGraph(const MeshDataT &mesh_data, UvCornerGraph *graph) {
  const auto &table = *mesh_data.corner_table();
  const auto &vertex_to_entry = *mesh_data.vertex_to_data_map();
  const int32_t num_entries =
      static_cast<int32_t>(mesh_data.data_to_corner_map()->size());
  const int num_corners = table.num_corners();
  // One degeneracy test per face, read by each of its corners and by its
  // opposite corners: CornerTable::IsDegenerated() inlined (it is not).
  const CornerTable &positions = uv_corner_graph_internal::PositionTable(table);
  std::vector<uint8_t> dropped(num_corners / 3);
  for (int f = 0; f < num_corners / 3; ++f) {
    const VertexIndex v0 = positions.Vertex(CornerIndex(3 * f));
    const VertexIndex v1 = positions.Vertex(CornerIndex(3 * f + 1));
    const VertexIndex v2 = positions.Vertex(CornerIndex(3 * f + 2));
    dropped[f] = v0 == v1 || v0 == v2 || v1 == v2;
  }
  graph->entry.resize(num_corners);
  graph->opposite.resize(num_corners);
  for (int c = 0; c < num_corners; ++c) {
    const CornerIndex corner(c);
    graph->entry[c] = graph->opposite[c] = UvCornerGraph::kNone;
    if (dropped[c / 3]) {
      continue;
    }
    const VertexIndex v = table.Vertex(corner);
    int32_t entry = UvCornerGraph::kNone;
    if (v != kInvalidVertexIndex && v.value() < vertex_to_entry.size()) {
      entry = vertex_to_entry[v.value()];
    }
    if (entry >= 0 && entry < num_entries) {
      graph->entry[c] = entry;
    }
    const CornerIndex opposite = table.Opposite(corner);
    if (opposite != kInvalidCornerIndex && opposite.value() < num_corners &&
        !dropped[opposite.value() / 3]) {
      graph->opposite[c] = static_cast<int32_t>(opposite.value());
    }
  }
}

}  // namespace draco

#endif  // DRACO_EXT_COMMON_UV_CORNER_GRAPH_H_
