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
// The order in which a prediction scheme visits its attribute entries. A
// scheme may predict entries in any order that the decoder can reproduce from
// the connectivity alone; Draco's correction array keeps its own order.
//
// Based on Draco's MaxPredictionDegreeTraverser (the traversal Draco uses for
// positions at -cl 10): a vertex is predicted when many of its neighbours
// are known, so that multi-stencil predictors see more stencils.
#ifndef PREDICTION_SCHEMES_WEIGHTED_UV_PROCESSING_ORDER_H_
#define PREDICTION_SCHEMES_WEIGHTED_UV_PROCESSING_ORDER_H_

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "draco/attributes/geometry_indices.h"
#include "draco_ext/common/uv_corner_graph.h"

namespace draco {

// Entries in processing order, the corner (of a UvCornerGraph) through which
// each is reached, i.e. its tip corner in a face whose other vertices come
// first, and the inverse permutation.
struct UvProcessingOrder {
  std::vector<int32_t> entries;
  std::vector<int32_t> corners;
  std::vector<int32_t> rank;  // rank[entry]: position of |entry| in |entries|.

  void Reset(int num_entries) {
    entries.clear();
    corners.clear();
    entries.reserve(num_entries);
    corners.reserve(num_entries);
    rank.assign(num_entries, -1);
  }
  bool IsPlaced(int32_t entry) const { return rank[entry] >= 0; }
  // Appends |entry| unless it is kNone or already placed.
  void Add(int32_t entry, int32_t corner) {
    if (entry == UvCornerGraph::kNone || IsPlaced(entry)) {
      return;
    }
    rank[entry] = static_cast<int32_t>(entries.size());
    entries.push_back(entry);
    corners.push_back(corner);
  }
};

// Draco's own order: entry p, reached through the corner Draco recorded.
inline void BuildDataOrder(const std::vector<CornerIndex> &data_to_corner,
                           UvProcessingOrder *order) {
  order->Reset(static_cast<int>(data_to_corner.size()));
  for (int p = 0; p < static_cast<int>(data_to_corner.size()); ++p) {
    order->Add(p, static_cast<int32_t>(data_to_corner[p].value()));
  }
}

namespace uv_order_internal {

// MaxPredictionDegreeTraverser over a UvCornerGraph, emitting (entry,
// corner) pairs. Unlike Draco's traverser it also crosses the start face's
// third edge: Draco never follows Opposite(start corner), which splits a
// chart into pieces that restart without any stencil whenever the start
// face is not on the chart's border.
class MaxDegreeTraversal {
 public:
  MaxDegreeTraversal(const UvCornerGraph &graph, UvProcessingOrder *order)
      : graph_(graph),
        order_(order),
        face_visited_(graph.num_faces(), 0),
        degree_(order->rank.size(), 0) {}

  // Starts a traversal at every corner of |start_corners| whose face is not
  // visited yet. Corner and face indices differ between Draco's encoder and
  // decoder; only the topology and the start corners' order are shared.
  void Run(const std::vector<CornerIndex> &start_corners) {
    for (const CornerIndex start : start_corners) {
      const int32_t corner = static_cast<int32_t>(start.value());
      if (corner < graph_.num_corners() && !IsFaceVisited(corner)) {
        TraverseChartFrom(corner);
      }
    }
  }

 private:
  static constexpr int kMaxPriority = 3;

  bool IsFaceVisited(int32_t corner) const {
    return corner == UvCornerGraph::kNone || face_visited_[corner / 3];
  }

  void VisitVertex(int32_t corner) {
    order_->Add(graph_.entry[corner], corner);
  }

  // Priority 0 for corners whose tip is known, 1 for tips with more than one
  // known neighbour face, 2 otherwise (Draco's ComputePriority()).
  int ComputePriority(int32_t corner) {
    const int32_t entry = graph_.entry[corner];
    if (entry == UvCornerGraph::kNone || order_->IsPlaced(entry)) {
      return 0;
    }
    return ++degree_[entry] > 1 ? 1 : 2;
  }

  void Push(int32_t corner, int priority) {
    stacks_[priority].push_back(corner);
    best_priority_ = std::min(best_priority_, priority);
  }

  int32_t Pop() {
    for (int i = best_priority_; i < kMaxPriority; ++i) {
      if (!stacks_[i].empty()) {
        const int32_t corner = stacks_[i].back();
        stacks_[i].pop_back();
        best_priority_ = i;
        return corner;
      }
    }
    return UvCornerGraph::kNone;
  }

  void TraverseChartFrom(int32_t start) {
    best_priority_ = 0;
    stacks_[0].push_back(start);
    VisitVertex(UvCornerGraph::Next(start));
    VisitVertex(UvCornerGraph::Previous(start));
    VisitVertex(start);
    const int32_t across = graph_.Opposite(start);
    if (across != UvCornerGraph::kNone) {
      Push(across, ComputePriority(across));
    }
    for (int32_t corner = Pop(); corner != UvCornerGraph::kNone;
         corner = Pop()) {
      if (!IsFaceVisited(corner)) {
        GrowFrom(corner);
      }
    }
  }

  // Visits the face of |corner| and keeps walking into a neighbour face
  // while one has the best priority; pushes the others.
  void GrowFrom(int32_t corner) {
    while (true) {
      face_visited_[corner / 3] = 1;
      VisitVertex(corner);
      const int32_t right = graph_.RightCorner(corner);
      const int32_t left = graph_.LeftCorner(corner);
      const bool right_visited = IsFaceVisited(right);
      if (!IsFaceVisited(left)) {
        const int priority = ComputePriority(left);
        if (right_visited && priority <= best_priority_) {
          corner = left;
          continue;
        }
        Push(left, priority);
      }
      if (!right_visited) {
        const int priority = ComputePriority(right);
        if (priority <= best_priority_) {
          corner = right;
          continue;
        }
        Push(right, priority);
      }
      return;
    }
  }

  const UvCornerGraph &graph_;
  UvProcessingOrder *order_;
  std::vector<uint8_t> face_visited_;
  std::vector<int32_t> degree_;
  std::array<std::vector<int32_t>, kMaxPriority> stacks_;
  int best_priority_ = 0;
};

}  // namespace uv_order_internal

// The max prediction degree order over |graph|, starting charts in Draco's
// entry order (|data_to_corner|). Entries the traversal does not reach (none
// for meshes Draco produced) are appended in Draco's order, so every entry
// gets exactly one rank.
inline void BuildMaxDegreeOrder(const UvCornerGraph &graph,
                                const std::vector<CornerIndex> &data_to_corner,
                                UvProcessingOrder *order) {
  order->Reset(static_cast<int>(data_to_corner.size()));
  uv_order_internal::MaxDegreeTraversal(graph, order).Run(data_to_corner);
  for (int p = 0; p < static_cast<int>(data_to_corner.size()); ++p) {
    order->Add(p, static_cast<int32_t>(data_to_corner[p].value()));
  }
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_WEIGHTED_UV_PROCESSING_ORDER_H_
