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
#include "draco_ext/eval/uv_gltf_eval.h"

#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>

#include "draco/io/scene_io.h"
#include "draco/tools/draco_transcoder_lib.h"
#include "draco_ext/eval/uv_eval.h"
#include "draco_ext/gltf/uv_gltf_extension.h"

namespace draco {

namespace {

namespace fs = std::filesystem;

constexpr uint32_t kGlbMagic = 0x46546c67;  // "glTF"
constexpr size_t kGlbHeaderBytes = 12;
constexpr size_t kGlbChunkHeaderBytes = 8;

StatusOr<std::string> ReadFileBytes(const std::string &file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) {
    return ErrorStatus("Cannot open " + file);
  }
  return std::string(std::istreambuf_iterator<char>(stream),
                     std::istreambuf_iterator<char>());
}

uint32_t ReadUint32(const std::string &bytes, size_t offset) {
  uint32_t value;
  std::memcpy(&value, bytes.data() + offset, sizeof(value));
  return value;
}

// The JSON of a .gltf, or the first chunk of a .glb.
StatusOr<nlohmann::json> ReadGltfJson(const std::string &file) {
  DRACO_ASSIGN_OR_RETURN(const std::string bytes, ReadFileBytes(file));
  std::string json_text = bytes;
  if (bytes.size() >= kGlbHeaderBytes && ReadUint32(bytes, 0) == kGlbMagic) {
    const size_t start = kGlbHeaderBytes + kGlbChunkHeaderBytes;
    if (bytes.size() < start ||
        ReadUint32(bytes, kGlbHeaderBytes) > bytes.size() - start) {
      return ErrorStatus("Truncated GLB " + file);
    }
    json_text = bytes.substr(start, ReadUint32(bytes, kGlbHeaderBytes));
  }
  nlohmann::json json = nlohmann::json::parse(json_text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) {
    return ErrorStatus("Invalid glTF JSON in " + file);
  }
  return json;
}

bool IsDataUri(const std::string &uri) { return uri.rfind("data:", 0) == 0; }

// Values of attribute |att| at every face corner, as float32 bit patterns.
std::vector<uint32_t> CornerBits(const Mesh &mesh, const PointAttribute &att) {
  std::vector<uint32_t> bits;
  std::vector<float> value(att.num_components());
  for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (int c = 0; c < 3; ++c) {
      att.ConvertValue<float>(att.mapped_index(mesh.face(f)[c]), &value[0]);
      for (const float component : value) {
        uint32_t word;
        std::memcpy(&word, &component, sizeof(word));
        bits.push_back(word);
      }
    }
  }
  return bits;
}

Status CompareNamedAttributes(const Mesh &expected, const Mesh &actual,
                              GeometryAttribute::Type type,
                              const std::string &label) {
  const int count = expected.NumNamedAttributes(type);
  if (actual.NumNamedAttributes(type) != count) {
    return ErrorStatus(label + ": different number of attribute sets");
  }
  for (int i = 0; i < count; ++i) {
    if (CornerBits(expected, *expected.GetNamedAttribute(type, i)) !=
        CornerBits(actual, *actual.GetNamedAttribute(type, i))) {
      return ErrorStatus(label + " set " + std::to_string(i) +
                         ": values differ");
    }
  }
  return OkStatus();
}

int CountTexturedMeshes(const Scene &scene) {
  int count = 0;
  for (MeshIndex i(0); i < scene.NumMeshes(); ++i) {
    count +=
        scene.GetMesh(i).NumNamedAttributes(GeometryAttribute::TEX_COORD) > 0;
  }
  return count;
}

std::string SafeFileName(const std::string &name) {
  std::string safe = name;
  for (char &c : safe) {
    if (!std::isalnum(static_cast<unsigned char>(c))) {
      c = '_';
    }
  }
  return safe;
}

// Transcodes with |options| into |output| and reads the result back.
StatusOr<std::unique_ptr<Scene>> TranscodeAndRead(
    const std::string &input, const std::string &output,
    const DracoCompressionOptions &options) {
  DRACO_RETURN_IF_ERROR(TranscodeGltfFile(input, output, options));
  return ReadSceneFromFile(output);
}

}  // namespace

Status TranscodeGltfFile(const std::string &input, const std::string &output,
                         const DracoCompressionOptions &options) {
  DracoTranscodingOptions transcoding_options;
  transcoding_options.geometry = options;
  DRACO_ASSIGN_OR_RETURN(std::unique_ptr<DracoTranscoder> transcoder,
                         DracoTranscoder::Create(transcoding_options));
  DracoTranscoder::FileOptions file_options;
  file_options.input_filename = input;
  file_options.output_filename = output;
  return transcoder->Transcode(file_options);
}

