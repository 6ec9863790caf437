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
#include "draco_ext/eval/uv_seam_stats.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "draco/compression/bit_coders/rans_bit_encoder.h"
#include "draco/compression/mesh/mesh_edgebreaker_decoder.h"
#include "draco/core/varint_encoding.h"
#include "draco/mesh/mesh_attribute_corner_table.h"
#include "draco_ext/seams/uv_seam_edgebreaker.h"
#include "draco_ext/seams/uv_seam_range_coder.h"

namespace draco {

namespace {

// One adaptive probability: (n1 + 1/2) / (n + 1), Krichevsky-Trofimov.
class AdaptiveBit {
 public:
  void Encode(bool bit, UvSeamRangeEncoder *encoder) {
    const int p = ((2 * count_[1] + 1) << kUvSeamProbabilityBits) /
                  (2 * (count_[0] + count_[1]) + 2);
    encoder->EncodeBit(bit, std::min(std::max(p, 1), 4095));
    ++count_[bit];
  }

 private:
  int64_t count_[2] = {0, 0};
};

// A stream as a Draco traversal buffer would hold it: varint length, bytes.
int64_t FramedSize(size_t bytes) {
  EncoderBuffer length;
  EncodeVarint(static_cast<uint32_t>(bytes), &length);
  return static_cast<int64_t>(length.size() + bytes);
}

double BinaryEntropy(double p) {
  return p <= 0 || p >= 1 ? 0
                          : -(p * std::log2(p) + (1 - p) * std::log2(1 - p));
}

// The interior edges of |table| in Draco's seam order (uv_seam_coder.h),
// each as the corner it is opposite to.
std::vector<uint32_t> DracoSeamEdgeCorners(const UvSeamCornerTable &table) {
  std::vector<uint32_t> corners;
  for (uint32_t c = 0; c < table.num_corners(); ++c) {
    const uint32_t opposite = table.Opposite(c);
    if (opposite != UvSeamCornerTable::kBoundary && opposite / 3 >= c / 3) {
      corners.push_back(c);
    }
  }
  return corners;
}

// The two vertices of the edge opposite to |corner|.
std::array<uint32_t, 2> EdgeVertices(const UvSeamCornerTable &table,
                                     uint32_t corner) {
  const uint32_t first = corner / 3 * 3;
  return {table.Vertex(first + (corner - first + 1) % 3),
          table.Vertex(first + (corner - first + 2) % 3)};
}

// Per-vertex crease flags of one attribute (Isenburg & Snoeyink 2000): a
// vertex's flag is skipped when a known crease implies it or when all its
// edges are decided; a flagged vertex's last undecided edge is skipped
// when it must be the crease.
void EncodePerVertexFlags(const UvSeamProblem &problem, int attribute,
                          UvSeamRangeEncoder *encoder) {
  constexpr uint8_t kUndecided = 2;
  const size_t num_edges = problem.edge_corners.size();
  std::vector<std::vector<uint32_t>> edges_at(problem.table.num_vertices);
  for (size_t e = 0; e < num_edges; ++e) {
    for (const uint32_t v :
         EdgeVertices(problem.table, problem.edge_corners[e])) {
      edges_at[v].push_back(static_cast<uint32_t>(e));
    }
  }
  auto seam = [&](uint32_t e) {
    return problem.bits[e * problem.num_attributes + attribute] != 0;
  };
  std::vector<uint8_t> state(num_edges, kUndecided);
  AdaptiveBit flag_bit, edge_bit;
  for (const std::vector<uint32_t> &ring : edges_at) {
    std::vector<uint32_t> undecided;
    bool known_crease = false;
    bool has_crease = false;
    for (const uint32_t e : ring) {
      has_crease = has_crease || seam(e);
      if (state[e] == kUndecided) {
        undecided.push_back(e);
      } else {
        known_crease = known_crease || state[e] == 1;
      }
    }
    if (undecided.empty()) {
      continue;
    }
    if (!known_crease) {
      flag_bit.Encode(has_crease, encoder);
    }
    bool crease_seen = known_crease;
    for (size_t i = 0; i < undecided.size(); ++i) {
      const uint32_t e = undecided[i];
      state[e] = seam(e);
      const bool implied =
          !has_crease || (i + 1 == undecided.size() && !crease_seen);
      if (!implied) {
        edge_bit.Encode(seam(e), encoder);
      }
      crease_seen = crease_seen || seam(e);
    }
  }
}

}  // namespace

StatusOr<UvSeamProblem> BuildUvSeamProblem(const Mesh &mesh,
                                           const UvEncodeSettings &settings) {
  UvEncodeSettings stock = settings;
  stock.uv.seams = UvSeamCoding::kDraco;
  EncoderBuffer encoded;
  DRACO_RETURN_IF_ERROR(EncodeMeshWithSettings(mesh, stock, &encoded));
  // Draco's Edgebreaker decoder itself, to read its corner tables.
  DecoderBuffer buffer;
  buffer.Init(encoded.data(), encoded.size());
  DracoHeader header;
  DRACO_RETURN_IF_ERROR(PointCloudDecoder::DecodeHeader(&buffer, &header));
  if (header.encoder_method != MESH_EDGEBREAKER_ENCODING) {
    return Status(Status::DRACO_ERROR, "Seams need Edgebreaker (-cl 1..10).");
  }
  buffer.Init(encoded.data(), encoded.size());
  MeshEdgebreakerDecoder decoder;
  Mesh decoded;
  DRACO_RETURN_IF_ERROR(decoder.Decode(DecoderOptions(), &buffer, &decoded));
  UvSeamProblem problem;
  problem.table = UvSeamCornerTableOf(*decoder.GetCornerTable());
  problem.edge_corners = DracoSeamEdgeCorners(problem.table);
  // Draco's attribute data: the non-position attributes in attribute order.
  std::vector<const MeshAttributeCornerTable *> att_tables;
  for (int i = 0; i < mesh.num_attributes(); ++i) {
    const PointAttribute *const att = mesh.attribute(i);
    if (att->attribute_type() == GeometryAttribute::POSITION) {
      continue;
    }
    const int decoded_id = decoded.GetAttributeIdByUniqueId(att->unique_id());
    if (decoded_id < 0) {
      return Status(Status::DRACO_ERROR, "Attribute lost in decoding.");
    }
    // Null for attributes Draco codes per vertex: they have no seams.
    att_tables.push_back(decoder.GetAttributeCornerTable(decoded_id));
  }
  problem.num_attributes = static_cast<int>(att_tables.size());
  for (const uint32_t corner : problem.edge_corners) {
    for (const MeshAttributeCornerTable *const att_table : att_tables) {
      problem.bits.push_back(
          att_table != nullptr &&
          att_table->IsCornerOppositeToSeamEdge(CornerIndex(corner)));
    }
  }
  return problem;
}

int64_t PerEdgeSeamBytes(const UvSeamProblem &problem) {
  UvSeamRangeEncoder encoder;
  for (int a = 0; a < problem.num_attributes; ++a) {
    AdaptiveBit bit;
    for (size_t i = a; i < problem.bits.size(); i += problem.num_attributes) {
      bit.Encode(problem.bits[i] != 0, &encoder);
    }
  }
  return FramedSize(encoder.Finish().size());
}

int64_t PerVertexSeamBytes(const UvSeamProblem &problem) {
  UvSeamRangeEncoder encoder;
  for (int a = 0; a < problem.num_attributes; ++a) {
    EncodePerVertexFlags(problem, a, &encoder);
  }
  return FramedSize(encoder.Finish().size());
}

int64_t StockSeamStreamBytes(const UvSeamProblem &problem) {
  int64_t bytes = 0;
  for (int a = 0; a < problem.num_attributes; ++a) {
    RAnsBitEncoder encoder;
    encoder.StartEncoding();
    for (size_t i = a; i < problem.bits.size(); i += problem.num_attributes) {
      encoder.EncodeBit(problem.bits[i] != 0);
    }
    EncoderBuffer buffer;
    encoder.EndEncoding(&buffer);
    bytes += static_cast<int64_t>(buffer.size());
  }
  return bytes;
}

int64_t ContextSeamStreamBytes(const UvSeamProblem &problem) {
  std::vector<uint8_t> bytes;
  if (!EncodeUvSeams(problem.table, problem.num_attributes, problem.bits,
                     &bytes)) {
    return -1;
  }
  return FramedSize(bytes.size());
}

StatusOr<UvSeamStats> MeasureUvSeams(const std::string &name, const Mesh &mesh,
                                     const UvEncodeSettings &settings) {
  DRACO_ASSIGN_OR_RETURN(const UvSeamProblem problem,
                         BuildUvSeamProblem(mesh, settings));
  UvSeamStats stats;
  stats.mesh = name;
  stats.attributes = problem.num_attributes;
  stats.vertices = problem.table.num_vertices;
  stats.interior_edges = static_cast<int64_t>(problem.edge_corners.size());
  for (int a = 0; a < problem.num_attributes; ++a) {
    int64_t seam_edges = 0;
    for (size_t i = a; i < problem.bits.size(); i += problem.num_attributes) {
      seam_edges += problem.bits[i];
    }
    stats.seam_edges += seam_edges;
    if (stats.interior_edges > 0) {
      stats.per_edge_entropy_bytes +=
          stats.interior_edges / 8.0 *
          BinaryEntropy(static_cast<double>(seam_edges) / stats.interior_edges);
    }
  }
  stats.per_edge_bytes = PerEdgeSeamBytes(problem);
  stats.per_vertex_bytes = PerVertexSeamBytes(problem);
  stats.stock_bytes = StockSeamStreamBytes(problem);
  stats.context_bytes = ContextSeamStreamBytes(problem);
  if (stats.attributes > 0 && stats.interior_edges > 0) {
    // Eqs. 1-2 per attribute: p_c crease ratio, p_cv = 1 - (1 - p_c)^6.
    const double p_c = static_cast<double>(stats.seam_edges) /
                       (stats.attributes * stats.interior_edges);
    const double p_cv = 1 - std::pow(1 - p_c, 6);
    stats.eq1_bpv = stats.attributes * 3 * BinaryEntropy(p_c);
    stats.eq2_bpv = stats.attributes *
                    (BinaryEntropy(p_cv) + 6 * p_cv * BinaryEntropy(p_c));
  }
  UvEncodeSettings stock = settings;
  stock.uv.seams = UvSeamCoding::kDraco;
  UvEncodeSettings context = settings;
  context.uv.seams = UvSeamCoding::kContext;
  EncoderBuffer stock_file, context_file;
  DRACO_RETURN_IF_ERROR(EncodeMeshWithSettings(mesh, stock, &stock_file));
  DRACO_RETURN_IF_ERROR(EncodeMeshWithSettings(mesh, context, &context_file));
  stats.sizes_match_files = static_cast<int64_t>(context_file.size()) -
                                static_cast<int64_t>(stock_file.size()) ==
                            stats.context_bytes - stats.stock_bytes;
  return stats;
}

}  // namespace draco
