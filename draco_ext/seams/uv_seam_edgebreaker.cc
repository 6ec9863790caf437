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

namespace draco {

bool IsUvSeamEdgebreakerMethod(int method) {
  return method == MESH_EDGEBREAKER_STANDARD_CONTEXT_SEAMS_ENCODING ||
         method == MESH_EDGEBREAKER_VALENCE_CONTEXT_SEAMS_ENCODING;
}

bool CornerTableInDecoderOrder(const CornerTable &table,
                               const std::vector<CornerIndex> &face_corners,
                               UvSeamCornerTable *decoder_table) {
  constexpr uint32_t kNone = UvSeamCornerTable::kBoundary;
  // Decoder corner of every encoder corner of an encoded face.
  std::vector<uint32_t> decoder_corner(table.num_corners(), kNone);
  decoder_table->vertex.resize(3 * face_corners.size());
  for (size_t face = 0; face < face_corners.size(); ++face) {
    const CornerIndex first = face_corners[face];
    const CornerIndex corners[3] = {first, table.Next(first),
                                    table.Previous(first)};
    for (int i = 0; i < 3; ++i) {
      decoder_corner[corners[i].value()] = static_cast<uint32_t>(3 * face + i);
      decoder_table->vertex[3 * face + i] = table.Vertex(corners[i]).value();
    }
  }
  decoder_table->num_vertices = table.num_vertices();
  decoder_table->opposite.assign(3 * face_corners.size(), kNone);
  for (CornerIndex c(0); c < table.num_corners(); ++c) {
    const uint32_t corner = decoder_corner[c.value()];
    const CornerIndex other = table.Opposite(c);
    if (corner == kNone || other == kInvalidCornerIndex) {
      continue;
    }
    decoder_table->opposite[corner] = decoder_corner[other.value()];
    if (decoder_table->opposite[corner] == kNone) {
      return false;  // The opposite face was not encoded.
    }
  }
  return true;
}

UvSeamCornerTable UvSeamCornerTableOf(const CornerTable &table) {
  UvSeamCornerTable plain;
  plain.num_vertices = table.num_vertices();
  for (CornerIndex c(0); c < table.num_corners(); ++c) {
    plain.opposite.push_back(table.Opposite(c).value());
    plain.vertex.push_back(table.Vertex(c).value());
  }
  return plain;
}

}  // namespace draco
