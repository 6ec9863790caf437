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
// Crease-bit coding of attribute seams with context modelling.
//
// Váša & Brunnett, "Efficient encoding of texture coordinates guided by
// mesh geometry" (SGP 2014), section 3: texture connectivity is the mesh
// connectivity cut along crease edges, so one bit per interior edge
// describes it, and with arithmetic coding these bits beat the per-vertex
// crease flags of Taubin et al. (1998) and Isenburg & Snoeyink (2000)
// (eqs. 1-2, fig. 3). Draco's Edgebreaker codes exactly these bits, with one
// static probability per attribute. This coder codes the same bits in
// Draco's own order (faces in decoded order, each face's corners c, next(c),
// previous(c), boundary edges and edges of earlier faces skipped, every
// attribute of an edge before the next edge), so the decoder needs no
// topology of its own: one pass over the corner table.
//
// Seams form chains that end only at boundaries or where charts meet, so a
// bit is predicted from what is known at the edge's two vertices when it is
// coded: seams already decided there (one seam at a vertex almost always
// continues), the vertex's undecided interior edges left (when one is left
// after a lone seam, it is almost surely the continuation), whether the
// vertex lies on a boundary, and for later attributes whether an earlier one
// has a seam on the same edge (UV sets and per-corner normals often share
// seams). Each context has one adaptive probability (a shift update that
// starts fast, as in LZMA-like coders with a count-based warm-up), which
// drives a binary range coder (uv_seam_range_coder.h).
//
// Most edges are quiet: no seam and no boundary at either end yet, and
// seams there are rare. As in the run mode of LOCO-I / JPEG-LS (Weinberger,
// Seroussi & Sapiro, IEEE TIP 2000) and CALIC's binary mode (Wu & Memon,
// IEEE TCOM 1997), quiet edges get no bit each: per class of quiet edges the
// coder codes the number of them without a seam before the next one with a
// seam (an adaptive Elias gamma code), so a quiet edge costs a countdown.
// Everything is integer arithmetic on the connectivity alone, so the decoded
// seams, vertices and attribute values are exactly those of stock Draco.
#ifndef DRACO_EXT_SEAMS_UV_SEAM_CODER_H_
#define DRACO_EXT_SEAMS_UV_SEAM_CODER_H_

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "draco/core/macros.h"
#include "draco_ext/seams/uv_seam_range_coder.h"

namespace draco {

// A corner table in the decoder's corner numbering, as plain arrays: what
// the encoder and the evaluation tools code on.
struct UvSeamCornerTable {
  static constexpr uint32_t kBoundary = 0xFFFFFFFFu;

  uint32_t num_corners() const {
    return static_cast<uint32_t>(opposite.size());
  }
  uint32_t Opposite(uint32_t corner) const { return opposite[corner]; }
  uint32_t Vertex(uint32_t corner) const { return vertex[corner]; }

  std::vector<uint32_t> opposite;  // kBoundary for none.
  std::vector<uint32_t> vertex;
  uint32_t num_vertices = 0;
};

// Zero bits coded at probability 1/2 after the seams: a corrupt stream
// decodes them as zeros with probability 2^-14 only (the range coder's own
// checks catch truncation and trailing bytes, not altered ones). 14 bits
// rather than 16 keep the smallest meshes below stock Draco's seam bytes.
constexpr int kUvSeamCheckBits = 14;

// The seam bits of a corner table (TableT: num_corners(), Opposite(),
// Vertex() and num_vertices, in uint32_t, kBoundary for no opposite), coded
// in Draco's order with the contexts of the file comment. Encoder and
// decoder run the same code; only BitIoT::Code() differs.
template <class TableT>
class UvSeamContextCoder {
 public:
  // False if a corner's vertex or opposite is out of range (corrupt
  // connectivity).
  bool Init(const TableT &table, int num_attributes);

  // Interior edges that Draco codes a bit for, per attribute.
  size_t num_edges() const { return num_edges_; }

  // Codes num_edges() * num_attributes bits at |bits| (edge-major; read by
  // the encoder, written by the decoder, which passes zeros: the bits of
  // quiet edges inside runs are left alone), then the check bits; false if
  // a check bit decodes as one.
  template <class BitIoT>
  bool Code(BitIoT *io, uint8_t *bits) {
    // One attribute (the common case) with a constant count.
    const bool ok =
        num_attributes_ == 1 ? CodeBits<1>(io, bits) : CodeBits<0>(io, bits);
    bool checks_ok = true;
    for (int i = 0; i < kUvSeamCheckBits; ++i) {
      checks_ok = !io->Code(kUvSeamProbabilityOne / 2, false) && checks_ok;
    }
    return ok && checks_ok;
  }

