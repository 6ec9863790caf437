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
#include "draco_ext/seams/uv_seam_coder.h"

#include <algorithm>
#include <array>

#include "draco/core/macros.h"
#include "draco_ext/seams/uv_seam_bit_model.h"
#include "draco_ext/seams/uv_seam_range_coder.h"

namespace draco {

namespace {

constexpr uint8_t kUndecided = 2;

// Zero bits coded at probability 1/2 after the seams: a corrupt stream
// decodes them as zeros with probability 2^-14 only (the range coder's own
// checks catch truncation and trailing bytes, not altered ones). 14 bits
// rather than 16 keep the smallest meshes below stock Draco's seam bytes.
constexpr int kNumCheckBits = 14;
constexpr uint32_t kCheckBitProbability = kUvSeamProbabilityOne / 2;

// Rings longer than this are decided in ring order (bounds the work on
// high-valence vertices; real rings are rarely longer than 10).
constexpr int kMaxScoredRing = 16;

// Ring distance classes of the decided edge: no seam or boundary known at
// the vertex yet, three classes of distance to the nearest one relative to
// the ring size, and rings longer than kMaxScoredRing.
constexpr int kNoAnchor = 0;
constexpr int kLongRing = 4;
constexpr int kNumDistanceClasses = 5;

// An edge about to be decided from |vertex|.
struct Decision {
  int32_t vertex;
  int32_t other;  // The edge's other vertex.
  int32_t edge;
  int position = -1;  // In the ring, if it has at most kMaxScoredRing edges.
  int distance_class = kLongRing;
  int sector = 0;  // Edges between the nearest cuts around the decided one.
};

// The ring of the vertex being decided (at most kMaxScoredRing edges): which
// edges are undecided, and how far each is from the nearest cut (seam or
// boundary) in either direction.
class RingView {
 public:
  RingView(int size, const bool *undecided, const bool *cut) : size_(size) {
    for (int i = 0; i < size; ++i) {
      open_[i] = undecided[i];
      left_[i] = right_[i] = size;  // No cut.
    }
    for (int i = 0; i < size; ++i) {
      if (cut[i]) {
        AddCut(i);
      }
    }
  }

  void Decide(int position, bool seam) {
    open_[position] = false;
    if (seam) {
      AddCut(position);
    }
  }

  // The undecided position farthest from the nearest cut (the first one on
  // ties or without cuts), its distance (size() without cuts) and the
  // number of positions between the cuts around it.
  int Farthest(int *distance, int *sector) const {
    int best = -1;
    *distance = -1;
    for (int i = 0; i < size_; ++i) {
      const int d = std::min(left_[i], right_[i]);
      if (open_[i] && d > *distance) {
        best = i;
        *distance = d;
      }
    }
    *sector = *distance < size_ ? left_[best] + right_[best] - 1 : 0;
    return best;
  }

 private:
  void AddCut(int position) {
    for (int i = 0; i < size_; ++i) {
      const int to_left = i >= position ? i - position : i - position + size_;
      const int to_right = position >= i ? position - i : position - i + size_;
      left_[i] = std::min(left_[i], to_left);
      right_[i] = std::min(right_[i], to_right);
    }
  }

  int size_;
  bool open_[kMaxScoredRing];
  int left_[kMaxScoredRing];   // Steps to the nearest cut going left.
  int right_[kMaxScoredRing];  // Same, going right.
};

// Builds a context index from features with known ranges.
class MixedRadix {
 public:
  MixedRadix &Add(int value, int radix) {
    DRACO_DCHECK(value >= 0 && value < radix);
    index_ = index_ * radix + value;
    size_ *= radix;
    return *this;
  }
  int index() const { return index_; }
  int size() const { return size_; }

