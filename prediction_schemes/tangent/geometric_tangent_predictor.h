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
// The prediction of MESH_PREDICTION_GEOMETRIC_TANGENT: a vertex's tangent
// computed from the decoded positions, normals and texture coordinates the
// way the tangent's writer computed it, in fixed point.
//
// Based on:
//   [Mikkelsen 2008] M. Mikkelsen: Simulation of wrinkled surfaces
//     revisited. MSc thesis, University of Copenhagen; the MikkTSpace
//     reference code (mikktspace.c, "EvalTspace") that glTF names for
//     tangents.
//   [Lengyel 2001] E. Lengyel: Computing tangent space basis vectors for an
//     arbitrary mesh. Terathon (per-face tangents from UV gradients).
#ifndef PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_PREDICTOR_H_
#define PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_PREDICTOR_H_

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

#include "draco/attributes/point_attribute.h"
#include "draco/mesh/mesh.h"
#include "prediction_schemes/tangent/geometric_tangent_settings.h"
#include "prediction_schemes/tangent/tangent_geometry.h"

namespace draco {

// The integer components of a parent attribute by point. Read in place
// where the attribute holds 4-byte integers (Draco's portable attributes:
// int32 in the decoder, uint32 in the encoder, the same bits), else from a
// copy converted once; either way a value costs one address computation
// instead of PointAttribute::ConvertValue()'s type dispatch.
template <int N>
class TangentParentValues {
 public:
  void Init(const PointAttribute &att) {
    att_ = &att;
    copy_.clear();
    if ((att.data_type() == DT_INT32 || att.data_type() == DT_UINT32) &&
        att.byte_stride() >= static_cast<int64_t>(sizeof(int32_t) * N) &&
        att.size() > 0) {
      base_ = att.GetAddress(AttributeValueIndex(0));
      stride_ = att.byte_stride();
      return;
    }
    copy_.resize(att.size() * N);
    for (AttributeValueIndex i(0); i < static_cast<uint32_t>(att.size()); ++i) {
      int64_t value[N] = {};
      att.ConvertValue(i, N, value);
      for (int c = 0; c < N; ++c) {
        copy_[N * i.value() + c] = static_cast<int32_t>(std::clamp<int64_t>(
            value[c], INT32_MIN, INT32_MAX));
      }
    }
    base_ = reinterpret_cast<const uint8_t *>(copy_.data());
    stride_ = sizeof(int32_t) * N;
  }
  void Get(PointIndex point, int32_t *value) const {
    std::memcpy(value, base_ + stride_ * att_->mapped_index(point).value(),
                sizeof(int32_t) * N);
  }