  // The encoder's run lengths for |bits| (see CodeRun()): per class of
  // quiet edges (QuietClass()) and quiet edge of that class with a seam, in
  // coding order, the edges of the class without seams before it.
  std::vector<std::vector<uint32_t>> QuietRuns(const uint8_t *bits) const;

 private:
  // Code() for kNumAttributes attributes, or num_attributes_ if 0.
  template <int kNumAttributes, class BitIoT>
  bool CodeBits(BitIoT *io, uint8_t *bits);
  // Codes the bits of the edge opposite |corner| (|opposite| across it,
  // ends |a| at Next(corner) and |b|) for every attribute at |bit| with the
  // contexts of the file comment. |implied_seam|: some attribute has a
  // seam there, so the last bit is one if the others are zero.
  template <int kNumAttributes, class BitIoT>
  void CodeEdge(BitIoT *io, uint32_t corner, uint32_t opposite, uint32_t a,
                uint32_t b, bool implied_seam, uint8_t *bit);
  // Codes the length of the next run of quiet edges of class |quiet_class|
  // and sets |countdown| to the quiet edges of the class up to and including
  // the next one with a seam, or to kEndless if none follows (counted down,
  // it stays above num_edges_); false if the length is out of range.
  template <class BitIoT>
  bool CodeRun(BitIoT *io, int quiet_class, uint32_t *countdown);

  // A vertex's state: undecided interior edges left (bits 2 and up), whether
  // a seam of any attribute has been decided there (bit 1) and whether it
  // lies on a boundary (bit 0). An edge with neither flag at either end is
  // quiet.
  static constexpr uint32_t kOnBoundary = 1;
  static constexpr uint32_t kHasSeam = 2;
  static constexpr uint32_t kOneEdge = 4;
  static constexpr uint32_t kEndless = 0xFFFFFFFFu;
  // Ring steps to the nearest cut that are told apart: 1 to kMaxSteps, and
  // farther.
  static constexpr int kMaxSteps = 3;
  // Unordered pairs of step counts in [1, kMaxSteps + 1].
  static constexpr int kNumStepPairs = 10;
  // An end of the edge without seams: undecided edges left and boundary
  // (QuietEnd()). With seams (1, 2, 3+) also the steps to the nearest cut
  // either way around the vertex.
  static constexpr int kNumQuietEnds = 4 * 2;
  static constexpr int kNumEnds = kNumQuietEnds + 3 * 4 * 2 * kNumStepPairs;
  // The other end of the edge, without the steps.
  static constexpr int kNumShortEnds = 4 * 4 * 2;
  static constexpr int kNumEdgeContexts = kNumEnds * kNumShortEnds;
  // A run starts with a flag, whether a quiet edge with a seam follows at
  // all; then its length plus one as an Elias gamma code of at most
  // kMaxRunBits bits after the leading one: the unary part and the two bits
  // after the leading one are adaptive, the rest coded at probability 1/2.
  static constexpr int kMaxRunBits = 31;
  static constexpr int kRunMore = 0;
  static constexpr int kRunUnary = 1;
  static constexpr int kRunMantissa = kRunUnary + kMaxRunBits;
  static constexpr int kNumRunContexts = kRunMantissa + 2 * kMaxRunBits;
  // Quiet edges form classes by the fewer undecided edges left at either
  // end (1, 2, 3+; 0, impossible on a manifold table, counts as 1); each
  // class has its own runs.
  static constexpr int kNumQuietClasses = 3;
  static int QuietClass(uint32_t state_a, uint32_t state_b) {
    const uint32_t fewer = std::min(state_a, state_b);
    return (fewer >= 2 * kOneEdge) + (fewer >= 3 * kOneEdge);
  }

  // One adaptive probability of a one, in 1/65536, and how many bits it
  // has seen (up to kMaxSeen).
  struct Probability {
    uint16_t p1 = 1u << 15;
    uint16_t seen = 0;
  };
  static constexpr int kMaxSeen = 45;

  static uint32_t Next(uint32_t c) { return c % 3 == 2 ? c - 2 : c + 1; }
  static uint32_t Previous(uint32_t c) { return c % 3 == 0 ? c + 2 : c - 1; }

