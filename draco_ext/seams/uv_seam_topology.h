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
// The mesh connectivity as the crease-bit seam coder sees it: the corners
// of the faces in the order Draco's Edgebreaker decoder creates them (face
// f owns corners 3f, 3f + 1, 3f + 2) and their opposite corners, nothing
// else. Encoder and decoder build it from the same information, so every
// index below is the same on both sides.
//
// Vertices are corner fans (maximal sequences of corners joined by
// swinging around a vertex), numbered in order of their smallest corner;
// this is how Draco's corner tables see vertices too, including the copies
// Draco makes of non-manifold vertices. Each fan has a ring: its edges in
// rotational order (Draco's SwingRight direction), starting at the fan's
// boundary edge if the fan is open and at the edge after its smallest
// corner otherwise. Only interior edges (two faces) carry seam bits;
// boundary edges appear in rings as kBoundary.
#ifndef DRACO_EXT_SEAMS_UV_SEAM_TOPOLOGY_H_
#define DRACO_EXT_SEAMS_UV_SEAM_TOPOLOGY_H_

#include <array>
#include <cstdint>
#include <vector>

namespace draco {

class UvSeamTopology {
 public:
  static constexpr int32_t kBoundary = -1;

  // Builds the topology from the opposite corner of every corner
  // (kBoundary if none). Fails unless |opposite| pairs corners of different
  // faces symmetrically and every edge joins two different vertices (true
  // for every Draco corner table without degenerate faces).
  bool Init(const std::vector<int32_t> &opposite);

  int num_corners() const { return static_cast<int>(opposite_.size()); }
  int num_edges() const { return static_cast<int>(edge_corner_.size()); }
  int num_vertices() const { return static_cast<int>(ring_begin_.size()) - 1; }

  // The smaller of the two corners opposite |edge|.
  int32_t EdgeCorner(int32_t edge) const { return edge_corner_[edge]; }
  // The two vertices of |edge|.
  int32_t EdgeVertex(int32_t edge, int end) const {
    return edge_vertices_[2 * edge + end];
  }
  // The four other edges of the two faces of |edge| (kBoundary entries for
  // boundary edges).
  const std::array<int32_t, 4> &Wings(int32_t edge) const {
    return wings_[edge];
  }

  // Ring of |vertex|: edges from RingBegin() to RingEnd().
  const int32_t *RingBegin(int32_t vertex) const {
    return ring_.data() + ring_begin_[vertex];
  }
  const int32_t *RingEnd(int32_t vertex) const {
    return ring_.data() + ring_begin_[vertex + 1];
  }
  int RingSize(int32_t vertex) const {
    return ring_begin_[vertex + 1] - ring_begin_[vertex];
  }
  // For each ring entry, the other vertex of the edge (kBoundary for
  // boundary edges).
  const int32_t *RingNeighbors(int32_t vertex) const {
    return ring_neighbor_.data() + ring_begin_[vertex];
  }
  // Interior edges in the ring of |vertex|.
  int InteriorDegree(int32_t vertex) const { return interior_degree_[vertex]; }
  // True if the fan of |vertex| is open (the vertex lies on a boundary).
  bool IsOpen(int32_t vertex) const { return is_open_[vertex] != 0; }

  // Interior edges in the order in which Draco's Edgebreaker codes their
  // seam bits (MeshEdgebreakerDecoderImpl::DecodeAttributeConnectivitiesOnFace:
  // faces in order, each face's corners in order, every edge once, from the
  // face that comes first).
  std::vector<int32_t> DracoSeamOrder() const;

  static int32_t Next(int32_t corner) {
    return corner % 3 == 2 ? corner - 2 : corner + 1;
  }
  static int32_t Previous(int32_t corner) {
    return corner % 3 == 0 ? corner + 2 : corner - 1;
  }

 private:
  bool IsValidPairing() const;
  void NumberEdges();
  void BuildFans();
  // Fills the vertex arrays once every corner has its vertex; false if an
  // edge joins a vertex to itself.
  bool ConnectVertices();
  // Adds the fan of |corner| as a new vertex.
  void AddFan(int32_t corner);
  int32_t SwingLeft(int32_t corner) const;
  int32_t SwingRight(int32_t corner) const;

  std::vector<int32_t> opposite_;
  std::vector<int32_t> corner_edge_;
  std::vector<int32_t> edge_corner_;    // The smaller corner of each edge.
  std::vector<int32_t> edge_vertices_;  // Two per edge.
  std::vector<std::array<int32_t, 4>> wings_;
  std::vector<int32_t> corner_vertex_;
  std::vector<int32_t> ring_begin_;
  std::vector<int32_t> ring_;
  std::vector<int32_t> ring_neighbor_;
  std::vector<uint8_t> is_open_;
  std::vector<int32_t> interior_degree_;
};

}  // namespace draco

#endif  // DRACO_EXT_SEAMS_UV_SEAM_TOPOLOGY_H_