 private:
  int index_ = 0;
  int size_ = 1;
};

// What the decoder knows about one decision, in small ranges.
struct Features {
  int seams_here = 0;       // Seams decided at the vertex, up to 3.
  int seams_there = 0;      // Seams decided at the other vertex, up to 2.
  int open_here = 0;        // The vertex lies on a boundary.
  int open_there = 0;       // The other vertex lies on a boundary.
  int distance_class = 0;   // See kNumDistanceClasses.
  int undecided_here = 0;   // Undecided edges at the vertex, 1 to 3.
  int undecided_there = 0;  // Same at the other vertex, 1 to 2, if it has a
                            // seam already; 0 otherwise.
  int wing_cuts = 0;        // Seam or boundary among the wings, up to 2.
  int wing_joins = 0;       // Decided non-seams among the wings, up to 3.
  int ring_size = 0;        // Up to 9.
  int earlier_seam = 0;     // An earlier attribute has a seam here.
  int sector = 0;
};

// Model 0: everything; model 1: the seam counts at both ends; model 2: the
// vertex's ring. Mixing lets the small models speak while the big one is
// still learning.
constexpr int kNumModels = 3;

MixedRadix RichContext(const Features &f) {
  return MixedRadix()
      .Add(f.seams_here, 4)
      .Add(f.seams_there, 3)
      .Add(f.open_here, 2)
      .Add(f.open_there, 2)
      .Add(f.distance_class, kNumDistanceClasses)
      .Add(f.undecided_here, 4)
      .Add(f.wing_cuts, 3)
      .Add(f.wing_joins, 4)
      .Add(f.undecided_there, 3)
      .Add(f.earlier_seam, 2)
      .Add(std::min(f.ring_size, 8) / 2, 5)
      .Add(std::min(f.sector, 5), 6);
}

MixedRadix EndsContext(const Features &f) {
  return MixedRadix()
      .Add(f.seams_here, 4)
      .Add(f.seams_there, 3)
      .Add(f.open_here, 2)
      .Add(f.earlier_seam, 2);
}

MixedRadix RingContext(const Features &f) {
  return MixedRadix()
      .Add(f.seams_here, 4)
      .Add(f.distance_class, kNumDistanceClasses)
      .Add(f.undecided_here, 4)
      .Add(f.ring_size, 10)
      .Add(f.sector, 8)
      .Add(f.earlier_seam, 2);
}

std::array<int, kNumModels> ContextCounts() {
  const Features zero;
  return {RichContext(zero).size(), EndsContext(zero).size(),
          RingContext(zero).size()};
}

class EncodingIo {
 public:
  bool Code(uint32_t probability_of_one, bool bit) {
    coder_.EncodeBit(bit, probability_of_one);
    return bit;
  }
  UvSeamRangeEncoder *coder() { return &coder_; }

 private:
  UvSeamRangeEncoder coder_;
};

class DecodingIo {
 public:
  DecodingIo(const uint8_t *data, size_t size) : coder_(data, size) {}
  bool Code(uint32_t probability_of_one, bool /* bit */) {
    return coder_.DecodeBit(probability_of_one);
  }
  const UvSeamRangeDecoder &coder() const { return coder_; }

 private:
  UvSeamRangeDecoder coder_;
};

// Decides the seam flags of attributes one after another, walking seam
// chains (see the header). Encoder and decoder run the same walk; only
// BitIoT::Code() differs.
template <class BitIoT>
class CreaseWalker {
 public:
  CreaseWalker(const UvSeamTopology &topology, BitIoT *io)
      : topology_(topology), io_(io), model_(ContextCounts()) {}

  // Decides every edge of one attribute into |decided|. |truth| holds the
  // encoder's flags (null when decoding); |earlier| flags edges on which an
  // earlier attribute has a seam.
  void CodeAttribute(const UvSeamFlags *truth, const UvSeamFlags &earlier,
                     UvSeamFlags *decided);