StatusOr<int64_t> TranscodedGltfBytes(const std::string &file) {
  std::error_code error;
  int64_t bytes = fs::file_size(file, error);
  if (error) {
    return ErrorStatus("Cannot stat " + file);
  }
  DRACO_ASSIGN_OR_RETURN(const nlohmann::json json, ReadGltfJson(file));
  for (const nlohmann::json &buffer : json.value("buffers", nlohmann::json())) {
    const std::string uri = buffer.value("uri", "");
    if (uri.empty() || IsDataUri(uri)) {
      continue;  // GLB's own chunk, or inside the JSON.
    }
    const fs::path path = fs::path(file).parent_path() / uri;
    bytes += fs::file_size(path, error);
    if (error) {
      return ErrorStatus("Cannot stat " + path.string());
    }
  }
  return bytes;
}

StatusOr<bool> RequiresUvGltfExtension(const std::string &file) {
  DRACO_ASSIGN_OR_RETURN(const nlohmann::json json, ReadGltfJson(file));
  for (const nlohmann::json &name :
       json.value("extensionsRequired", nlohmann::json())) {
    if (name.is_string() && IsUvGltfExtension(name.get<std::string>())) {
      return true;
    }
  }
  return false;
}

Status CompareSceneGeometry(const Scene &expected, const Scene &actual,
                            bool compare_tex_coords) {
  if (expected.NumMeshes() != actual.NumMeshes()) {
    return ErrorStatus("Different number of meshes");
  }
  for (MeshIndex i(0); i < expected.NumMeshes(); ++i) {
    const Mesh &a = expected.GetMesh(i);
    const Mesh &b = actual.GetMesh(i);
    const std::string label = "mesh " + std::to_string(i.value());
    if (a.num_faces() != b.num_faces()) {
      return ErrorStatus(label + ": different number of faces");
    }
    DRACO_RETURN_IF_ERROR(CompareNamedAttributes(
        a, b, GeometryAttribute::POSITION, label + " POSITION"));
    if (!compare_tex_coords) {
      if (a.NumNamedAttributes(GeometryAttribute::TEX_COORD) !=
          b.NumNamedAttributes(GeometryAttribute::TEX_COORD)) {
        return ErrorStatus(label + ": different number of TEX_COORD sets");
      }
      continue;
    }
    DRACO_RETURN_IF_ERROR(CompareNamedAttributes(
        a, b, GeometryAttribute::TEX_COORD, label + " TEX_COORD"));
  }
  return OkStatus();
}

StatusOr<std::vector<UvGltfEvalRow>> EvaluateGltfAsset(
    const std::string &input, const std::string &name,
    const UvGltfEvalOptions &options, const std::string &work_dir) {
  // One folder per variant and the same file name in each, so that the
  // buffer and image names in the JSON have the same length.
  const std::string file_name =
      SafeFileName(name) + (options.glb ? ".glb" : ".gltf");
  const auto output_path = [&](const std::string &variant) {
    const fs::path dir = fs::path(work_dir) / SafeFileName(variant);
    fs::create_directories(dir);
    return (dir / file_name).string();
  };

  DracoCompressionOptions stock_options = options.compression;
  stock_options.uv = UvCompressionOptions();
  const std::string stock_file = output_path("reference");
  DRACO_RETURN_IF_ERROR(TranscodeGltfFile(input, stock_file, stock_options));
  const auto stock_scene = ReadSceneFromFile(stock_file);
  if (!stock_scene.ok()) {
    return ErrorStatus("Draco cannot read its own stock output: " +
                       stock_scene.status().error_msg_string());
  }
  DRACO_ASSIGN_OR_RETURN(const int64_t stock_bytes,
                         TranscodedGltfBytes(stock_file));

  std::vector<UvGltfEvalRow> rows;
  for (const std::string &scheme : options.schemes) {
    UvGltfEvalRow row;
    row.asset = name;
    row.scheme = scheme;
    row.primitives = stock_scene.value()->NumMeshes();
    row.textured_primitives = CountTexturedMeshes(*stock_scene.value());
    row.stock_bytes = stock_bytes;

    DracoCompressionOptions scheme_options = options.compression;
    DRACO_ASSIGN_OR_RETURN(scheme_options.uv, ParseUvSchemeName(scheme));
    const std::string file = output_path(scheme);
    const auto scene = TranscodeAndRead(input, file, scheme_options);
    Status status = scene.status();
    if (status.ok()) {
      // The lossy Laplacians change the UVs by design.
      status = CompareSceneGeometry(*stock_scene.value(), *scene.value(),
                                    !IsUvLaplacian(scheme_options.uv.prediction));
    }
    if (status.ok()) {
      DRACO_ASSIGN_OR_RETURN(row.bytes, TranscodedGltfBytes(file));
      DRACO_ASSIGN_OR_RETURN(row.requires_extension,
                             RequiresUvGltfExtension(file));
    }
    row.round_trip_ok = status.ok();
    row.detail = status.ok() ? "" : status.error_msg_string();
    rows.push_back(row);
  }
  return rows;
}

}  // namespace draco
