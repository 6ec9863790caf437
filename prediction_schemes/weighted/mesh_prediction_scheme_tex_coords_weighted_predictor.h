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
// Mesh-guided texture coordinate predictor shared by the encoder and the
// decoder of MESH_PREDICTION_TEX_COORDS_WEIGHTED.
//
// Based on:
//   [Váša & Brunnett 2014] L. Váša, G. Brunnett: Efficient encoding of
//     texture coordinates guided by mesh geometry. CGF 33(5), section 4.
//   [Touma & Gotsman 1998] C. Touma, C. Gotsman: Triangle mesh compression.
//     Graphics Interface 1998 (the parallelogram rule).
// The stencil arithmetic is in uv_stencil_geometry.h; the variants beyond
// the paper (stencil averaging, agreement weighting, the per-vertex adaptive
// choice, inferred orientation) were selected by measuring residual entropy
// on real meshes (BENCHMARKS.md).
#ifndef PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_PREDICTOR_H_
#define PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_PREDICTOR_H_

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <tuple>
#include <vector>

#include "draco/attributes/geometry_indices.h"
#include "draco/attributes/point_attribute.h"
#include "draco_ext/common/threads.h"
#include "draco_ext/common/uv_corner_graph.h"
#include "draco_ext/common/uv_residual_coder.h"
#include "prediction_schemes/weighted/mesh_prediction_scheme_tex_coords_weighted_shared.h"
#include "prediction_schemes/weighted/uv_lookahead.h"
#include "prediction_schemes/weighted/uv_processing_order.h"
#include "prediction_schemes/weighted/uv_stencil_geometry.h"
#include "prediction_schemes/weighted/uv_stencil_plan.h"

namespace draco {

// A stencil's unfolded frame, which depends only on the 3D positions;
// |usable| is false for degenerate or extreme 3D stencils.
struct UvComputedFrame {
  UvStencilFrame frame;
  bool usable = false;
};

// Predicts the texture coordinates of the entries (UV vertices) of one
// attribute, in a UvProcessingOrder, from the entries processed before and
// from the quantised 3D positions of all vertices.
//
// Stencils: faces whose tip (last processed vertex) is O and whose other two
// UV vertices L and R are known: up to three (UvStencilPlanner: the face
// through which the order reaches O and its two neighbours around O) or
// (kReach*) the one through which Draco's traversal reaches O. Each stencil gives
//   c  the weighted parallelogram of eq. (3)-(4) when B, the vertex across
//      LR, is known (exact for locally affine parameterisations), else s;
//   s  the similarity (conformal) rule; its side of LR comes from B, else
//      from the opposite vertices of the last step that had any, so no
//      orientation bit is sent;
//   a  the parallelogram vL + vR - vB when B is known.
// Candidates combine the stencils: mean of c and s, mean of c, mean of s,
// and the agreement-weighted mean of (c + s) / 2 (UvAgreementWeight()); the
// reach kinds use c, s, a and the mean of c and s instead. kAdaptive picks, per vertex, the candidate with the
// smallest recent errors (a sum over all vertices so far that decays by
// 15/16 per vertex; it beat the errors at the vertex's own neighbours on 6
// of 7 test meshes, and costs no per-vertex memory); kReachAdaptive does the
// same among c, s and a (without the mean of c and s, corpus UV bytes at
// qt 12 grow by 0.45 % in total, 0.0014 in the median ratio, while each
// candidate costs about 30 instructions per vertex to decode);
// kAgreementWeighted always takes the last one, kReachMean the first.
//
// Also provides the residual context: the bit length (capped at 7) of the
// neighbours' mean residual magnitude; kUvResidualNoNeighbourContext
// without known neighbours (a chart's first vertex) and
// kUvResidualNoStencilContext with neighbours but no stencil (mostly a
// chart's second vertex, whose residual is a UV edge, not a prediction
// error).
//
// Fallbacks: no stencil (the first two vertices of a chart, degenerate
// fans): the latest known neighbour, else the previously processed entry,
// else zero. Stencils with a degenerate 3D edge or extreme coefficients
// predict the midpoint of LR.
//
// Weak on layouts unrelated to the geometry (hand-made, mirrored or packed
// islands) and on chart starts, which are pure deltas; many-chart atlases
// spend a large share of their bits there.
//
// Threads: stencil frames depend only on the connectivity and the
// positions, so RunUvPrediction() computes them (and the reach kinds'
// stencils) ahead on a second thread (UvLookahead) when there are at least
// kMinItemsForLookaheadThread of them, unless set_max_threads(1). The
// predictions are the same either way.
template <typename DataTypeT>
class MeshPredictionSchemeTexCoordsWeightedPredictor {
 public:
  static constexpr int kNumCandidates = 5;