  // True if the edge opposite |corner| is a boundary or a decided seam of
  // the attribute whose corner flags are |seam_corners|.
  bool IsCut(uint32_t corner, const uint8_t *seam_corners) const {
    return table_->Opposite(corner) == TableT::kBoundary ||
           seam_corners[corner] != 0;
  }
  // Steps around the vertex shared by the edges opposite |corner| and
  // opposite its Previous() (kPrevious) or Next() corner, from the former
  // to the first cut: 1 to kMaxSteps + 1 (farther).
  template <bool kPrevious>
  int StepsToCut(uint32_t corner, const uint8_t *seam_corners) const;
  // Index among kNumStepPairs of the steps to the nearest cuts either way
  // around the end of the edge opposite |corner| at Next(corner)
  // (kAtNext) or Previous(corner); |opposite| is its opposite corner.
  template <bool kAtNext>
  int StepPair(uint32_t corner, uint32_t opposite,
               const uint8_t *seam_corners) const;
  // Context of an end without seams of this attribute, from its state: 1,
  // 2 or 3 undecided edges left, each on a boundary or not, 4 left off the
  // boundary, and more (found measurably better than splitting the last
  // class by boundary).
  static int QuietEnd(uint32_t state) {
    static constexpr uint8_t kQuietEnd[10] = {0, 0, 0, 1, 2, 3, 4, 5, 6, 7};
    const uint32_t left_and_boundary =
        ((state >> 1) & ~1u) | (state & kOnBoundary);
    return kQuietEnd[std::min<uint32_t>(left_and_boundary, 9)];
  }
  static int ShortEnd(uint32_t state, int seams) {
    return std::min(seams, 3) * kNumQuietEnds + QuietEnd(state);
  }
  static int FullEnd(uint32_t state, int seams, int step_pair) {
    return kNumQuietEnds +
           ((std::min(seams, 3) - 1) * kNumQuietEnds + QuietEnd(state)) *
               kNumStepPairs +
           step_pair;
  }
  // Codes |bit| with |probability| and adapts it; returns the bit.
  template <class BitIoT>
  static bool CodeFlag(BitIoT *io, Probability *probability, bool bit);

