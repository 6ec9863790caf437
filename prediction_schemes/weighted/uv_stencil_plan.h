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
// The stencil plan of one step of a processing order: which stencils and
// known neighbours its entry has, read from the face through which the
// order reaches the entry and the two faces beside it around the entry's
// vertex (Draco's SwingLeft() / SwingRight() of the reach corner).
//
// A face is a stencil of the entry whose corner is processed last (the
// tip); the other two (L, R) are known by then, and so is B, the vertex
// across LR, when it comes before the tip. With the max prediction degree
// order (uv_processing_order.h) a vertex has 1 or 2 stencils as a rule, and
// they are its reach face and a face beside it: on the test corpus, looking
// at every face around the vertex changes the sizes by under 0.1 %, but
// costs about twice the instructions.
//
// Corner indices differ between Draco's encoder and decoder, the topology
// does not, so both find the same lists in the same order.
#ifndef PREDICTION_SCHEMES_WEIGHTED_UV_STENCIL_PLAN_H_
#define PREDICTION_SCHEMES_WEIGHTED_UV_STENCIL_PLAN_H_

#include <cstdint>

#include "draco_ext/common/uv_corner_graph.h"
#include "prediction_schemes/weighted/uv_processing_order.h"

namespace draco {

// The stencils and known neighbours of one step.
struct UvStencilPlan {
  struct Stencil {
    int32_t l, r;
    int32_t b;  // UvCornerGraph::kNone when B is unknown at the tip's step.
  };
  static constexpr int kMaxStencils = 3;
  static constexpr int kMaxNeighbours = 4;

  Stencil stencils[kMaxStencils];
  int32_t neighbours[kMaxNeighbours];
  int num_stencils;
  int num_neighbours;
};

// Builds the plans of the steps of |order| over |graph| (both must outlive
// it); Build() may run on several threads at once.
class UvStencilPlanner {
 public:
  UvStencilPlanner(const UvCornerGraph &graph, const UvProcessingOrder &order)
      : graph_(graph), order_(order) {}

  // The plan of |step|: the reach face, then the faces beside it across
  // the reach corner's previous and next edges. The neighbours are the
  // known vertices of those faces other than the tip, each once unless the
  // fan has only three faces.
  void Build(int step, UvStencilPlan *plan) const {
    using G = UvCornerGraph;
    plan->num_stencils = plan->num_neighbours = 0;
    const int32_t start = order_.corners[step];
    if (start < 0 || start >= graph_.num_corners() ||
        !IsAt(start, step)) {
      return;  // A face dropped by BuildUvCornerGraph().
    }
    const bool next_known = IsKnown(G::Next(start), step);
    const bool previous_known = IsKnown(G::Previous(start), step);
    AddFace(start, next_known, previous_known, step, plan);
    AddNeighbour(G::Next(start), next_known, plan);
    AddNeighbour(G::Previous(start), previous_known, plan);
    const int32_t left = graph_.SwingLeft(start);
    if (left != G::kNone && left != start && IsAt(left, step)) {
      const bool far_known = IsKnown(G::Previous(left), step);
      AddFace(left, previous_known, far_known, step, plan);
      AddNeighbour(G::Previous(left), far_known, plan);
    }
    const int32_t right = graph_.SwingRight(start);
    if (right != G::kNone && right != start && right != left &&
        IsAt(right, step)) {
      const bool far_known = IsKnown(G::Next(right), step);
      AddFace(right, far_known, next_known, step, plan);
      AddNeighbour(G::Next(right), far_known, plan);
    }
  }

 private:
  // True when |corner|'s entry is the one at |step| (false only for corrupt
  // connectivity, where a swing may leave the vertex).
  bool IsAt(int32_t corner, int step) const {
    return graph_.entry[corner] == order_.entries[step];
  }

  bool IsKnown(int32_t corner, int step) const {
    const int32_t entry = graph_.entry[corner];
    return entry != UvCornerGraph::kNone && order_.rank[entry] < step;
  }

  void AddNeighbour(int32_t corner, bool known, UvStencilPlan *plan) const {
    if (known) {
      plan->neighbours[plan->num_neighbours++] = graph_.entry[corner];
    }
  }

  // The face of |corner|, whose vertex is the tip, if L (its next corner's)
  // and R (its previous corner's) are known and distinct.
  void AddFace(int32_t corner, bool l_known, bool r_known, int step,
               UvStencilPlan *plan) const {
    if (!l_known || !r_known) {
      return;
    }
    const int32_t l = graph_.entry[UvCornerGraph::Next(corner)];
    const int32_t r = graph_.entry[UvCornerGraph::Previous(corner)];
    if (l == r) {
      return;
    }
    const int32_t opposite = graph_.opposite[corner];
    const int32_t b =
        opposite != UvCornerGraph::kNone && IsKnown(opposite, step)
            ? graph_.entry[opposite]
            : UvCornerGraph::kNone;
    plan->stencils[plan->num_stencils++] = {l, r, b};
  }

  const UvCornerGraph &graph_;
  const UvProcessingOrder &order_;
};

}  // namespace draco

#endif  // PREDICTION_SCHEMES_WEIGHTED_UV_STENCIL_PLAN_H_
