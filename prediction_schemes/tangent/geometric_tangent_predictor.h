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
#include <memory>
#include <vector>

#include "draco/attributes/point_attribute.h"
#include "draco/mesh/mesh.h"
#include "prediction_schemes/tangent/geometric_tangent_settings.h"
#include "prediction_schemes/tangent/tangent_geometry.h"

// For the per-entry functions the coding loop calls once per entry: inlined
// there, they pass the prediction in registers instead of through memory
// (compilers otherwise keep them out of line as too large).
#if defined(__GNUC__) || defined(__clang__)
#define DRACO_UV_TANGENT_INLINE __attribute__((always_inline)) inline
#elif defined(_MSC_VER)
#define DRACO_UV_TANGENT_INLINE __forceinline
#else
#define DRACO_UV_TANGENT_INLINE inline
#endif

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
  // The predicted direction, components below 2^31, and its length
  // (rounded down, at least 1).
  TangentVec3 tangent = {0, 0, 0};
  int64_t length = 1;
  // plane normal x tangent, components below 2^44: only its direction
  // serves.
  TangentVec3 bitangent = {0, 0, 0};
  // +1 where the vertex's UV triangles are counter-clockwise (by weight),
  // else -1.
  int handedness = 1;
  // kFace: the triangle when only one gave the prediction, else -1 (two
  // entries with the same single triangle have the same kFace tangent).
  int single_face = -1;
};

// The connectivity the tangent prediction and coding read, as plain arrays
// taken once from the tangent attribute's Draco mesh data: the same for
// either of Draco's corner tables, so that the prediction and the coding
// loop are compiled once (in the WebAssembly decoder a copy per corner table
// cost 15 KB).
struct TangentConnectivity {
  const Mesh *mesh = nullptr;
  // The first corner of every entry (Draco's data_to_corner_map()).
  const CornerIndex *data_to_corner = nullptr;
  int num_entries = 0;
  int num_faces = 0;
  // Per corner of the corner table's faces, the entry at its vertex;
  // num_entries for a vertex without one (or out of the table's range).
  std::vector<uint32_t> corner_entry;
};

// Fills |connectivity| from |mesh_data| (a MeshPredictionSchemeData).
template <class MeshDataT>
void InitTangentConnectivity(const MeshDataT &mesh_data,
                             TangentConnectivity *connectivity) {
  const auto &table = *mesh_data.corner_table();
  const std::vector<int32_t> &vertex_to_data = *mesh_data.vertex_to_data_map();
  const uint32_t num_entries =
      static_cast<uint32_t>(mesh_data.data_to_corner_map()->size());
  const uint32_t num_vertices = static_cast<uint32_t>(
      std::min<size_t>(table.num_vertices(), vertex_to_data.size()));
  connectivity->mesh = mesh_data.mesh();
  connectivity->data_to_corner = mesh_data.data_to_corner_map()->data();
  connectivity->num_entries = static_cast<int>(num_entries);
  connectivity->num_faces = table.num_faces();
  connectivity->corner_entry.resize(3 * static_cast<size_t>(table.num_faces()));
  uint32_t *const corner_entry = connectivity->corner_entry.data();
  for (uint32_t c = 0; c < connectivity->corner_entry.size(); ++c) {
    const uint32_t vertex = table.ConfidentVertex(CornerIndex(c)).value();
    const uint32_t entry = vertex < num_vertices
                               ? static_cast<uint32_t>(vertex_to_data[vertex])
                               : num_entries;
    corner_entry[c] = entry < num_entries ? entry : num_entries;
  }
}

