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
// Meshes made from indexed triangle soups the way Draco's OBJ reader makes
// them (per-corner positions and texture coordinates, values and points
// deduplicated), and the round-trip oracle that the degenerate-mesh tests
// and the round-trip fuzzer share: a -uv_pred encoding must decode to
// exactly what stock Draco's encoding at the same settings decodes to.
// Header-only, so that the fuzz build needs no test library.
#ifndef DRACO_UV_TESTS_UV_SOUP_MESH_H_
#define DRACO_UV_TESTS_UV_SOUP_MESH_H_

#include <array>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "draco/compression/decode.h"
#include "draco/mesh/triangle_soup_mesh_builder.h"
#include "draco_ext/options/uv_encode_settings.h"

namespace draco {

struct SoupMesh {
  struct Face {
    std::array<int, 3> position;  // Indices into positions.
    std::array<int, 3> uv;        // Indices into uvs.
  };
  std::vector<std::array<float, 3>> positions;  // Empty: no POSITION.
  std::vector<std::array<float, 2>> uvs;        // Empty: no TEX_COORD.
  std::vector<Face> faces;
};

// The Draco mesh of |soup|; indices are taken modulo the value counts.
inline std::unique_ptr<Mesh> BuildSoupMesh(const SoupMesh &soup) {
  TriangleSoupMeshBuilder builder;
  builder.Start(static_cast<int>(soup.faces.size()));
  const int pos_id =
      soup.positions.empty()
          ? -1
          : builder.AddAttribute(GeometryAttribute::POSITION, 3, DT_FLOAT32);
  const int uv_id =
      soup.uvs.empty()
          ? -1
          : builder.AddAttribute(GeometryAttribute::TEX_COORD, 2, DT_FLOAT32);
  for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
    const SoupMesh::Face &face = soup.faces[f];
    if (pos_id >= 0) {
      const auto p = [&](int i) {
        return soup.positions[face.position[i] % soup.positions.size()].data();
      };
      builder.SetAttributeValuesForFace(pos_id, FaceIndex(f), p(0), p(1), p(2));
    }
    if (uv_id >= 0) {
      const auto t = [&](int i) {
        return soup.uvs[face.uv[i] % soup.uvs.size()].data();
      };
      builder.SetAttributeValuesForFace(uv_id, FaceIndex(f), t(0), t(1), t(2));
    }
  }
  return builder.Finalize();
}

// True when an attribute of |type| holds a NaN or an infinity.
inline bool HasNonFiniteValue(const Mesh &mesh, GeometryAttribute::Type type) {
  for (int i = 0; i < mesh.NumNamedAttributes(type); ++i) {
    const PointAttribute &att = *mesh.GetNamedAttribute(type, i);
    std::vector<float> value(att.num_components());
    for (AttributeValueIndex v(0); v < static_cast<uint32_t>(att.size()); ++v) {
      att.ConvertValue(v, att.num_components(), value.data());
      for (const float x : value) {
        if (!std::isfinite(x)) {
          return true;
        }
      }
    }
  }
  return false;
}

// Bits of every attribute value at every face corner, in face order.
inline std::vector<uint8_t> CornerBytes(const Mesh &mesh) {
  std::vector<uint8_t> bytes;
  for (int i = 0; i < mesh.num_attributes(); ++i) {
    const PointAttribute &att = *mesh.attribute(i);
    for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
      for (const PointIndex point : mesh.face(f)) {
        const uint8_t *value = att.GetAddress(att.mapped_index(point));
        bytes.insert(bytes.end(), value, value + att.byte_stride());
      }
    }
  }
  return bytes;
}

inline StatusOr<std::unique_ptr<Mesh>> DecodeEncoded(
    const EncoderBuffer &encoded) {
  DecoderBuffer buffer;
  buffer.Init(encoded.data(), encoded.size());
  Decoder decoder;
  return decoder.DecodeMeshFromBuffer(&buffer);
}

// What encoding |mesh| with |settings| did, compared with stock Draco.
struct UvRoundTrip {
  Status encoded = OkStatus();  // Encoding with |settings|.
  Status decoded = OkStatus();  // Decoding that, if it was encoded.
  bool stock_encoded = false;   // Stock Draco encoded and decoded it too.
  bool identical = false;       // Both decode to the same bits everywhere.
};

// Encodes |mesh| with |settings| and, unless |with_stock| is false, with
// stock Draco (settings.uv left at its defaults), decodes both and compares
// the decoded meshes corner by corner.
inline UvRoundTrip RoundTripAgainstStock(const Mesh &mesh,
                                         const UvEncodeSettings &settings,
                                         bool with_stock = true) {
  UvRoundTrip result;
  EncoderBuffer ours;
  result.encoded = EncodeMeshWithSettings(mesh, settings, &ours);
  if (!result.encoded.ok()) {
    return result;
  }
  auto our_mesh = DecodeEncoded(ours);
  result.decoded = our_mesh.status();
  if (!result.decoded.ok() || !with_stock) {
    return result;
  }
  UvEncodeSettings stock_settings = settings;
  stock_settings.uv = UvCompressionOptions();
  EncoderBuffer stock;
  if (!EncodeMeshWithSettings(mesh, stock_settings, &stock).ok()) {
    return result;
  }
  const auto stock_mesh = DecodeEncoded(stock);
  if (!stock_mesh.ok()) {
    return result;
  }
  result.stock_encoded = true;
  result.identical =
      our_mesh.value()->num_faces() == stock_mesh.value()->num_faces() &&
      our_mesh.value()->num_attributes() ==
          stock_mesh.value()->num_attributes() &&
      CornerBytes(*our_mesh.value()) == CornerBytes(*stock_mesh.value());
  return result;
}

}  // namespace draco

#endif  // DRACO_UV_TESTS_UV_SOUP_MESH_H_
