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
#include "draco_ext/uv_seam_topology.h"

namespace draco {

bool UvSeamTopology::Init(const std::vector<int32_t> &opposite) {
  opposite_ = opposite;
  if (!IsValidPairing()) {
    return false;
  }
  NumberEdges();
  BuildFans();
  return true;
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
    const int32_t sides[2] = {edge_corner_[edge],
                              opposite_[edge_corner_[edge]]};
    for (int side = 0; side < 2; ++side) {
      wings_[edge][2 * side] = corner_edge_[Next(sides[side])];
      wings_[edge][2 * side + 1] = corner_edge_[Previous(sides[side])];
    }
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
  for (int32_t corner = 0; corner < num_corners(); ++corner) {
    if (corner_vertex_[corner] < 0) {
      AddFan(corner);
    }
  }
}

void UvSeamTopology::AddFan(int32_t corner) {
  // With a symmetric pairing, swinging is a bijection between corners of a
  // fan, so walking left either returns to |corner| or stops at a boundary.
  int32_t first = corner;
  bool open = false;
  for (int32_t left = SwingLeft(corner); left != corner;
       left = SwingLeft(left)) {
    if (left == kBoundary) {
      open = true;
      break;
    }
    first = left;
  }
  if (!open) {
    first = corner;
  }
  const int32_t vertex = static_cast<int32_t>(is_open_.size());
  is_open_.push_back(open);
  if (open) {
    ring_.push_back(corner_edge_[Next(first)]);  // The boundary edge.
  }
  int32_t current = first;
  do {
    corner_vertex_[current] = vertex;
    ring_.push_back(corner_edge_[Previous(current)]);
    current = SwingRight(current);
  } while (current != kBoundary && current != first);
  ring_begin_.push_back(static_cast<int32_t>(ring_.size()));
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