  void SetPositionAttribute(const PointAttribute &position_attribute) {
    pos_attribute_ = &position_attribute;
  }
  void SetEntryToPointIdMap(const PointIndex *map) {
    entry_to_point_id_map_ = map;
  }
  bool IsInitialized() const { return pos_attribute_ != nullptr; }
  // At most this many threads run a prediction pass (RunUvPrediction()).
  void set_max_threads(int max_threads) { max_threads_ = max_threads; }
  int max_threads() const { return max_threads_; }

  typedef UvStencilPlan::Stencil Stencil;

  // Prepares one pass of a multi-stencil kind over the entries of |order|,
  // which must outlive it.
  void Start(UvPredictorKind kind, const UvProcessingOrder &order);
  // Start() for the reach kinds, whose order is Draco's entry order.
  void StartReach(UvPredictorKind kind, int num_entries);

  // The frame of |stencil| with tip |tip|. Reads only the positions cached
  // by Start(), so other threads may call it during a pass.
  UvComputedFrame ComputeFrame(const Stencil &stencil, int32_t tip) const;

  // Computes predicted_value() and context() for the entry at |step| of the
  // order from its stencils and known neighbours (both lists must stay valid
  // until Update()); |data| holds the values of all earlier steps' entries.
  // |frames| holds ComputeFrame() of each of the (at most
  // UvStencilPlan::kMaxStencils) stencils.
  void Predict(int step, const Stencil *stencils, int num_stencils,
               const int32_t *neighbours, int num_neighbours,
               const DataTypeT *data, const UvComputedFrame *frames);

  // Predict() for the reach kinds (after StartReach()) at entry |p|: the
  // candidates of |stencil| and its |frame| when |num_stencils| is 1, else
  // the fallback; the known vertices of |stencil| are the neighbours.
  void PredictReach(int p, const Stencil &stencil, int num_stencils,
                    const UvComputedFrame &frame, const DataTypeT *data);

  // Records the value (now in |data|) and the correction of the entry just
  // predicted at |step|.
  void Update(int step, const DataTypeT *data, const DataTypeT *correction);

  const DataTypeT *predicted_value() const { return predicted_value_; }
  int context() const { return context_; }

 private:
  typedef UvStencilPos Pos;
  typedef UvStencilUv Uv;

  // Indices of the candidates.
  enum {
    kMeanOfBoth = 0,
    kAffineMean = 1,
    kSimilarityMean = 2,
    kParallelogramMean = 3,
    kAgreement = 4
  };
  // kReachAdaptive's candidates: kFirstReachCandidate .. kAgreement - 1.
  static constexpr int kFirstReachCandidate = kAffineMean;

  Uv UvOf(const DataTypeT *data, int32_t entry) const {
    return Uv(data[entry * kUvNumComponents],
              data[entry * kUvNumComponents + 1]);
  }
  const Pos &PositionOf(int32_t entry) const { return positions_[entry]; }
  // Sign of the 2D cross product; 0 also for differences out of the
  // supported range (only in hostile data), which keeps products < 2^41.
  static int SignOfCross(const Uv &a, const Uv &b) {
    if (!IsSupportedUvDifference(a) || !IsSupportedUvDifference(b)) {
      return 0;
    }
    const int64_t cross = a[0] * b[1] - a[1] * b[0];
    return cross > 0 ? 1 : (cross < 0 ? -1 : 0);
  }

  bool IsAdaptive() const {
    return kind_ == UvPredictorKind::kAdaptive ||
           kind_ == UvPredictorKind::kReachAdaptive;
  }
  void CachePositions();
  // Sets positions_ from |value|(entry, component), shifted as documented.
  template <class ValueT>
  void ShiftPositions(ValueT value);
  int OrientationFor(const Uv &f, const Uv &g, bool has_b);
  void PredictStencil(const Stencil &stencil, const UvComputedFrame &frame,
                      const DataTypeT *data, Uv *affine, Uv *similarity);
  void ComputeCandidates(const DataTypeT *data, const UvComputedFrame *frames);
  void ComputeCandidatesOfOneStencil(const UvComputedFrame &frame,
                                     const DataTypeT *data);
  void ComputeFallback(int step, const DataTypeT *data);
  void ComputeReachFallback(int p, const Stencil &stencil,
                            const DataTypeT *data);
  void ComputeReachContext(const Stencil &stencil);
  int ChooseCandidate() const;
  void ComputeContext();