  const TableT *table_ = nullptr;
  int num_attributes_ = 0;
  size_t num_edges_ = 0;
  std::vector<uint32_t> vertex_state_;
  std::vector<uint8_t> seams_at_;  // [attribute * num_vertices + vertex].
  // [attribute * num_corners + corner]: 1 if the edge opposite the corner
  // is a decided seam.
  std::vector<uint8_t> seam_corners_;
  // Attribute 0, then later attributes without and with an earlier seam on
  // the same edge.
  std::vector<Probability> probabilities_;
  Probability run_probabilities_[kNumQuietClasses][kNumRunContexts];
};

template <class TableT>
bool UvSeamContextCoder<TableT>::Init(const TableT &table, int num_attributes) {
  table_ = &table;
  num_attributes_ = num_attributes;
  num_edges_ = 0;
  const uint32_t num_vertices = table.num_vertices;
  const uint32_t num_corners = table.num_corners() / 3 * 3;
  // A vertex of a manifold table has one interior edge per corner, one
  // fewer on a boundary, where it ends two boundary edges: the one whose
  // corner's Next() it is takes the edge off. (Other tables only get other
  // contexts.)
  vertex_state_.assign(num_vertices, 0);
  uint32_t *const state = vertex_state_.data();
  for (uint32_t first = 0; first < num_corners; first += 3) {
    const uint32_t v[3] = {table.Vertex(first), table.Vertex(first + 1),
                           table.Vertex(first + 2)};
    if (std::max(v[0], std::max(v[1], v[2])) >= num_vertices) {
      return false;
    }
    for (int i = 0; i < 3; ++i) {
      state[v[i]] += kOneEdge;
      const uint32_t opposite = table.Opposite(first + i);
      if (opposite == TableT::kBoundary) {
        uint32_t &next = state[v[i == 2 ? 0 : i + 1]];
        next = (next - kOneEdge) | kOnBoundary;
        state[v[i == 0 ? 2 : i - 1]] |= kOnBoundary;
      } else if (opposite >= num_corners) {
        return false;
      } else {
        num_edges_ += opposite >= first;  // Not an edge of an earlier face.
      }
    }
  }
  seams_at_.assign(static_cast<size_t>(num_vertices) * num_attributes, 0);
  seam_corners_.assign(static_cast<size_t>(num_corners) * num_attributes, 0);
  probabilities_.assign(
      num_attributes > 1 ? 3 * kNumEdgeContexts : kNumEdgeContexts,
      Probability());
  for (Probability *probabilities : run_probabilities_) {
    std::fill(probabilities, probabilities + kNumRunContexts, Probability());
    // A run's first unary bit starts at 1/4: on small meshes, where the
    // warm-up counts, runs are short.
    probabilities[kRunUnary].p1 = 1u << 14;
  }
  return true;
}

template <class TableT>
std::vector<std::vector<uint32_t>> UvSeamContextCoder<TableT>::QuietRuns(
    const uint8_t *bits) const {
  const TableT &table = *table_;
  const uint32_t num_corners = table.num_corners() / 3 * 3;
  std::vector<uint32_t> state = vertex_state_;
  std::vector<std::vector<uint32_t>> runs(kNumQuietClasses);
  uint32_t run[kNumQuietClasses] = {};
  for (uint32_t first = 0; first < num_corners; first += 3) {
    for (int i = 0; i < 3; ++i) {
      const uint32_t opposite = table.Opposite(first + i);
      if (opposite == TableT::kBoundary || opposite < first) {
        continue;
      }
      const uint32_t a = table.Vertex(i == 2 ? first : first + i + 1);
      const uint32_t b = table.Vertex(i == 0 ? first + 2 : first + i - 1);
      const bool seam = std::any_of(bits, bits + num_attributes_,
                                    [](uint8_t bit) { return bit != 0; });
      bits += num_attributes_;
      if (((state[a] | state[b]) & (kOnBoundary | kHasSeam)) == 0) {
        const int quiet_class = QuietClass(state[a], state[b]);
        if (seam) {
          runs[quiet_class].push_back(run[quiet_class]);
          run[quiet_class] = 0;
        } else {
          ++run[quiet_class];
        }
      }
      if (seam) {
        state[a] |= kHasSeam;
        state[b] |= kHasSeam;
      }
      state[a] -= kOneEdge;
      state[b] -= kOneEdge;
    }
  }
  return runs;
}

template <class TableT>
template <bool kPrevious>
int UvSeamContextCoder<TableT>::StepsToCut(uint32_t corner,
                                           const uint8_t *seam_corners) const {
  for (int steps = 1; steps <= kMaxSteps; ++steps) {
    const uint32_t wing = kPrevious ? Previous(corner) : Next(corner);
    if (IsCut(wing, seam_corners)) {
      return steps;
    }
    corner = table_->Opposite(wing);  // Not a boundary: not a cut.
  }
  return kMaxSteps + 1;
}

template <class TableT>
template <bool kAtNext>
int UvSeamContextCoder<TableT>::StepPair(uint32_t corner, uint32_t opposite,
                                         const uint8_t *seam_corners) const {
  // The end is Next(corner) of the edge's face and Previous(opposite) of
  // the opposite face, or the other way round.
  int one_way = StepsToCut<kAtNext>(corner, seam_corners);
  int other_way = StepsToCut<!kAtNext>(opposite, seam_corners);
  if (one_way > other_way) {
    std::swap(one_way, other_way);
  }
  static constexpr int kFirstPair[kMaxSteps + 1] = {0, 4, 7, 9};
  return kFirstPair[one_way - 1] + other_way - one_way;
}

template <class TableT>
template <class BitIoT>
inline bool UvSeamContextCoder<TableT>::CodeFlag(BitIoT *io,
                                                 Probability *probability,
                                                 bool bit) {
  // 65536 * 2 / (2 * seen + 3): the rate of a count-based estimate, which
  // settles at 1/46.5 (kMaxSeen).
  static constexpr uint16_t kRate[kMaxSeen + 1] = {
      43690, 26214, 18724, 14563, 11915, 10082, 8738, 7710, 6898, 6241,
      5698,  5242,  4854,  4519,  4228,  3971,  3744, 3542, 3360, 3196,
      3048,  2912,  2788,  2674,  2570,  2473,  2383, 2299, 2221, 2148,
      2080,  2016,  1956,  1899,  1846,  1795,  1747, 1702, 1659, 1618,
      1579,  1542,  1506,  1472,  1440,  1409};
  const uint32_t p1 = probability->p1;
  // p1 stays within [1, 65535]; | 1 keeps the coder's probability in
  // [1, 4095].
  const bool one = io->Code((p1 >> 4) | 1, bit);
  const uint32_t rate = kRate[probability->seen];
  probability->seen += probability->seen < kMaxSeen;
  probability->p1 = static_cast<uint16_t>(
      one ? p1 + (((65536u - p1) * rate) >> 16) : p1 - ((p1 * rate) >> 16));
  return one;
}

template <class TableT>
template <class BitIoT>
bool UvSeamContextCoder<TableT>::CodeRun(BitIoT *io, int quiet_class,
                                         uint32_t *countdown) {
  // The encoder's run length plus one, 0 for none; the decoder's is 0.
  const uint32_t value = io->NextRun(quiet_class);
  Probability *const probabilities = run_probabilities_[quiet_class];
  if (!CodeFlag(io, &probabilities[kRunMore], value != 0)) {
    *countdown = kEndless;
    return true;
  }
  int length = 0;  // Bits after the leading one.
  while (CodeFlag(io, &probabilities[kRunUnary + length],
                  (value >> (length + 1)) != 0)) {
    if (++length == kMaxRunBits) {
      return false;
    }
  }
  uint32_t decoded = 1;
  for (int i = length - 1; i >= 0; --i) {
    const bool bit = ((value >> i) & 1) != 0;
    const int rank = length - 1 - i;  // 0 for the bit after the leading one.
    decoded = (decoded << 1) |
              (rank < 2 ? CodeFlag(io,
                                   &probabilities[kRunMantissa +
                                                  2 * (length - 1) + rank],
                                   bit)
                        : io->Code(kUvSeamProbabilityOne / 2, bit));
  }
  // A run longer than the edges is corrupt.
  if (decoded > num_edges_) {
    return false;
  }
  *countdown = decoded;
  return true;
}

template <class TableT>
template <int kNumAttributes, class BitIoT>
inline void UvSeamContextCoder<TableT>::CodeEdge(BitIoT *io, uint32_t corner,
                                                 uint32_t opposite, uint32_t a,
                                                 uint32_t b, bool implied_seam,
                                                 uint8_t *bit) {
  const int num_attributes =
      kNumAttributes > 0 ? kNumAttributes : num_attributes_;
  const size_t num_corners = table_->num_corners() / 3 * 3;
  const size_t num_vertices = table_->num_vertices;
  uint32_t *const state = vertex_state_.data();
  const uint32_t state_a = state[a];
  const uint32_t state_b = state[b];
  bool earlier = false;
  for (int attribute = 0; attribute < num_attributes; ++attribute) {
    uint8_t *const seams = &seams_at_[attribute * num_vertices];
    uint8_t *const seam_corners = &seam_corners_[attribute * num_corners];
    bool seam;
    if (implied_seam && !earlier && attribute == num_attributes - 1) {
      seam = true;
    } else {
      const int seams_a = seams[a];
      const int seams_b = seams[b];
      // The more telling end in full, the other one short.
      int context;
      if ((seams_a | seams_b) == 0) {
        const int end_a = QuietEnd(state_a);
        const int end_b = QuietEnd(state_b);
        context = end_a >= end_b ? end_a * kNumShortEnds + end_b
                                 : end_b * kNumShortEnds + end_a;
      } else {
        const int end_a =
            seams_a == 0
                ? QuietEnd(state_a)
                : FullEnd(state_a, seams_a,
                          StepPair<true>(corner, opposite, seam_corners));
        const int end_b =
            seams_b == 0
                ? QuietEnd(state_b)
                : FullEnd(state_b, seams_b,
                          StepPair<false>(corner, opposite, seam_corners));
        context = end_a >= end_b
                      ? end_a * kNumShortEnds + ShortEnd(state_b, seams_b)
                      : end_b * kNumShortEnds + ShortEnd(state_a, seams_a);
      }
      const int plane = attribute == 0 ? 0 : 1 + earlier;
      seam = CodeFlag(io, &probabilities_[plane * kNumEdgeContexts + context],
                      bit[attribute] != 0);
    }
    bit[attribute] = seam;
    if (seam) {
      // Counts saturate (their contexts do at 3).
      seams[a] = static_cast<uint8_t>(std::min(seams[a] + 1, 255));
      seams[b] = static_cast<uint8_t>(std::min(seams[b] + 1, 255));
      seam_corners[corner] = 1;
      seam_corners[opposite] = 1;
      state[a] |= kHasSeam;
      state[b] |= kHasSeam;
      earlier = true;
    }
  }
}

template <class TableT>
template <int kNumAttributes, class BitIoT>
bool UvSeamContextCoder<TableT>::CodeBits(BitIoT *io, uint8_t *bits) {
  const TableT &table = *table_;
  const int num_attributes =
      kNumAttributes > 0 ? kNumAttributes : num_attributes_;
  const uint32_t num_corners = table.num_corners() / 3 * 3;
  uint32_t *const state = vertex_state_.data();
  uint8_t *bit = bits;
  // Per quiet class, 0 before its first quiet edge and after one with a
  // seam: the next one starts a run.
  uint32_t countdown[kNumQuietClasses] = {};
  // Codes the edge opposite |corner| of the face starting at |first|, with
  // ends |a| at Next(corner) and |b|; false on a corrupt run length.
  const auto code_edge = [&](uint32_t first, uint32_t corner, uint32_t a,
                             uint32_t b) {
    const uint32_t opposite = table.Opposite(corner);
    // Boundary edges (kBoundary + 1 wraps to 0) and edges of earlier faces
    // have no bit.
    if (opposite + 1 <= first) {
      return true;
    }
    if (((state[a] | state[b]) & (kOnBoundary | kHasSeam)) != 0) {
      CodeEdge<kNumAttributes>(io, corner, opposite, a, b, false, bit);
    } else {
      const int quiet_class = QuietClass(state[a], state[b]);
      uint32_t *const left = &countdown[quiet_class];
      if (*left == 0 && !CodeRun(io, quiet_class, left)) {
        return false;
      }
      if (--*left == 0) {
        // The quiet edge that ends the run has a seam.
        CodeEdge<kNumAttributes>(io, corner, opposite, a, b, true, bit);
      }
    }
    bit += num_attributes;
    state[a] -= kOneEdge;
    state[b] -= kOneEdge;
    return true;
  };
  for (uint32_t first = 0; first < num_corners; first += 3) {
    const uint32_t v0 = table.Vertex(first);
    const uint32_t v1 = table.Vertex(first + 1);
    const uint32_t v2 = table.Vertex(first + 2);
    if (!code_edge(first, first, v1, v2) ||
        !code_edge(first, first + 1, v2, v0) ||
        !code_edge(first, first + 2, v0, v1)) {
      return false;
    }
  }
  // A run that the quiet edges did not use up is corrupt. (kEndless stays
  // above num_edges_: there are fewer than 2^31 edges.)
  return std::all_of(countdown, countdown + kNumQuietClasses,
                     [this](uint32_t left) {
                       return left == 0 || left > num_edges_;
                     });
}

// Encodes |bits| (Draco's seam bits of |table|, edge-major, num_edges() *
// |num_attributes|) with the check bits; false if their number is wrong or
// the table is invalid.
bool EncodeUvSeams(const UvSeamCornerTable &table, int num_attributes,
                   const std::vector<uint8_t> &bits,
                   std::vector<uint8_t> *bytes);

// Bit I/O of the decoder for UvSeamContextCoder::Code().
class UvSeamDecodingIo {
 public:
  UvSeamDecodingIo(const uint8_t *data, size_t size) : coder_(data, size) {}
  bool Code(uint32_t probability_of_one, bool /* bit */) {
    return coder_.DecodeBit(probability_of_one);
  }
  uint32_t NextRun(int /* quiet_class */) const { return 0; }
  const UvSeamRangeDecoder &coder() const { return coder_; }

 private:
  UvSeamRangeDecoder coder_;
};

// Decodes the seam bits of |table| for |num_attributes| attributes from
// |size| bytes at |data| into |bits| (edge-major, Draco's order); false if
// the bytes are not a complete stream of EncodeUvSeams() for them: the
// check bits catch altered bytes (all but a 2^-14 fraction of them), the
// range coder's tail truncation and trailing bytes.
template <class TableT>
bool DecodeUvSeams(const TableT &table, int num_attributes, const uint8_t *data,
                   size_t size, std::vector<uint8_t> *bits) {
  UvSeamContextCoder<TableT> coder;
  if (!coder.Init(table, num_attributes)) {
    return false;
  }
  bits->assign(coder.num_edges() * num_attributes, 0);
  UvSeamDecodingIo io(data, size);
  return coder.Code(&io, bits->data()) && io.coder().Finish();
}

}  // namespace draco

#endif  // DRACO_EXT_SEAMS_UV_SEAM_CODER_H_
