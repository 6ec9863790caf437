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
#include "draco_ext/seams/uv_seam_topology.h"

#include <cstddef>

namespace draco {

bool UvSeamTopology::Init(const std::vector<int32_t> &opposite) {
  opposite_ = opposite;
  if (!IsValidPairing()) {
    return false;
  }
  NumberEdges();
  BuildFans();
  return ConnectVertices();
}

bool UvSeamTopology::IsValidPairing() const {
  const int32_t num_corners = static_cast<int32_t>(opposite_.size());
  if (num_corners % 3 != 0) {
    return false;
  }
  for (int32_t corner = 0; corner < num_corners; ++corner) {
    const int32_t other = opposite_[corner];
    if (other == kBoundary) {
      continue;
    }
    if (other < 0 || other >= num_corners || other / 3 == corner / 3 ||
        opposite_[other] != corner) {
      return false;
    }
  }
  return true;
}

void UvSeamTopology::NumberEdges() {
  corner_edge_.assign(opposite_.size(), kBoundary);
  edge_corner_.clear();
  for (int32_t corner = 0; corner < num_corners(); ++corner) {
    const int32_t other = opposite_[corner];
    if (other > corner) {
      corner_edge_[corner] = corner_edge_[other] =
          static_cast<int32_t>(edge_corner_.size());
      edge_corner_.push_back(corner);
    }
  }
  wings_.resize(edge_corner_.size());
  for (int32_t edge = 0; edge < num_edges(); ++edge) {
    const int32_t corner = edge_corner_[edge];
    const int32_t other = opposite_[corner];
    wings_[edge] = {corner_edge_[Next(corner)], corner_edge_[Previous(corner)],
                    corner_edge_[Next(other)], corner_edge_[Previous(other)]};
  }
}

int32_t UvSeamTopology::SwingLeft(int32_t corner) const {
  const int32_t other = opposite_[Next(corner)];
  return other == kBoundary ? kBoundary : Next(other);
}

int32_t UvSeamTopology::SwingRight(int32_t corner) const {
  const int32_t other = opposite_[Previous(corner)];
  return other == kBoundary ? kBoundary : Previous(other);
}

void UvSeamTopology::BuildFans() {
  corner_vertex_.assign(opposite_.size(), -1);
  ring_begin_.assign(1, 0);
  ring_.clear();
  is_open_.clear();
  interior_degree_.clear();
  // One entry per corner, plus one per open fan.
  ring_.reserve(opposite_.size() + opposite_.size() / 4);
  ring_begin_.reserve(opposite_.size() / 4);
  is_open_.reserve(opposite_.size() / 4);
  interior_degree_.reserve(opposite_.size() / 4);
  for (int32_t corner = 0; corner < num_corners(); ++corner) {
    if (corner_vertex_[corner] < 0) {
      AddFan(corner);
    }
  }
}

void UvSeamTopology::AddFan(int32_t corner) {
  const int32_t vertex = static_cast<int32_t>(is_open_.size());
  const size_t ring_start = ring_.size();
  // With a symmetric pairing, swinging is a bijection between the corners of
  // a fan: walking right either returns to |corner| (a closed fan) or stops
  // at a boundary, and then the fan starts further left.
  int32_t current = corner;
  do {
    ring_.push_back(corner_edge_[Previous(current)]);
    current = SwingRight(current);
  } while (current != kBoundary && current != corner);
  const bool open = current == kBoundary;
  int32_t first = corner;
  if (open) {
    for (int32_t left = SwingLeft(corner); left != kBoundary;
         left = SwingLeft(left)) {
      first = left;
    }
    ring_.resize(ring_start);
    ring_.push_back(corner_edge_[Next(first)]);  // The boundary edge.
    for (current = first; current != kBoundary; current = SwingRight(current)) {
      ring_.push_back(corner_edge_[Previous(current)]);
    }
  }
  int interior = 0;
  for (size_t i = ring_start; i < ring_.size(); ++i) {
    interior += ring_[i] != kBoundary;
  }
  // Corners of the fan, in ring order.
  current = first;
  do {
    corner_vertex_[current] = vertex;
    current = SwingRight(current);
  } while (current != kBoundary && current != first);
  is_open_.push_back(open);
  interior_degree_.push_back(interior);
  ring_begin_.push_back(static_cast<int32_t>(ring_.size()));
}

bool UvSeamTopology::ConnectVertices() {
  edge_vertices_.resize(2 * edge_corner_.size());
  for (int32_t edge = 0; edge < num_edges(); ++edge) {
    const int32_t corner = edge_corner_[edge];
    edge_vertices_[2 * edge] = corner_vertex_[Next(corner)];
    edge_vertices_[2 * edge + 1] = corner_vertex_[Previous(corner)];
    if (edge_vertices_[2 * edge] == edge_vertices_[2 * edge + 1]) {
      return false;  // Only corrupt connectivity joins a vertex to itself.
    }
  }
  ring_neighbor_.resize(ring_.size());
  for (int32_t vertex = 0; vertex < num_vertices(); ++vertex) {
    for (int32_t i = ring_begin_[vertex]; i < ring_begin_[vertex + 1]; ++i) {
      const int32_t edge = ring_[i];
      if (edge == kBoundary) {
        ring_neighbor_[i] = kBoundary;
      } else {
        const int32_t end0 = edge_vertices_[2 * edge];
        ring_neighbor_[i] =
            end0 == vertex ? edge_vertices_[2 * edge + 1] : end0;
      }
    }
  }
  return true;
}

std::vector<int32_t> UvSeamTopology::DracoSeamOrder() const {
  std::vector<int32_t> order;
  order.reserve(edge_corner_.size());
  for (int32_t corner = 0; corner < num_corners(); ++corner) {
    const int32_t other = opposite_[corner];
    if (other != kBoundary && other / 3 >= corner / 3) {
      order.push_back(corner_edge_[corner]);
    }
  }
  return order;
}

}  // namespace draco
