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
// What both sides of uv_seam_edgebreaker.h share; the encoder and decoder
// sides are in uv_seam_edgebreaker_encoder.cc and
// uv_seam_edgebreaker_decoder.cc (apart, so that a build of only one side,
// such as Draco's WebAssembly encoder, needs none of the other's code).
#include "draco_ext/seams/uv_seam_edgebreaker.h"

#include "draco/compression/config/compression_shared.h"
#include "draco_ext/seams/uv_seam_topology.h"

namespace draco {

bool IsUvSeamEdgebreakerMethod(int method) {
  return method == MESH_EDGEBREAKER_STANDARD_CONTEXT_SEAMS_ENCODING ||
         method == MESH_EDGEBREAKER_VALENCE_CONTEXT_SEAMS_ENCODING;
}

bool OppositesInDecoderOrder(const CornerTable &table,
                             const std::vector<CornerIndex> &face_corners,
                             std::vector<int32_t> *opposite) {
  // Decoder corner of every encoder corner of an encoded face.
  std::vector<int32_t> decoder_corner(table.num_corners(),
                                      UvSeamTopology::kBoundary);
  for (size_t face = 0; face < face_corners.size(); ++face) {
    const CornerIndex first = face_corners[face];
    const CornerIndex corners[3] = {first, table.Next(first),
                                    table.Previous(first)};
    for (int i = 0; i < 3; ++i) {
      decoder_corner[corners[i].value()] = static_cast<int32_t>(3 * face + i);
    }
  }
  opposite->assign(3 * face_corners.size(), UvSeamTopology::kBoundary);
  for (CornerIndex c(0); c < table.num_corners(); ++c) {
    const int32_t corner = decoder_corner[c.value()];
    const CornerIndex other = table.Opposite(c);
    if (corner == UvSeamTopology::kBoundary || other == kInvalidCornerIndex) {
      continue;
    }
    (*opposite)[corner] = decoder_corner[other.value()];
    if ((*opposite)[corner] == UvSeamTopology::kBoundary) {
      return false;  // The opposite face was not encoded.
    }
  }
  return true;
}

std::vector<int32_t> OppositesOf(const CornerTable &table) {
  std::vector<int32_t> opposite(table.num_corners());
  for (CornerIndex c(0); c < table.num_corners(); ++c) {
    const CornerIndex other = table.Opposite(c);
    opposite[c.value()] = other == kInvalidCornerIndex
                              ? UvSeamTopology::kBoundary
                              : other.value();
  }
  return opposite;
}

}  // namespace draco