 private:
  void Reset();
  void DecideVertex(int32_t vertex);
  // The view of a ring of at most kMaxScoredRing edges.
  RingView ReadRing(int32_t vertex) const;
  // Picks the next edge of |vertex| to decide: the farthest of |view| if
  // the ring is short enough, the first undecided one otherwise.
  Decision Choose(int32_t vertex, const RingView &view) const;
  Features Describe(const Decision &decision) const;
  bool IsAnchor(int32_t edge) const {
    return edge == UvSeamTopology::kBoundary || (*state_)[edge] == 1;
  }
  bool IsUndecided(int32_t edge) const {
    return edge != UvSeamTopology::kBoundary && (*state_)[edge] == kUndecided;
  }

  const UvSeamTopology &topology_;
  BitIoT *io_;
  UvSeamBitModel<kNumModels> model_;
  const UvSeamFlags *truth_ = nullptr;
  const UvSeamFlags *earlier_ = nullptr;
  UvSeamFlags *state_ = nullptr;
  std::vector<int> seams_at_;      // Per vertex.
  std::vector<int> undecided_at_;  // Per vertex.
  std::vector<int32_t> stack_;     // Vertices reached by seams.
};

template <class BitIoT>
void CreaseWalker<BitIoT>::CodeAttribute(const UvSeamFlags *truth,
                                         const UvSeamFlags &earlier,
                                         UvSeamFlags *decided) {
  truth_ = truth;
  earlier_ = &earlier;
  state_ = decided;
  Reset();
  for (int32_t start = 0; start < topology_.num_vertices(); ++start) {
    if (undecided_at_[start] == 0) {
      continue;
    }
    stack_.push_back(start);
    while (!stack_.empty()) {
      const int32_t vertex = stack_.back();
      stack_.pop_back();
      DecideVertex(vertex);
    }
  }
}

template <class BitIoT>
void CreaseWalker<BitIoT>::Reset() {
  state_->assign(topology_.num_edges(), kUndecided);
  seams_at_.assign(topology_.num_vertices(), 0);
  undecided_at_.assign(topology_.num_vertices(), 0);
  for (int32_t vertex = 0; vertex < topology_.num_vertices(); ++vertex) {
    undecided_at_[vertex] = topology_.InteriorDegree(vertex);
  }
}

template <class BitIoT>
void CreaseWalker<BitIoT>::DecideVertex(int32_t vertex) {
  if (undecided_at_[vertex] == 0) {
    return;
  }
  RingView view = ReadRing(vertex);
  while (undecided_at_[vertex] > 0) {
    const Decision decision = Choose(vertex, view);
    const Features features = Describe(decision);
    const std::array<int, kNumModels> contexts = {
        RichContext(features).index(), EndsContext(features).index(),
        RingContext(features).index()};
    const uint32_t probability = model_.Predict(contexts);
    const bool seam = io_->Code(
        probability, truth_ != nullptr && (*truth_)[decision.edge] != 0);
    model_.Update(seam);
    (*state_)[decision.edge] = seam;
    if (decision.position >= 0) {
      view.Decide(decision.position, seam);
    }
    --undecided_at_[decision.vertex];
    --undecided_at_[decision.other];
    if (seam) {
      ++seams_at_[decision.vertex];
      ++seams_at_[decision.other];
      if (undecided_at_[decision.other] > 0) {
        stack_.push_back(decision.other);
      }
    }
  }
}

template <class BitIoT>
RingView CreaseWalker<BitIoT>::ReadRing(int32_t vertex) const {
  bool undecided[kMaxScoredRing];
  bool cut[kMaxScoredRing];
  const int size = std::min(topology_.RingSize(vertex), kMaxScoredRing);
  const int32_t *const ring = topology_.RingBegin(vertex);
  for (int i = 0; i < size; ++i) {
    undecided[i] = IsUndecided(ring[i]);
    cut[i] = IsAnchor(ring[i]);
  }
  return RingView(size, undecided, cut);
}

template <class BitIoT>
Decision CreaseWalker<BitIoT>::Choose(int32_t vertex,
                                      const RingView &view) const {
  const int32_t *const ring = topology_.RingBegin(vertex);
  const int size = topology_.RingSize(vertex);
  Decision decision;
  decision.vertex = vertex;
  int best;
  if (size > kMaxScoredRing) {
    best = static_cast<int>(
        std::find_if(ring, ring + size,
                     [this](int32_t edge) { return IsUndecided(edge); }) -
        ring);
    decision.position = -1;
    decision.distance_class = kLongRing;
  } else {
    int distance;
    best = view.Farthest(&distance, &decision.sector);
    decision.position = best;
    decision.distance_class =
        distance == size ? kNoAnchor : 1 + std::min(2, 6 * distance / size);
    decision.sector = std::min(decision.sector, 7);
  }
  DRACO_DCHECK(best >= 0 && best < size);
  decision.edge = ring[best];
  decision.other = topology_.RingNeighbors(vertex)[best];
  return decision;
}

template <class BitIoT>
Features CreaseWalker<BitIoT>::Describe(const Decision &decision) const {
  Features f;
  f.seams_here = std::min(seams_at_[decision.vertex], 3);
  f.seams_there = std::min(seams_at_[decision.other], 2);
  f.open_here = topology_.IsOpen(decision.vertex);
  f.open_there = topology_.IsOpen(decision.other);
  f.distance_class = decision.distance_class;
  f.undecided_here = std::min(undecided_at_[decision.vertex], 3);
  f.undecided_there =
      f.seams_there > 0 ? std::min(undecided_at_[decision.other], 2) : 0;
  int cuts = 0;
  int joins = 0;
  for (const int32_t wing : topology_.Wings(decision.edge)) {
    if (IsAnchor(wing)) {
      ++cuts;
    } else if ((*state_)[wing] == 0) {
      ++joins;
    }
  }
  f.wing_cuts = std::min(cuts, 2);
  f.wing_joins = std::min(joins, 3);
  f.ring_size = std::min(topology_.RingSize(decision.vertex), 9);
  f.earlier_seam = (*earlier_)[decision.edge];
  f.sector = decision.sector;
  return f;
}

void MergeSeams(const UvSeamFlags &seams, UvSeamFlags *earlier) {
  for (size_t edge = 0; edge < seams.size(); ++edge) {
    (*earlier)[edge] |= seams[edge] != 0;
  }
}

}  // namespace

std::vector<uint8_t> EncodeUvSeams(const UvSeamTopology &topology,
                                   const std::vector<UvSeamFlags> &seams) {
  EncodingIo io;
  CreaseWalker<EncodingIo> walker(topology, &io);
  UvSeamFlags earlier(topology.num_edges(), 0);
  UvSeamFlags decided;
  for (const UvSeamFlags &attribute_seams : seams) {
    DRACO_DCHECK_EQ(attribute_seams.size(), topology.num_edges());
    walker.CodeAttribute(&attribute_seams, earlier, &decided);
    MergeSeams(attribute_seams, &earlier);
  }
  for (int i = 0; i < kNumCheckBits; ++i) {
    io.Code(kCheckBitProbability, false);
  }
  return io.coder()->Finish();
}

bool DecodeUvSeams(const UvSeamTopology &topology, int num_attributes,
                   const uint8_t *data, size_t size,
                   std::vector<UvSeamFlags> *seams) {
  DecodingIo io(data, size);
  CreaseWalker<DecodingIo> walker(topology, &io);
  UvSeamFlags earlier(topology.num_edges(), 0);
  seams->assign(num_attributes, UvSeamFlags());
  for (UvSeamFlags &attribute_seams : *seams) {
    walker.CodeAttribute(nullptr, earlier, &attribute_seams);
    MergeSeams(attribute_seams, &earlier);
  }
  bool checks_ok = true;
  for (int i = 0; i < kNumCheckBits; ++i) {
    checks_ok = !io.Code(kCheckBitProbability, false) && checks_ok;
  }
  return checks_ok && io.coder().Finish();
}

}  // namespace draco
