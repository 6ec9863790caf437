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
// The analysis of [Váša & Brunnett 2014] section 3 (eqs. 1-2, fig. 3) with
// measured instead of modelled numbers: what texture connectivity costs per
// mesh vertex when coded as
//
//  * per-edge bits: the paper's proposal, one bit per interior edge, at
//    their entropy and arithmetic coded with one adaptive probability;
//  * per-vertex flags: Taubin et al. 1998 as improved by Isenburg &
//    Snoeyink 2000, one adaptive flag per vertex that may have crease edges,
//    then one adaptive bit per undecided edge of flagged vertices, skipping
//    every bit that earlier bits imply;
//  * stock Draco: one static-probability rANS stream per attribute
//    (RAnsBitEncoder, exactly as Draco writes it);
//  * draco-uv's crease-bit coder (-uv_seams context, uv_seam_coder.h),
//    exactly as the encoder writes it;
//
// all on the same bits: those of Draco's Edgebreaker for the mesh, read
// from the corner tables of Draco's own decoder (so in its face order, with
// its treatment of non-manifold edges), for every non-position attribute.
// The first two are real range-coded sizes (UvSeamRangeEncoder), not
// entropy estimates; the last two are exactly the bytes in Draco files.
#ifndef DRACO_EXT_EVAL_UV_SEAM_STATS_H_
#define DRACO_EXT_EVAL_UV_SEAM_STATS_H_

#include <cstdint>
#include <string>
#include <vector>

#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"
#include "draco_ext/options/uv_encode_settings.h"
#include "draco_ext/seams/uv_seam_coder.h"

namespace draco {

struct UvSeamStats {
  std::string mesh;
  int attributes = 0;    // Non-position attributes (seam sets).
  int64_t vertices = 0;  // Vertices of Draco's position corner table.
  int64_t interior_edges = 0;
  int64_t seam_edges = 0;  // Summed over attributes.
  // Per-edge bits at their empirical entropy (each attribute's seam ratio
  // known in advance), the bound for any coder with one probability.
  double per_edge_entropy_bytes = 0;
  int64_t per_edge_bytes = 0;
  int64_t per_vertex_bytes = 0;
  int64_t stock_bytes = 0;    // Draco's streams, all attributes.
  int64_t context_bytes = 0;  // -uv_seams context, with its length prefix.
  // Eqs. 1 and 2 of the paper for this mesh's crease ratio, in bits per
  // vertex (three edges and valence six per vertex assumed, as there).
  double eq1_bpv = 0;
  double eq2_bpv = 0;
  // Whole files: size(-uv_seams context) - size(stock) equals
  // context_bytes - stock_bytes, i.e. the two byte counts are exact.
  bool sizes_match_files = false;
};

// Draco's Edgebreaker seam bits of every non-position attribute of a mesh,
// on the corner table of its decoder, in Draco's order.
struct UvSeamProblem {
  UvSeamCornerTable table;
  int num_attributes = 0;  // Draco's attribute data order.
  // Per interior edge in Draco's order, the corner it is opposite to.
  std::vector<uint32_t> edge_corners;
  std::vector<uint8_t> bits;  // [edge * num_attributes + attribute].
};

// Encodes |mesh| with |settings| (stock seam coding) and decodes it with
// Draco's MeshEdgebreakerDecoder, whose corner tables give the problem.
StatusOr<UvSeamProblem> BuildUvSeamProblem(const Mesh &mesh,
                                           const UvEncodeSettings &settings);

// Bytes of each coding of |problem| (see the file comment).
int64_t PerEdgeSeamBytes(const UvSeamProblem &problem);
int64_t PerVertexSeamBytes(const UvSeamProblem &problem);
int64_t StockSeamStreamBytes(const UvSeamProblem &problem);
int64_t ContextSeamStreamBytes(const UvSeamProblem &problem);

// Everything above for one mesh, at |settings| (its uv_seams is ignored).
StatusOr<UvSeamStats> MeasureUvSeams(const std::string &name, const Mesh &mesh,
                                     const UvEncodeSettings &settings);

}  // namespace draco

#endif  // DRACO_EXT_EVAL_UV_SEAM_STATS_H_
