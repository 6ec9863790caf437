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
// static probability per attribute. This coder codes the same bits, in an
// order and with contexts that follow the structure of seams:
//
//  * Seams form chains: once a seam edge reaches a vertex, the chain almost
//    always continues there. The coder walks the chains: it visits vertices
//    in fan order, decides all undecided edges of a vertex, and when an edge
//    turns out to be a seam it continues at the edge's other end (depth
//    first) before resuming the scan.
//  * Around a vertex, it first decides the edge farthest (in the ring) from
//    the seams and boundaries already known there, where a continuing chain
//    most likely leaves.
//  * Each bit is predicted from what the decoder knows at that point: seams
//    already decided at both ends, boundary flags, the ring distance class,
//    undecided edges left at both ends, the decided state of the four other
//    edges of the edge's two faces, the ring size, and whether an earlier
//    attribute has a seam on the same edge (UV sets and per-corner normals
//    often share seams). Three context models are mixed (UvSeamBitModel)
//    and drive a range coder (UvSeamRangeCoder).
//
// Everything is integer arithmetic on the connectivity alone, decoded
// before any attribute values; geometry (e.g. dihedral angles) would need
// the seams decoded after the positions (see BENCHMARKS.md for what that
// would be worth). The coder reproduces the bits exactly, so the decoded
// seams, vertices and attribute values are those of stock Draco, including
// Draco's treatment of complex and non-manifold vertices (it works on
// Draco's own corner fans).
#ifndef DRACO_EXT_SEAMS_UV_SEAM_CODER_H_
#define DRACO_EXT_SEAMS_UV_SEAM_CODER_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "draco_ext/seams/uv_seam_topology.h"

namespace draco {

// Seam flags of one attribute, one byte (0 or 1) per edge of a topology.
typedef std::vector<uint8_t> UvSeamFlags;

// Codes the seams of every attribute (|seams|[i] has one flag per edge of
// |topology|), then 14 check bits, and returns the coded bytes.
std::vector<uint8_t> EncodeUvSeams(const UvSeamTopology &topology,
                                   const std::vector<UvSeamFlags> &seams);

// Decodes |num_attributes| seam flag sets from |size| bytes at |data|;
// false if the bytes are not a complete stream of EncodeUvSeams() for
// |topology| and |num_attributes|: 14 check bits after the seams catch
// altered bytes (all but a 2^-14 fraction of them), the range coder's tail
// truncation and trailing bytes.
bool DecodeUvSeams(const UvSeamTopology &topology, int num_attributes,
                   const uint8_t *data, size_t size,
                   std::vector<UvSeamFlags> *seams);

}  // namespace draco

#endif  // DRACO_EXT_SEAMS_UV_SEAM_CODER_H_
