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
#include "draco_ext/eval/uv_decoded_digest.h"

#include <cinttypes>
#include <cstdio>

#include "draco/compression/decode.h"

namespace draco {

namespace {

std::string Hex64(uint64_t value) {
  char text[17];
  snprintf(text, sizeof(text), "%016" PRIx64, value);
  return text;
}

std::string DataTypeName(DataType type) {
  switch (type) {
    case DT_INT8: return "int8";
    case DT_UINT8: return "uint8";
    case DT_INT16: return "int16";
    case DT_UINT16: return "uint16";
    case DT_INT32: return "int32";
    case DT_UINT32: return "uint32";
    case DT_INT64: return "int64";
    case DT_UINT64: return "uint64";
    case DT_FLOAT32: return "float32";
    case DT_FLOAT64: return "float64";
    case DT_BOOL: return "bool";
    default: return "type" + std::to_string(static_cast<int>(type));
  }
}

uint64_t CornerValuesHash(const Mesh &mesh, const PointAttribute &att) {
  uint64_t hash = Fnv1a64(nullptr, 0);
  const size_t stride = att.byte_stride();
  for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (const PointIndex point : mesh.face(f)) {
      hash = Fnv1a64(att.GetAddress(att.mapped_index(point)), stride, hash);
    }
  }
  return hash;
}

}  // namespace

uint64_t Fnv1a64(const void *data, size_t size, uint64_t hash) {
  const uint8_t *bytes = static_cast<const uint8_t *>(data);
  for (size_t i = 0; i < size; ++i) {
    hash = (hash ^ bytes[i]) * 0x100000001b3ull;
  }
  return hash;
}

Status CheckMeshIndices(const Mesh &mesh) {
  for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (const PointIndex point : mesh.face(f)) {
      if (point.value() >= mesh.num_points()) {
        return Status(Status::DRACO_ERROR,
                      "Face " + std::to_string(f.value()) + " uses point " +
                          std::to_string(point.value()) + " of " +
                          std::to_string(mesh.num_points()) + ".");
      }
    }
  }
  for (int i = 0; i < mesh.num_attributes(); ++i) {
    const PointAttribute &att = *mesh.attribute(i);
    const bool mapped = !att.is_mapping_identity();
    if ((mapped && att.indices_map_size() < mesh.num_points()) ||
        att.buffer()->data_size() < att.size() * att.byte_stride()) {
      return Status(Status::DRACO_ERROR,
                    "Attribute " + std::to_string(i) + " is incomplete.");
    }
    for (PointIndex point(0); point < mesh.num_points(); ++point) {
      if (att.mapped_index(point).value() >= att.size()) {
        return Status(Status::DRACO_ERROR,
                      "Point " + std::to_string(point.value()) +
                          " has no value of attribute " + std::to_string(i) +
                          ".");
      }
    }
  }
  return OkStatus();
}

std::string MeshDigest(const Mesh &mesh) {
  std::string digest = "faces=" + std::to_string(mesh.num_faces()) +
                       " points=" + std::to_string(mesh.num_points());
  for (int i = 0; i < mesh.num_attributes(); ++i) {
    const PointAttribute &att = *mesh.attribute(i);
    digest += " " + GeometryAttribute::TypeToString(att.attribute_type()) +
              ":" + DataTypeName(att.data_type()) + "x" +
              std::to_string(att.num_components()) + "=" +
              Hex64(CornerValuesHash(mesh, att));
  }
  return digest;
}

StatusOr<std::string> DecodedMeshDigest(const char *data, size_t size,
                                        bool quantized) {
  DecoderBuffer buffer;
  buffer.Init(data, size);
  Decoder decoder;
  if (quantized) {
    for (const GeometryAttribute::Type type :
         {GeometryAttribute::POSITION, GeometryAttribute::NORMAL,
          GeometryAttribute::COLOR, GeometryAttribute::TEX_COORD,
          GeometryAttribute::GENERIC}) {
      decoder.SetSkipAttributeTransform(type);
    }
  }
  DRACO_ASSIGN_OR_RETURN(std::unique_ptr<Mesh> mesh,
                         decoder.DecodeMeshFromBuffer(&buffer));
  DRACO_RETURN_IF_ERROR(CheckMeshIndices(*mesh));
  return MeshDigest(*mesh);
}

}  // namespace draco