// Computes GeometricTangentPrediction per tangent entry from the parents:
// quantised positions (3 integer components), octahedral normals (Draco's
// 2 portable components) and quantised texture coordinates (2 integer
// components), on the tangent attribute's TangentConnectivity.
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
// Positions are taken below 2^15 and texture coordinates below 2^14
// (shifted there once per mesh where they are not, as with more than 15
// and 14 quantisation bits), so that a triangle's products fit 64 bits
// without a shift of its own.
//
// Weak where the writer grouped corners differently from the tangent's
// Draco value (a tangent value shared across a UV seam sums two groups,
// which only matters where their tangents differ, and then Draco splits
// them), where it skipped degenerate triangles differently, and where the
// quantised UVs of small triangles turn the gradient (qt 12 on a triangle a
// few texels wide). MikkTSpace projects the edges onto the normal plane
// before measuring a corner's angle; here the 3D angle is used, and
// approximated within 0.072 radian (tangent_geometry.h).
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
  // entries of |connectivity|; |normal_bits| are the normals' octahedral
  // bits. Call before Predict().
  void ComputeSums(const TangentConnectivity &connectivity,
                   GeometricTangentKind kind, int normal_bits);

  // The prediction of |entry|.
  DRACO_UV_TANGENT_INLINE GeometricTangentPrediction
  Predict(const TangentConnectivity &connectivity, int entry) const;

 private:
  // Positions and texture coordinates are brought below these (see above).
  static constexpr int kPositionBits = 15;
  static constexpr int kTexCoordBits = 14;
  // Plane normals are shifted below 2^kPlaneNormalBits.
  static constexpr int kPlaneNormalBits = 12;

  struct Sums {
    TangentVec3 direction = {0, 0, 0};
    int64_t orientation = 0;  // Sum of weight * orientation.
  };
  // kFace's sums besides: the unit normals, the corners and the last one's
  // face. The counts also guard the others' sums in meshes where an entry
  // could reach kMaxCornersPerEntry.
  struct FaceSums {
    TangentVec3 normal = {0, 0, 0};
    int32_t num_faces = 0;
    int32_t last_face = -1;
  };
  // A vertex of more corners than this would let the sums overflow; no real
  // mesh comes near it.
  static constexpr int32_t kMaxCornersPerEntry = 1 << 20;

  static bool Take(const PointAttribute *att, int num_components,
                   const PointAttribute **slot) {
    if (att->num_components() != num_components) {
      return false;
    }
    *slot = att;
    return true;
  }
  // Fills point_values_ for the points of |mesh|.
  void GatherPointValues(const Mesh &mesh);
  // Brings component |c| of every point value below 2^|bits| (minus the
  // smallest and shifted right) where the largest is not already.
  void FitBelow(int c, int num_components, int bits);
  // Adds every triangle's part to sums_, and with |count| to face_sums_.
  // One copy per kind, whose branches would cost a tenth of the loop's
  // instructions; |count| is a flag (a copy per value cost 4 KB of
  // WebAssembly).
  template <GeometricTangentKind kind>
  void SumFaces(const TangentConnectivity &connectivity, bool count);
  // The plane normal of |entry| for kMikkTSpace and kUniform, below
  // 2^kPlaneNormalBits.
  TangentVec3 VertexNormal(const TangentConnectivity &connectivity,
                           int entry) const;

  const PointAttribute *positions_ = nullptr;
  const PointAttribute *normals_ = nullptr;
  const PointAttribute *tex_coords_ = nullptr;
  GeometricTangentKind kind_ = GeometricTangentKind::kMikkTSpace;
  int normal_bits_ = 0;
  TangentParentValues<2> normal_values_;
  // Per point: its position and texture coordinate, brought below 2^15 and
  // 2^14. Not a std::vector: its zeroing would cost as much as the filling.
  using PointValues = std::array<int32_t, 5>;
  std::unique_ptr<PointValues[]> point_values_;
  size_t num_points_ = 0;
  size_t point_values_capacity_ = 0;
  // Per entry, and one dummy past the last.
  std::vector<Sums> sums_;
  std::vector<FaceSums> face_sums_;
};

inline void GeometricTangentPredictor::ComputeSums(
    const TangentConnectivity &connectivity, GeometricTangentKind kind,
    int normal_bits) {
  kind_ = kind;
  normal_bits_ = normal_bits;
  normal_values_.Init(*normals_);
  GatherPointValues(*connectivity.mesh);
  const size_t num_entries = connectivity.num_entries;
  // Corners of vertices without an entry add to the dummy sums past the
  // last entry.
  sums_.assign(num_entries + 1, Sums());
  const bool count =
      kind_ == GeometricTangentKind::kFace ||
      3 * int64_t{connectivity.num_faces} >= kMaxCornersPerEntry;
  face_sums_.assign(count ? num_entries + 1 : 0, FaceSums());
  switch (kind_) {
    case GeometricTangentKind::kMikkTSpace:
      SumFaces<GeometricTangentKind::kMikkTSpace>(connectivity, count);
      break;
    case GeometricTangentKind::kUniform:
      SumFaces<GeometricTangentKind::kUniform>(connectivity, count);
      break;
    case GeometricTangentKind::kFace:
      SumFaces<GeometricTangentKind::kFace>(connectivity, count);
      break;
  }
}