  const PointAttribute *pos_attribute_ = nullptr;
  const PointIndex *entry_to_point_id_map_ = nullptr;
  UvPredictorKind kind_ = UvPredictorKind::kAdaptive;
  int max_threads_ = 2;
  const UvProcessingOrder *order_ = nullptr;
  int num_entries_ = 0;

  // Positions by entry, non-negative and below 2^30 (CachePositions()).
  std::vector<Pos> positions_;
  // Per entry: |correction| summed over both components (saturated).
  std::vector<uint32_t> magnitude_;
  // The candidates the multi-stencil kinds choose from, kMeanOfBoth first;
  // they leave out kParallelogramMean, which the adaptive choice picks for
  // few vertices (corpus sizes +0.1 % with it left out). The reach kinds
  // choose among kFirstReachCandidate .. kAgreement - 1 instead.
  std::array<int, kNumCandidates> active_candidates_ = {};
  int num_active_ = 0;
  // Per candidate: the recent prediction errors, decaying (adaptive kinds).
  std::array<uint64_t, kNumCandidates> recent_error_ = {};
  // Orientation the opposite vertices of the last step that had any gave
  // (+1 before any), and the sum of the current step's.
  int last_orientation_ = 1;
  int step_orientation_sum_ = 0;

  // State of the current step.
  const Stencil *stencils_ = nullptr;
  int num_stencils_ = 0;
  const int32_t *neighbours_ = nullptr;
  int num_neighbours_ = 0;
  std::array<Uv, kNumCandidates> candidates_;  // Rounded to texture units.
  DataTypeT predicted_value_[kUvNumComponents] = {};
  int context_ = 0;
};

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::
    CachePositions() {
  // Positions within [0, 2^30) (Draco's quantised positions up to 30 bits)
  // are used as they are, others shifted by ShiftPositions().
  constexpr uint64_t kLimit = uint64_t{1} << 30;
  positions_.resize(num_entries_);
  if (pos_attribute_->data_type() == DT_INT32) {
    // Decoding: one copy of Draco's portable positions.
    uint32_t spread = 0;
    for (int entry = 0; entry < num_entries_; ++entry) {
      Pos &pos = positions_[entry];
      std::memcpy(pos.data(),
                  pos_attribute_->GetAddress(pos_attribute_->mapped_index(
                      entry_to_point_id_map_[entry])),
                  sizeof(Pos));
      spread |= static_cast<uint32_t>(pos[0]) | static_cast<uint32_t>(pos[1]) |
                static_cast<uint32_t>(pos[2]);
    }
    if (spread >= kLimit) {
      ShiftPositions(
          [&](int entry, int i) { return int64_t{positions_[entry][i]}; });
    }
    return;
  }
  std::vector<std::array<int64_t, 3>> values(num_entries_);
  bool in_range = true;
  for (int entry = 0; entry < num_entries_; ++entry) {
    pos_attribute_->ConvertValue(
        pos_attribute_->mapped_index(entry_to_point_id_map_[entry]), 3,
        values[entry].data());
    for (int i = 0; i < 3; ++i) {
      in_range &= static_cast<uint64_t>(values[entry][i]) < kLimit;
      positions_[entry][i] =
          static_cast<int32_t>(values[entry][i] & (kLimit - 1));
    }
  }
  if (!in_range) {
    ShiftPositions([&](int entry, int i) { return values[entry][i]; });
  }
}

template <typename DataTypeT>
template <class ValueT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::ShiftPositions(
    ValueT value) {
  // Each component minus its minimum; integer attributes of any width fit
  // once shifted below 2^30.
  int64_t min_value[3], max_value[3];
  std::fill(min_value, min_value + 3, std::numeric_limits<int64_t>::max());
  std::fill(max_value, max_value + 3, std::numeric_limits<int64_t>::lowest());
  for (int entry = 0; entry < num_entries_; ++entry) {
    for (int i = 0; i < 3; ++i) {
      min_value[i] = std::min(min_value[i], value(entry, i));
      max_value[i] = std::max(max_value[i], value(entry, i));
    }
  }
  uint64_t range = 0;
  for (int i = 0; i < 3 && num_entries_ > 0; ++i) {
    range = std::max(range, static_cast<uint64_t>(max_value[i] - min_value[i]));
  }
  const int shift = std::max(0, BitLength(range) - 30);
  for (int entry = 0; entry < num_entries_; ++entry) {
    for (int i = 0; i < 3; ++i) {
      positions_[entry][i] =
          static_cast<int32_t>((value(entry, i) - min_value[i]) >> shift);
    }
  }
}

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::Start(
    UvPredictorKind kind, const UvProcessingOrder &order) {
  DRACO_DCHECK(!UsesReachStencil(kind));
  kind_ = kind;
  order_ = &order;
  num_entries_ = static_cast<int>(order.rank.size());
  CachePositions();
  magnitude_.assign(num_entries_, 0);
  active_candidates_ = {kMeanOfBoth, kAffineMean, kSimilarityMean, kAgreement};
  num_active_ = 4;
  recent_error_.fill(0);
  last_orientation_ = 1;
  step_orientation_sum_ = 0;
}

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::StartReach(
    UvPredictorKind kind, int num_entries) {
  DRACO_DCHECK(UsesReachStencil(kind));
  kind_ = kind;
  order_ = nullptr;
  num_entries_ = num_entries;
  CachePositions();
  magnitude_.assign(num_entries_, 0);
  recent_error_.fill(0);
  last_orientation_ = 1;
  step_orientation_sum_ = 0;
}

template <typename DataTypeT>
int MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::OrientationFor(
    const Uv &f, const Uv &g, bool has_b) {
  // Face (O, L, R) has the orientation of face (B, R, L) across LR, whose
  // UV area has the sign of -cross(f, g), f = vR - vL, g = vB - vL. Without
  // B, the orientation the opposite vertices of earlier steps gave. (Within
  // a step the stencils' order differs between encoder and decoder, so a
  // step only accumulates and Update() takes the sign of the sum.)
  if (has_b) {
    const int64_t cross = f[0] * g[1] - f[1] * g[0];
    if (cross != 0) {
      const int orientation = cross > 0 ? -1 : 1;
      step_orientation_sum_ += orientation;
      return orientation;
    }
  }
  return last_orientation_;
}

template <typename DataTypeT>
UvComputedFrame
MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::ComputeFrame(
    const Stencil &stencil, int32_t tip) const {
  const bool has_b = stencil.b != UvCornerGraph::kNone;
  UvComputedFrame result;
  result.usable = ComputeUvStencilFrame(
      PositionOf(stencil.l), PositionOf(stencil.r), PositionOf(tip),
      PositionOf(has_b ? stencil.b : stencil.l), has_b, &result.frame);
  return result;
}

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::PredictStencil(
    const Stencil &stencil, const UvComputedFrame &frame, const DataTypeT *data,
    Uv *affine, Uv *similarity) {
  const Uv uv_l = UvOf(data, stencil.l);
  const Uv uv_r = UvOf(data, stencil.r);
  const bool has_b = stencil.b != UvCornerGraph::kNone;
  const Uv f = uv_r - uv_l;
  const Uv g = has_b ? UvOf(data, stencil.b) - uv_l : Uv(0, 0);
  // Checking f and g first also bounds the cross product in
  // OrientationFor() below 2^41.
  if (!IsSupportedUvDifference(f) || !IsSupportedUvDifference(g) ||
      !frame.usable) {
    *similarity = *affine = PredictMidpointQ16(uv_l, uv_r);
    return;
  }
  *similarity = ClampPredictionQ16(
      PredictSimilarityQ16(frame.frame, uv_l, f, OrientationFor(f, g, has_b)));
  *affine = frame.frame.has_opposite
                ? ClampPredictionQ16(PredictAffineQ16(frame.frame, uv_l, f, g))
                : *similarity;
}

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::
    ComputeCandidates(const DataTypeT *data, const UvComputedFrame *frames) {
  if (num_stencils_ == 1) {
    ComputeCandidatesOfOneStencil(frames[0], data);
    return;
  }
  // Only the multi-stencil kinds have several stencils. The mean
  // parallelogram is not one of their candidates (active_candidates_).
  DRACO_DCHECK(!UsesReachStencil(kind_));
  Uv affine_sum(0, 0), similarity_sum(0, 0), agreement_sum(0, 0);
  int64_t weight_sum = 0;
  for (int i = 0; i < num_stencils_; ++i) {
    Uv affine, similarity;
    PredictStencil(stencils_[i], frames[i], data, &affine, &similarity);
    affine_sum = affine_sum + affine;
    similarity_sum = similarity_sum + similarity;
    const int64_t weight = UvAgreementWeight(affine, similarity);
    weight_sum += weight;
    agreement_sum = agreement_sum + (affine + similarity) / 2 * weight;
  }
  candidates_[kMeanOfBoth] =
      UvMeanOfQ16(affine_sum + similarity_sum, 2 * num_stencils_);
  candidates_[kAgreement] =
      weight_sum > 0
          ? Uv(RoundedDivide(agreement_sum[0], weight_sum * kUvStencilOne),
               RoundedDivide(agreement_sum[1], weight_sum * kUvStencilOne))
          : candidates_[kMeanOfBoth];
  if (!IsAdaptive()) {
    return;
  }
  candidates_[kAffineMean] = UvMeanOfQ16(affine_sum, num_stencils_);
  candidates_[kSimilarityMean] = UvMeanOfQ16(similarity_sum, num_stencils_);
}

// ComputeCandidates() for a single stencil (every vertex of the reach kinds
// that has one), without the sums: each mean is the stencil's own
// prediction, the agreement-weighted mean is the mean of both (the weight
// cancels: round(((a + s) / 2) w / (w 2^16)) = round((a + s) / 2^17)), and
// the parallelogram vL + vR - vB needs no rounding. Unlike PredictStencil(),
// no clamps: one stencil's Q16 predictions stay below 2^54
// (uv_stencil_geometry.h). Only the candidates the kind chooses from.
template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<
    DataTypeT>::ComputeCandidatesOfOneStencil(const UvComputedFrame &frame,
                                              const DataTypeT *data) {
  const Stencil &stencil = stencils_[0];
  const bool has_b = stencil.b != UvCornerGraph::kNone;
  const Uv uv_l = UvOf(data, stencil.l);
  const Uv uv_r = UvOf(data, stencil.r);
  const Uv uv_b = has_b ? UvOf(data, stencil.b) : uv_l;
  const Uv f = uv_r - uv_l;
  const Uv g = uv_b - uv_l;
  Uv affine, similarity;
  // Checking f and g first also bounds the cross product in
  // OrientationFor() below 2^41.
  if (!frame.usable || !IsSupportedUvDifference(f) ||
      !IsSupportedUvDifference(g)) {
    affine = similarity = PredictMidpointQ16(uv_l, uv_r);
  } else {
    similarity =
        PredictSimilarityQ16(frame.frame, uv_l, f, OrientationFor(f, g, has_b));
    affine = frame.frame.has_opposite
                 ? PredictAffineQ16(frame.frame, uv_l, f, g)
                 : similarity;
  }
  Uv mean;
  for (int i = 0; i < 2; ++i) {
    mean[i] = RoundedShiftUp(affine[i] + similarity[i], 17);
  }
  if (kind_ != UvPredictorKind::kReachAdaptive) {
    candidates_[kMeanOfBoth] = candidates_[kAgreement] = mean;
  }
  if (!IsAdaptive()) {
    return;
  }
  for (int i = 0; i < 2; ++i) {
    candidates_[kAffineMean][i] = RoundedShiftUp(affine[i], 16);
    candidates_[kSimilarityMean][i] = RoundedShiftUp(similarity[i], 16);
  }
  candidates_[kParallelogramMean] = has_b ? uv_l + uv_r - uv_b : mean;
}

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::ComputeFallback(
    int step, const DataTypeT *data) {
  // The latest known neighbour, else the previous entry, else zero.
  int32_t source = step > 0 ? order_->entries[step - 1] : UvCornerGraph::kNone;
  int32_t latest = -1;
  for (int i = 0; i < num_neighbours_; ++i) {
    const int32_t neighbour = neighbours_[i];
    if (order_->rank[neighbour] > latest) {
      latest = order_->rank[neighbour];
      source = neighbour;
    }
  }
  candidates_.fill(source == UvCornerGraph::kNone ? Uv(0, 0)
                                                  : UvOf(data, source));
}

template <typename DataTypeT>
int MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::ChooseCandidate()
    const {
  if (kind_ == UvPredictorKind::kAgreementWeighted) {
    return kAgreement;
  }
  if (kind_ == UvPredictorKind::kReachMean) {
    return kMeanOfBoth;
  }
  int best = kMeanOfBoth;
  for (int i = 1; i < num_active_; ++i) {
    const int k = active_candidates_[i];
    if (recent_error_[k] < recent_error_[best]) {
      best = k;
    }
  }
  return best;
}

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::ComputeContext() {
  const int count = num_neighbours_;
  if (count == 0 || num_stencils_ == 0) {
    context_ = count == 0 ? kUvResidualNoNeighbourContext
                          : kUvResidualNoStencilContext;
    return;
  }
  int64_t sum = 0;
  for (int i = 0; i < count; ++i) {
    sum += magnitude_[neighbours_[i]];
  }
  const uint64_t mean =
      static_cast<uint64_t>(DivideBySmallCount(sum + count / 2, count));
  context_ = std::min(kUvResidualNoNeighbourContext - 1, BitLength(mean));
}

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::Predict(
    int step, const Stencil *stencils, int num_stencils,
    const int32_t *neighbours, int num_neighbours, const DataTypeT *data,
    const UvComputedFrame *frames) {
  DRACO_DCHECK(num_stencils <= UvStencilPlan::kMaxStencils);
  stencils_ = stencils;
  num_stencils_ = num_stencils;
  neighbours_ = neighbours;
  num_neighbours_ = num_neighbours;
  if (num_stencils_ == 0) {
    ComputeFallback(step, data);
  } else {
    ComputeCandidates(data, frames);
  }
  const Uv &chosen = candidates_[ChooseCandidate()];
  for (int i = 0; i < kUvNumComponents; ++i) {
    // The wrap transform clamps to the attribute's range afterwards.
    predicted_value_[i] = static_cast<DataTypeT>(std::max<int64_t>(
        std::numeric_limits<DataTypeT>::lowest(),
        std::min<int64_t>(std::numeric_limits<DataTypeT>::max(), chosen[i])));
  }
  ComputeContext();
}

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<
    DataTypeT>::ComputeReachFallback(int p, const Stencil &stencil,
                                     const DataTypeT *data) {
  // ComputeFallback() in Draco's order, where an entry's rank is itself:
  // the latest known vertex, else the previous entry, else zero.
  const int32_t latest = std::max(std::max(stencil.l, stencil.r), stencil.b);
  const int32_t source = latest != UvCornerGraph::kNone ? latest : p - 1;
  candidates_.fill(source < 0 ? Uv(0, 0) : UvOf(data, source));
}

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<
    DataTypeT>::ComputeReachContext(const Stencil &stencil) {
  // ComputeContext() over the known vertices of |stencil|.
  uint64_t sum = 0;
  int count = 0;
  for (const int32_t entry : {stencil.l, stencil.r, stencil.b}) {
    if (entry != UvCornerGraph::kNone) {
      sum += magnitude_[entry];
      ++count;
    }
  }
  if (count == 0 || num_stencils_ == 0) {
    context_ = count == 0 ? kUvResidualNoNeighbourContext
                          : kUvResidualNoStencilContext;
    return;
  }
  // (sum + count / 2) / count with constant divisors.
  const uint64_t mean =
      count == 3 ? (sum + 1) / 3 : (count == 2 ? (sum + 1) / 2 : sum);
  context_ = std::min(kUvResidualNoNeighbourContext - 1, BitLength(mean));
}

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::PredictReach(
    int p, const Stencil &stencil, int num_stencils,
    const UvComputedFrame &frame, const DataTypeT *data) {
  stencils_ = &stencil;
  num_stencils_ = num_stencils;
  int chosen = kMeanOfBoth;
  if (num_stencils == 0) {
    ComputeReachFallback(p, stencil, data);
  } else {
    ComputeCandidatesOfOneStencil(frame, data);
    if (kind_ == UvPredictorKind::kReachAdaptive) {
      // ChooseCandidate() over kReachAdaptive's candidates.
      chosen = kFirstReachCandidate;
      for (int k = kFirstReachCandidate + 1; k < kAgreement; ++k) {
        chosen = recent_error_[k] < recent_error_[chosen] ? k : chosen;
      }
    }
  }
  for (int i = 0; i < kUvNumComponents; ++i) {
    predicted_value_[i] = static_cast<DataTypeT>(std::max<int64_t>(
        std::numeric_limits<DataTypeT>::lowest(),
        std::min<int64_t>(std::numeric_limits<DataTypeT>::max(),
                          candidates_[chosen][i])));
  }
  ComputeReachContext(stencil);
}

template <typename DataTypeT>
void MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT>::Update(
    int step, const DataTypeT *data, const DataTypeT *correction) {
  const int32_t tip = order_ != nullptr ? order_->entries[step] : step;
  if (step_orientation_sum_ != 0) {
    last_orientation_ = step_orientation_sum_ > 0 ? 1 : -1;
    step_orientation_sum_ = 0;
  }
  magnitude_[tip] = static_cast<uint32_t>(
      std::min<uint64_t>(std::numeric_limits<uint32_t>::max(),
                         AbsAsUnsigned(correction[0]) +
                             AbsAsUnsigned(correction[1])));
  if (!IsAdaptive()) {
    return;
  }
  // Exponentially decaying error sums (weight 15/16 per step). Candidates
  // stay below 2^38 texture units, so errors stay below 2^40 and the sums
  // below 2^44. The loop bound is a constant for each kind's candidates.
  const int64_t value[2] = {data[tip * kUvNumComponents],
                            data[tip * kUvNumComponents + 1]};
  const auto update = [&](int k) {
    recent_error_[k] += AbsAsUnsigned(value[0] - candidates_[k][0]) +
                        AbsAsUnsigned(value[1] - candidates_[k][1]) -
                        recent_error_[k] / 16;
  };
  if (UsesReachStencil(kind_)) {
    for (int k = kFirstReachCandidate; k < kAgreement; ++k) {
      update(k);
    }
  } else {
    for (int i = 0; i < num_active_; ++i) {
      update(active_candidates_[i]);
    }
  }
}

namespace uv_prediction_internal {

// The face of |corner| as a stencil: its vertices known at entry |p| (below
// |p| in Draco's order), kNone for the others. Returns the number of
// stencils it makes, 1 when L and R are known and distinct, else 0.
template <class MeshDataT>
int StencilOfCorner(const MeshDataT &mesh_data, int p, CornerIndex corner,
                    UvStencilPlan::Stencil *stencil) {
  const auto &table = *mesh_data.corner_table();
  const auto &vertex_to_entry = *mesh_data.vertex_to_data_map();
  const auto known_entry = [&](CornerIndex c) -> int32_t {
    if (c == kInvalidCornerIndex) {
      return UvCornerGraph::kNone;
    }
    const VertexIndex v = table.Vertex(c);
    if (v == kInvalidVertexIndex || v.value() >= vertex_to_entry.size()) {
      return UvCornerGraph::kNone;
    }
    const int32_t entry = vertex_to_entry[v.value()];
    return entry >= 0 && entry < p ? entry : UvCornerGraph::kNone;
  };
  *stencil = {known_entry(table.Next(corner)),
              known_entry(table.Previous(corner)),
              known_entry(table.Opposite(corner))};
  return stencil->l != UvCornerGraph::kNone &&
         stencil->r != UvCornerGraph::kNone && stencil->l != stencil->r;
}

// The stencil of the face through which Draco's traversal reached entry
// |p|. When that face has none (Draco's traversal never crosses its start
// face's third edge, so it may restart a chart next to known vertices), the
// first face around the vertex that has one, swinging left then right up to
// a boundary or a degenerate face; without any, the reach face's known
// vertices. Returns the number of stencils, 0 or 1.
template <class MeshDataT>
int ReachStencil(const MeshDataT &mesh_data, int p,
                 UvStencilPlan::Stencil *stencil) {
  const auto &table = *mesh_data.corner_table();
  const CornerIndex reach = (*mesh_data.data_to_corner_map())[p];
  if (StencilOfCorner(mesh_data, p, reach, stencil)) {
    return 1;
  }
  UvStencilPlan::Stencil other;
  CornerIndex corner = table.SwingLeft(reach);
  bool swinging_left = true;
  for (int steps = 0; steps < table.num_corners() && corner != reach; ++steps) {
    // Faces degenerate in the position connectivity are not coded (see
    // BuildUvCornerGraph()): the decoder has a boundary there.
    if (corner == kInvalidCornerIndex ||
        table.IsDegenerated(table.Face(corner))) {
      if (!swinging_left) {
        break;
      }
      swinging_left = false;
      corner = table.SwingRight(reach);
      continue;
    }
    if (StencilOfCorner(mesh_data, p, corner, &other)) {
      *stencil = other;
      return 1;
    }
    corner = swinging_left ? table.SwingLeft(corner) : table.SwingRight(corner);
  }
  return 0;
}

// What a step of Draco's order needs from the connectivity and the
// positions alone, so that it can be computed ahead (UvLookahead).
struct ReachStep {
  UvStencilPlan::Stencil stencil;
  UvComputedFrame frame;  // Of the stencil, if any.
  int32_t num_stencils;
};

// Smallest number of items (steps or stencils) for which a second thread
// computes them ahead. Starting a thread costs about as much as 400 steps,
// but on the 2-core test VM attributes below a few thousand entries decoded
// no faster with it (draco_uv_decode_bench), while those above 10k did.
constexpr int kMinItemsForLookaheadThread = 8192;

template <typename DataTypeT>
bool UseLookaheadThread(
    const MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT> &predictor,
    int num_items) {
  return predictor.max_threads() > 1 &&
         num_items >= kMinItemsForLookaheadThread && SecondThreadAvailable();
}

template <typename DataTypeT, class MeshDataT>
void ComputeReachSteps(
    const MeshDataT &mesh_data,
    const MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT> &predictor,
    int begin, int end, ReachStep *out) {
  for (int p = begin; p < end; ++p, ++out) {
    out->num_stencils = ReachStencil(mesh_data, p, &out->stencil);
    out->frame = out->num_stencils > 0 ? predictor.ComputeFrame(out->stencil, p)
                                       : UvComputedFrame();
  }
}

// RunUvPrediction() for the kinds that use the reach stencil: the stencils
// and their frames are computed ahead, on a second thread if allowed.
template <typename DataTypeT, class MeshDataT, class ProcessT>
bool RunReachPrediction(
    const MeshDataT &mesh_data, const UvPredictionConfig &config,
    const DataTypeT *data,
    MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT> *predictor,
    ProcessT process) {
  const int num_entries =
      static_cast<int>(mesh_data.data_to_corner_map()->size());
  predictor->StartReach(config.kind, num_entries);
  const auto compute = [&](int begin, int end, ReachStep *out) {
    ComputeReachSteps(mesh_data, *predictor, begin, end, out);
  };
  UvLookahead<ReachStep, decltype(compute)> steps(
      num_entries, UseLookaheadThread(*predictor, num_entries), compute);
  for (int p = 0; p < num_entries; ++p) {
    const ReachStep &step = steps.Get(p);
    predictor->PredictReach(p, step.stencil, step.num_stencils, step.frame,
                            data);
    if (!process(p, p)) {
      return false;
    }
  }
  return true;
}

// What a step of a multi-stencil order needs from the connectivity and
// the positions alone, so that it can be computed ahead (UvLookahead).
struct PlanStep {
  UvStencilPlan plan;
  UvComputedFrame frames[UvStencilPlan::kMaxStencils];
};

template <typename DataTypeT>
void ComputePlanSteps(
    const UvStencilPlanner &planner, const UvProcessingOrder &order,
    const MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT> &predictor,
    int begin, int end, PlanStep *out) {
  for (int step = begin; step < end; ++step, ++out) {
    planner.Build(step, &out->plan);
    for (int i = 0; i < out->plan.num_stencils; ++i) {
      out->frames[i] =
          predictor.ComputeFrame(out->plan.stencils[i], order.entries[step]);
    }
  }
}

// RunUvPrediction() for the kinds that use every stencil (up to
// UvStencilPlan::kMaxStencils) of a vertex: the stencils and their frames
// are computed ahead, on a second thread if allowed.
template <typename DataTypeT, class MeshDataT, class ProcessT>
bool RunPlanPrediction(
    const MeshDataT &mesh_data, const UvPredictionConfig &config,
    const DataTypeT *data,
    MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT> *predictor,
    ProcessT process) {
  const auto &data_to_corner = *mesh_data.data_to_corner_map();
  UvProcessingOrder order;
  UvCornerGraph graph;
  BuildUvCornerGraph(mesh_data, &graph);
  if (config.max_degree_order) {
    BuildMaxDegreeOrder(graph, data_to_corner, &order);
  } else {
    BuildDataOrder(data_to_corner, &order);
  }
  predictor->Start(config.kind, order);
  const UvStencilPlanner planner(graph, order);
  const int num_steps = static_cast<int>(order.entries.size());
  const auto compute = [&](int begin, int end, PlanStep *out) {
    ComputePlanSteps(planner, order, *predictor, begin, end, out);
  };
  UvLookahead<PlanStep, decltype(compute)> steps(
      num_steps, UseLookaheadThread(*predictor, num_steps), compute);
  for (int step = 0; step < num_steps; ++step) {
    const PlanStep &s = steps.Get(step);
    predictor->Predict(step, s.plan.stencils, s.plan.num_stencils,
                       s.plan.neighbours, s.plan.num_neighbours, data,
                       s.frames);
    if (!process(step, order.entries[step])) {
      return false;
    }
  }
  return true;
}

}  // namespace uv_prediction_internal

// Runs |predictor| over all entries of |mesh_data| as |config| says: builds
// the processing order and the stencils, and for every step calls
// Predict() and then |process|(step, entry), which must make the entry's
// value available in |data| and call Update(), and may return false to
// stop; RunUvPrediction() then returns false.
template <typename DataTypeT, class MeshDataT, class ProcessT>
bool RunUvPrediction(
    const MeshDataT &mesh_data, const UvPredictionConfig &config,
    const DataTypeT *data,
    MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT> *predictor,
    ProcessT process) {
  if (UsesReachStencil(config.kind)) {
    return uv_prediction_internal::RunReachPrediction(mesh_data, config, data,
                                                      predictor, process);
  }
  return uv_prediction_internal::RunPlanPrediction(mesh_data, config, data,
                                                   predictor, process);
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_PREDICTOR_H_
