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
// Which stencils and known neighbours every entry has, for a given
// processing order, computed in two linear passes over the faces and edges
// instead of swinging around every vertex while decoding.
//
// A face is a stencil of exactly one entry: its corner processed last (the
// tip); the other two (L, R) are known by then, and so is B, the vertex
// across LR, when it comes before the tip. An edge makes its earlier end a
// known neighbour of its later end.
//
// Lists are stored per step (compressed rows). Their order depends on face
// indices, which Draco's encoder and decoder do not share, so users must
// only compute order-independent functions of them (sums, minima, counts)
// unless they sort first.
#ifndef DRACO_EXT_WEIGHTED_UV_STENCIL_PLAN_H_
#define DRACO_EXT_WEIGHTED_UV_STENCIL_PLAN_H_

#include <cstdint>
#include <vector>

#include "draco_ext/common/uv_corner_graph.h"
#include "draco_ext/weighted/uv_processing_order.h"

namespace draco {

struct UvStencilPlan {
  struct Stencil {
    int32_t l, r;
    int32_t b;  // UvCornerGraph::kNone when B is unknown at the tip's step.
  };

  // Rows by step: stencils[stencil_begin[s] .. stencil_begin[s + 1]), and
  // likewise for neighbours.
  std::vector<int32_t> stencil_begin;
  std::vector<Stencil> stencils;
  std::vector<int32_t> neighbour_begin;
  std::vector<int32_t> neighbours;
};

namespace uv_plan_internal {

// Counts per row, then turns the counts into row starts.
inline void CountsToStarts(std::vector<int32_t> *begin) {
  int32_t sum = 0;
  for (int32_t &value : *begin) {
    const int32_t count = value;
    value = sum;
    sum += count;
  }
}

// The face's corner with the latest step, or kNone when the face has an
// invalid or repeated entry.
inline int32_t LastCorner(const UvCornerGraph &graph,
                          const UvProcessingOrder &order, int32_t face) {
  int32_t last = UvCornerGraph::kNone;
  int32_t last_rank = -1;
  for (int32_t c = 3 * face; c < 3 * face + 3; ++c) {
    const int32_t entry = graph.entry[c];
    if (entry == UvCornerGraph::kNone || order.rank[entry] == last_rank) {
      return UvCornerGraph::kNone;
    }
    if (order.rank[entry] > last_rank) {
      last_rank = order.rank[entry];
      last = c;
    }
  }
  return last;
}

}  // namespace uv_plan_internal

inline void BuildStencils(const UvCornerGraph &graph,
                          const UvProcessingOrder &order,
                          UvStencilPlan *plan) {
  using uv_plan_internal::LastCorner;
  const int num_steps = static_cast<int>(order.entries.size());
  std::vector<int32_t> tips(graph.num_faces());
  plan->stencil_begin.assign(num_steps + 1, 0);
  for (int32_t f = 0; f < graph.num_faces(); ++f) {
    tips[f] = LastCorner(graph, order, f);
    if (tips[f] != UvCornerGraph::kNone) {
      ++plan->stencil_begin[order.rank[graph.entry[tips[f]]]];
    }
  }
  uv_plan_internal::CountsToStarts(&plan->stencil_begin);
  plan->stencils.resize(plan->stencil_begin[num_steps]);
  std::vector<int32_t> fill(plan->stencil_begin.begin(),
                            plan->stencil_begin.end() - 1);
  for (int32_t f = 0; f < graph.num_faces(); ++f) {
    const int32_t tip = tips[f];
    if (tip == UvCornerGraph::kNone) {
      continue;
    }
    const int32_t step = order.rank[graph.entry[tip]];
    const int32_t opposite = graph.opposite[tip];
    int32_t b = opposite == UvCornerGraph::kNone ? UvCornerGraph::kNone
                                                 : graph.entry[opposite];
    if (b != UvCornerGraph::kNone && order.rank[b] >= step) {
      b = UvCornerGraph::kNone;
    }
    plan->stencils[fill[step]++] = {graph.entry[UvCornerGraph::Next(tip)],
                                    graph.entry[UvCornerGraph::Previous(tip)],
                                    b};
  }
}

inline void BuildNeighbours(const UvCornerGraph &graph,
                            const UvProcessingOrder &order,
                            UvStencilPlan *plan) {
  const int num_steps = static_cast<int>(order.entries.size());
  // Every edge once: from the corner opposite it with the smaller index.
  const auto for_each_edge = [&](auto visit) {
    for (int32_t c = 0; c < graph.num_corners(); ++c) {
      const int32_t opposite = graph.opposite[c];
      if (opposite != UvCornerGraph::kNone && opposite < c) {
        continue;
      }
      const int32_t a = graph.entry[UvCornerGraph::Next(c)];
      const int32_t b = graph.entry[UvCornerGraph::Previous(c)];
      if (a != UvCornerGraph::kNone && b != UvCornerGraph::kNone && a != b) {
        // The later end gets the earlier one.
        if (order.rank[a] > order.rank[b]) {
          visit(order.rank[a], b);
        } else {
          visit(order.rank[b], a);
        }
      }
    }
  };
  plan->neighbour_begin.assign(num_steps + 1, 0);
  for_each_edge([&](int32_t step, int32_t) { ++plan->neighbour_begin[step]; });
  uv_plan_internal::CountsToStarts(&plan->neighbour_begin);
  plan->neighbours.resize(plan->neighbour_begin[num_steps]);
  std::vector<int32_t> fill(plan->neighbour_begin.begin(),
                            plan->neighbour_begin.end() - 1);
  for_each_edge([&](int32_t step, int32_t earlier) {
    plan->neighbours[fill[step]++] = earlier;
  });
}

// Builds both lists for |order| over |graph|.
inline void BuildUvStencilPlan(const UvCornerGraph &graph,
                               const UvProcessingOrder &order,
                               UvStencilPlan *plan) {
  BuildStencils(graph, order, plan);
  BuildNeighbours(graph, order, plan);
}

}  // namespace draco

#endif  // DRACO_EXT_WEIGHTED_UV_STENCIL_PLAN_H_