// Per triangle: MikkTSpace's tangent (InitTriInfo(): vOs with the sign of
// the UV orientation), normalised, and its corner angles (EvalTspace()),
// added to the entries of its corners. Positions below 2^15 and texture
// coordinates below 2^14 bound the gradient below 2^30 and the normal
// below 2^31.
inline void GeometricTangentPredictor::GatherPointValues(
    const Mesh &mesh) {
  TangentParentValues<3> positions;
  TangentParentValues<2> tex_coords;
  positions.Init(*positions_);
  tex_coords.Init(*tex_coords_);
  const size_t num_points = mesh.num_points();
  if (point_values_capacity_ < num_points) {
    point_values_.reset(new PointValues[num_points]);
    point_values_capacity_ = num_points;
  }
  num_points_ = num_points;
  // The components' bits, as unsigned: a negative one has all of them.
  uint32_t position_bits = 0, tex_coord_bits = 0;
  for (PointIndex p(0); p < static_cast<uint32_t>(num_points); ++p) {
    PointValues &values = point_values_[p.value()];
    positions.Get(p, &values[0]);
    tex_coords.Get(p, &values[3]);
    position_bits |= static_cast<uint32_t>(values[0]) |
                     static_cast<uint32_t>(values[1]) |
                     static_cast<uint32_t>(values[2]);
    tex_coord_bits |=
        static_cast<uint32_t>(values[3]) | static_cast<uint32_t>(values[4]);
  }
  if (position_bits >= (1u << kPositionBits)) {
    FitBelow(0, 3, kPositionBits);
  }
  if (tex_coord_bits >= (1u << kTexCoordBits)) {
    FitBelow(3, 2, kTexCoordBits);
  }
}

inline void GeometricTangentPredictor::FitBelow(int first, int num_components,
                                                int bits) {
  int64_t min = INT32_MAX, max = INT32_MIN;
  for (size_t p = 0; p < num_points_; ++p) {
    for (int c = first; c < first + num_components; ++c) {
      min = std::min<int64_t>(min, point_values_[p][c]);
      max = std::max<int64_t>(max, point_values_[p][c]);
    }
  }
  const int shift =
      std::max(0, BitLength(static_cast<uint64_t>(max - min)) - bits);
  for (size_t p = 0; p < num_points_; ++p) {
    for (int c = first; c < first + num_components; ++c) {
      point_values_[p][c] = static_cast<int32_t>(
          static_cast<uint64_t>(point_values_[p][c] - min) >> shift);
    }
  }
}