 private:
  const PointAttribute *att_ = nullptr;
  const uint8_t *base_ = nullptr;
  int64_t stride_ = 0;
  std::vector<int32_t> copy_;
};

// What the predictor says about one tangent.
struct GeometricTangentPrediction {
  // False when no triangle around the vertex has a UV gradient (all of them
  // degenerate in 3D or in UV); the other members are then meaningless.
  bool valid = false;
  TangentVec3 tangent = {0, 0, 0};    // Unit (kTangentUnit).
  // plane normal x tangent, in any length up to 2^50: only its direction
  // serves.
  TangentVec3 bitangent = {0, 0, 0};
  // +1 where the vertex's UV triangles are counter-clockwise (by weight),
  // else -1.
  int handedness = 1;
  // kFace: the triangle when only one gave the prediction, else -1 (two
  // entries with the same single triangle have the same kFace tangent).
  int single_face = -1;
};

// Computes GeometricTangentPrediction per tangent entry from the parents:
// quantised positions (3 integer components), octahedral normals (Draco's
// 2 portable components) and quantised texture coordinates (2 integer
// components), with MeshDataT the tangent attribute's Draco mesh data.
//
// ComputeSums() visits every triangle once: its UV gradient dP/du, as
// MikkTSpace's vOs = dv2 e1 - dv1 e2 with the sign of the UV area,
// normalised, weighted by each corner's angle (kMikkTSpace) or by one, is
// added to the entry of each of its corners, with its UV orientation (and,
// for kFace, its unit normal). The corners of one entry are the corners
// around its vertex that share the tangent's value (Draco's attribute
// connectivity), as MikkTSpace sums the corners of a group: corners with the
// same position, normal and UV, and the same UV orientation, whose tangents
// are therefore equal. Triangles without area in 3D or in UV add nothing,
// as MikkTSpace's degenerate triangles.
// Predict() turns an entry's sum into its tangent: kMikkTSpace and
// kUniform project it onto the plane of the vertex normal, kFace keeps it
// and takes the plane of the mean triangle normal instead; the handedness
// is the orientation with the larger weight.
//
// Weak where the writer grouped corners differently from the tangent's
// Draco value (a tangent value shared across a UV seam sums two groups,
// which only matters where their tangents differ, and then Draco splits
// them), where it skipped degenerate triangles differently, and where the
// quantised UVs of small triangles turn the gradient (qt 12 on a triangle a
// few texels wide). MikkTSpace projects the edges onto the normal plane
// before measuring a corner's angle; here the 3D angle is used, and
// approximated within 0.072 radian (tangent_geometry.h).
template <class MeshDataT>
class GeometricTangentPredictor {
 public:
  // Takes a parent attribute by its type; false for one the prediction
  // cannot use (not integer, wrong component count, another type).
  bool SetParentAttribute(const PointAttribute *att) {
    if (att == nullptr || !IsDataTypeIntegral(att->data_type())) {
      return false;
    }
    switch (att->attribute_type()) {
      case GeometryAttribute::POSITION:
        return Take(att, 3, &positions_);
      case GeometryAttribute::NORMAL:
        return Take(att, 2, &normals_);
      case GeometryAttribute::TEX_COORD:
        return Take(att, 2, &tex_coords_);
      default:
        return false;
    }
  }
  bool IsInitialized() const {
    return positions_ != nullptr && normals_ != nullptr &&
           tex_coords_ != nullptr;
  }

  // Sums every triangle's part of the predictions of |kind| into the
  // entries of |mesh_data|; |normal_bits| are the normals' octahedral bits.
  // Call before Predict().
  void ComputeSums(const MeshDataT &mesh_data, GeometricTangentKind kind,
                   int normal_bits);

  // The prediction of |entry|.
  GeometricTangentPrediction Predict(const MeshDataT &mesh_data,
                                     int entry) const;

 private:
  struct Face {
    TangentVec3 direction;  // Unit dP/du.
    TangentVec3 normal;     // Unit triangle normal (kFace only).
    std::array<int32_t, 3> weight;
    int orientation;        // +1, -1; 0: no gradient.
  };
  struct Sums {
    TangentVec3 direction = {0, 0, 0};
    TangentVec3 normal = {0, 0, 0};  // kFace only.
    int64_t orientation = 0;  // Sum of weight * orientation.
    // Corners summed and the last one's face: counted for kFace, and for
    // the others only in meshes where an entry could reach
    // kTangentMaxCornersPerEntry.
    int32_t num_faces = 0;
    int32_t last_face = -1;
  };

  static bool Take(const PointAttribute *att, int num_components,
                   const PointAttribute **slot) {
    if (att->num_components() != num_components) {
      return false;
    }
    *slot = att;
    return true;
  }
  bool ComputeFace(const Mesh::Face &points, Face *result) const;
  // Adds |face| (of index |f|) to the |entries| of its corners (-1: none);
  // with |count|, only to entries of fewer than kTangentMaxCornersPerEntry
  // corners, and counting them.
  template <bool count>
  void AddFace(const Face &face, int f, const int32_t *entries);