// Per triangle: MikkTSpace's tangent (InitTriInfo(): vOs with the sign of
// the UV orientation), normalised, and its corner angles (EvalTspace()),
// added to the entries of its corners. Positions below 2^15 and texture
// coordinates below 2^14 bound the gradient below 2^30 and the normal
// below 2^31.
template <GeometricTangentKind kind>
void GeometricTangentPredictor::SumFaces(
    const TangentConnectivity &connectivity, bool count) {
  constexpr bool angle_weights = kind == GeometricTangentKind::kMikkTSpace;
  constexpr bool face_normals = kind == GeometricTangentKind::kFace;
  const Mesh &mesh = *connectivity.mesh;
  const uint32_t *const corner_entry = connectivity.corner_entry.data();
  Sums *const all_sums = sums_.data();
  const int num_faces = connectivity.num_faces;
  for (int f = 0; f < num_faces; ++f) {
    const Mesh::Face &points = mesh.face(FaceIndex(f));
    const PointValues &p0 = point_values_[points[0].value()];
    const PointValues &p1 = point_values_[points[1].value()];
    const PointValues &p2 = point_values_[points[2].value()];
    const int64_t du1 = int64_t{p1[3]} - p0[3];
    int64_t dv1 = int64_t{p1[4]} - p0[4];
    const int64_t du2 = int64_t{p2[3]} - p0[3];
    int64_t dv2 = int64_t{p2[4]} - p0[4];
    const int64_t twice_uv_area = du1 * dv2 - du2 * dv1;
    if (twice_uv_area == 0) {
      continue;
    }
    const int orientation = twice_uv_area > 0 ? 1 : -1;
    if (orientation < 0) {
      dv1 = -dv1;
      dv2 = -dv2;
    }
    TangentVec3 e1, e2, gradient;
    for (int i = 0; i < 3; ++i) {
      e1[i] = int64_t{p1[i]} - p0[i];
      e2[i] = int64_t{p2[i]} - p0[i];
      gradient[i] = dv2 * e1[i] - dv1 * e2[i];
    }
    const TangentVec3 normal = Cross(e1, e2);
    const uint64_t gradient_squared = SquaredLength(gradient);
    const uint64_t normal_squared = SquaredLength(normal);
    if (gradient_squared == 0 || normal_squared == 0) {
      continue;
    }
    const TangentVec3 direction = ToUnitLength(gradient, gradient_squared);
    const std::array<int32_t, 3> weight =
        angle_weights ? CornerAngles(e1, e2, IntSqrtFloor(normal_squared))
                      : std::array<int32_t, 3>{1, 1, 1};
    TangentVec3 unit_normal = {0, 0, 0};
    if (face_normals) {
      unit_normal = ToUnitLength(normal, normal_squared);
    }
    for (int k = 0; k < 3; ++k) {
      const uint32_t entry = corner_entry[3 * f + k];
      if (count) {
        FaceSums &face_sums = face_sums_[entry];
        if (face_sums.num_faces >= kMaxCornersPerEntry) {
          continue;
        }
        ++face_sums.num_faces;
        face_sums.last_face = f;
        if (face_normals) {
          for (int i = 0; i < 3; ++i) {
            face_sums.normal[i] += unit_normal[i];
          }
        }
      }
      Sums &sums = all_sums[entry];
      const int64_t w = weight[k];
      for (int i = 0; i < 3; ++i) {
        sums.direction[i] += w * direction[i];
      }
      sums.orientation += w * orientation;
    }
  }
}

inline TangentVec3 GeometricTangentPredictor::VertexNormal(
    const TangentConnectivity &connectivity, int entry) const {
  const PointIndex point =
      connectivity.mesh->CornerToPointId(connectivity.data_to_corner[entry]);
  int32_t octahedral[2];
  normal_values_.Get(point, octahedral);
  const TangentVec3 normal =
      OctahedralToVector(octahedral[0], octahedral[1], normal_bits_);
  return normal_bits_ <= kPlaneNormalBits
             ? normal
             : ShiftRight(normal, normal_bits_ - kPlaneNormalBits);
}

// MikkTSpace's EvalTspace(): the weighted sum of the triangles' gradients
// around the vertex, projected onto the normal plane.
DRACO_UV_TANGENT_INLINE GeometricTangentPrediction
GeometricTangentPredictor::Predict(const TangentConnectivity &connectivity,
                                   int entry) const {
  GeometricTangentPrediction prediction;
  const Sums &sums = sums_[entry];
  prediction.handedness = sums.orientation >= 0 ? 1 : -1;
  // 30 bits: the projection's products fit, and its rounding (a 2^-8 of
  // the normal) stays far below the grid's steps.
  const TangentVec3 direction = ScaleToBits(sums.direction, 30);
  TangentVec3 plane_normal;
  if (kind_ == GeometricTangentKind::kFace) {
    const FaceSums &face_sums = face_sums_[entry];
    if (face_sums.num_faces == 1) {
      prediction.single_face = face_sums.last_face;
    }
    prediction.tangent = direction;
    plane_normal = ShiftRight(
        face_sums.normal,
        ShiftBelow(MaxAbsBits(face_sums.normal), kPlaneNormalBits));
  } else {
    plane_normal = VertexNormal(connectivity, entry);
    prediction.tangent = ProjectOntoPlane(direction, plane_normal);
  }
  const uint64_t squared = SquaredLength(prediction.tangent);
  if (squared == 0) {
    return prediction;
  }
  prediction.length = static_cast<int64_t>(IntSqrtFloor(squared));
  // The bitangent only serves its direction (the axis order and a ratio).
  prediction.bitangent = Cross(plane_normal, prediction.tangent);
  prediction.valid = true;
  return prediction;
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_PREDICTOR_H_