  const PointAttribute *positions_ = nullptr;
  const PointAttribute *normals_ = nullptr;
  const PointAttribute *tex_coords_ = nullptr;
  GeometricTangentKind kind_ = GeometricTangentKind::kMikkTSpace;
  int normal_bits_ = 0;
  TangentParentValues<3> position_values_;
  TangentParentValues<2> normal_values_;
  TangentParentValues<2> tex_coord_values_;
  std::vector<Sums> sums_;
};

// A vertex of more corners than this would let the sums overflow; no real
// mesh comes near it.
constexpr int32_t kTangentMaxCornersPerEntry = 1 << 20;

template <class MeshDataT>
void GeometricTangentPredictor<MeshDataT>::ComputeSums(
    const MeshDataT &mesh_data, GeometricTangentKind kind, int normal_bits) {
  kind_ = kind;
  normal_bits_ = normal_bits;
  position_values_.Init(*positions_);
  normal_values_.Init(*normals_);
  tex_coord_values_.Init(*tex_coords_);
  const Mesh &mesh = *mesh_data.mesh();
  const auto *const table = mesh_data.corner_table();
  const std::vector<int32_t> &vertex_to_data = *mesh_data.vertex_to_data_map();
  const uint32_t num_vertices = static_cast<uint32_t>(vertex_to_data.size());
  const uint32_t num_entries =
      static_cast<uint32_t>(mesh_data.data_to_corner_map()->size());
  sums_.assign(num_entries, Sums());
  const int num_faces = table->num_faces();
  // Entries can reach the limit only in meshes of that many corners; kFace
  // needs the counts anyway.
  const bool count = kind_ == GeometricTangentKind::kFace ||
                     3 * int64_t{num_faces} >= kTangentMaxCornersPerEntry;
  Face face;
  for (int f = 0; f < num_faces; ++f) {
    if (!ComputeFace(mesh.face(FaceIndex(f)), &face)) {
      continue;
    }
    int32_t entries[3];
    for (int k = 0; k < 3; ++k) {
      const uint32_t vertex = table->Vertex(CornerIndex(3 * f + k)).value();
      entries[k] = vertex < num_vertices ? vertex_to_data[vertex] : -1;
      if (static_cast<uint32_t>(entries[k]) >= num_entries) {
        entries[k] = -1;
      }
    }
    if (count) {
      AddFace<true>(face, f, entries);
    } else {
      AddFace<false>(face, f, entries);
    }
  }
}

template <class MeshDataT>
template <bool count>
void GeometricTangentPredictor<MeshDataT>::AddFace(const Face &face, int f,
                                                   const int32_t *entries) {
  for (int k = 0; k < 3; ++k) {
    if (entries[k] < 0) {
      continue;
    }
    Sums &sums = sums_[entries[k]];
    if (count) {
      if (sums.num_faces >= kTangentMaxCornersPerEntry) {
        continue;
      }
      ++sums.num_faces;
      sums.last_face = f;
    }
    const int64_t weight = face.weight[k];
    for (int i = 0; i < 3; ++i) {
      sums.direction[i] += weight * face.direction[i];
    }
    if (kind_ == GeometricTangentKind::kFace) {
      for (int i = 0; i < 3; ++i) {
        sums.normal[i] += weight * face.normal[i];
      }
    }
    sums.orientation += weight * face.orientation;
  }
}

// MikkTSpace's per-triangle tangent (InitTriInfo(): vOs and the UV
// orientation flag) and its corner angles (EvalTspace()); false for a
// triangle without a UV gradient.
template <class MeshDataT>
bool GeometricTangentPredictor<MeshDataT>::ComputeFace(
    const Mesh::Face &points, Face *result) const {
  int32_t p[3][3];
  int32_t uv[3][2];
  for (int k = 0; k < 3; ++k) {
    position_values_.Get(points[k], p[k]);
    tex_coord_values_.Get(points[k], uv[k]);
  }
  TangentVec3 e1, e2;
  for (int i = 0; i < 3; ++i) {
    e1[i] = int64_t{p[1][i]} - p[0][i];
    e2[i] = int64_t{p[2][i]} - p[0][i];
  }
  const int edge_shift = ShiftBelow(MaxAbsBits(e1) | MaxAbsBits(e2), 30);
  e1 = ShiftRight(e1, edge_shift);
  e2 = ShiftRight(e2, edge_shift);
  TangentVec3 d1 = {int64_t{uv[1][0]} - uv[0][0], int64_t{uv[1][1]} - uv[0][1],
                    0};
  TangentVec3 d2 = {int64_t{uv[2][0]} - uv[0][0], int64_t{uv[2][1]} - uv[0][1],
                    0};
  const int uv_shift = ShiftBelow(MaxAbsBits(d1) | MaxAbsBits(d2), 30);
  d1 = ShiftRight(d1, uv_shift);
  d2 = ShiftRight(d2, uv_shift);
  const int64_t twice_uv_area = d1[0] * d2[1] - d2[0] * d1[1];
  if (twice_uv_area == 0) {
    return false;
  }
  TangentVec3 gradient;
  for (int i = 0; i < 3; ++i) {
    gradient[i] = d2[1] * e1[i] - d1[1] * e2[i];
  }
  const TangentVec3 normal = Cross(e1, e2);
  if (normal == TangentVec3{0, 0, 0} ||
      !NormalizeToUnit(gradient, &result->direction)) {
    return false;
  }
  result->orientation = twice_uv_area > 0 ? 1 : -1;
  if (twice_uv_area < 0) {
    for (int64_t &c : result->direction) {
      c = -c;
    }
  }
  if (kind_ == GeometricTangentKind::kMikkTSpace) {
    result->weight = CornerAngles(e1, e2, normal);
  } else {
    result->weight = {1, 1, 1};
  }
  if (kind_ == GeometricTangentKind::kFace) {
    NormalizeToUnit(normal, &result->normal);
  }
  return true;
}

// MikkTSpace's EvalTspace(): the weighted sum of the triangles' gradients
// around the vertex, projected onto the normal plane and normalised.
template <class MeshDataT>
GeometricTangentPrediction GeometricTangentPredictor<MeshDataT>::Predict(
    const MeshDataT &mesh_data, int entry) const {
  GeometricTangentPrediction prediction;
  const Sums &sums = sums_[entry];
  // kMikkTSpace and kUniform count no corners: an entry without any has a
  // zero sum, which projects to no prediction below.
  if (kind_ == GeometricTangentKind::kFace && sums.num_faces == 0) {
    return prediction;
  }
  prediction.handedness = sums.orientation >= 0 ? 1 : -1;
  TangentVec3 plane_normal;
  if (kind_ == GeometricTangentKind::kFace) {
    if (!NormalizeToUnit(sums.direction, &prediction.tangent) ||
        !NormalizeToUnit(sums.normal, &plane_normal)) {
      return prediction;
    }
    if (sums.num_faces == 1) {
      prediction.single_face = sums.last_face;
    }
  } else {
    const PointIndex point = mesh_data.mesh()->CornerToPointId(
        (*mesh_data.data_to_corner_map())[entry]);
    int32_t octahedral[2];
    normal_values_.Get(point, octahedral);
    plane_normal =
        OctahedralToVector(octahedral[0], octahedral[1], normal_bits_);
    if (!NormalizeToUnit(ProjectOntoPlane(sums.direction, plane_normal),
                         &prediction.tangent)) {
      return prediction;
    }
    plane_normal = ShiftRight(plane_normal,
                              ShiftBelow(MaxAbsBits(plane_normal), 24));
  }
  // The bitangent only serves its direction (the axis order and a ratio).
  prediction.bitangent = Cross(plane_normal, prediction.tangent);
  prediction.valid = true;
  return prediction;
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_PREDICTOR_H_
