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
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "draco/io/gltf_encoder.h"
#include "draco/io/scene_io.h"
#include "draco/scene/scene_utils.h"
#include "draco/tools/draco_transcoder_lib.h"
#include "draco_ext/eval/uv_eval.h"
#include "draco_ext/gltf/uv_gltf_extension.h"
#include "draco_ext/options/tangent_compression_options.h"

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

// |json|'s member |key|, or null when |json| is no object or lacks it.
const nlohmann::json &Member(const nlohmann::json &json, const char *key) {
  static const nlohmann::json kNull;
  if (!json.is_object()) {
    return kNull;
  }
  const auto it = json.find(key);
  return it == json.end() ? kNull : *it;
}

// |json|'s integer member |key|, or |fallback|.
int64_t IntMember(const nlohmann::json &json, const char *key,
                  int64_t fallback) {
  const nlohmann::json &value = Member(json, key);
  return value.is_number_integer() ? value.get<int64_t>() : fallback;
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
    for (int t = 0; t < GeometryAttribute::NAMED_ATTRIBUTES_COUNT; ++t) {
      const auto type = static_cast<GeometryAttribute::Type>(t);
      const std::string name =
          label + " " + GeometryAttribute::TypeToString(type);
      if (type == GeometryAttribute::TEX_COORD && !compare_tex_coords) {
        if (a.NumNamedAttributes(type) != b.NumNamedAttributes(type)) {
          return ErrorStatus(name + ": different number of attribute sets");
        }
        continue;
      }
      DRACO_RETURN_IF_ERROR(CompareNamedAttributes(a, b, type, name));
    }
  }
  return OkStatus();
}

double TangentBitsPerValue(int64_t bytes, int64_t values) {
  return values > 0 ? 8.0 * bytes / values : 0.0;
}

double UvGltfRatio(int64_t bytes, int64_t stock_bytes) {
  return stock_bytes > 0 ? static_cast<double>(bytes) / stock_bytes : 0.0;
}

StatusOr<std::vector<GltfDracoPrimitive>> ReadGltfDracoPrimitives(
    const std::string &file) {
  DRACO_ASSIGN_OR_RETURN(const nlohmann::json json, ReadGltfJson(file));
  const nlohmann::json &views = Member(json, "bufferViews");
  const nlohmann::json &accessors = Member(json, "accessors");
  std::vector<GltfDracoPrimitive> primitives;
  std::set<int> seen_views;
  const nlohmann::json &meshes = Member(json, "meshes");
  for (size_t m = 0; m < meshes.size(); ++m) {
    const nlohmann::json &mesh_primitives = Member(meshes[m], "primitives");
    for (size_t p = 0; p < mesh_primitives.size(); ++p) {
      const nlohmann::json &draco =
          Member(Member(mesh_primitives[p], "extensions"),
                 "KHR_draco_mesh_compression");
      const int view = IntMember(draco, "bufferView", -1);
      if (view < 0 || !seen_views.insert(view).second) {
        continue;  // Not Draco-compressed, or a Draco buffer seen before.
      }
      if (static_cast<size_t>(view) >= views.size()) {
        return ErrorStatus("Invalid Draco buffer view in " + file);
      }
      GltfDracoPrimitive primitive;
      primitive.primitive = std::to_string(m) + "." + std::to_string(p);
      primitive.draco_bytes = IntMember(views[view], "byteLength", 0);
      const int tangent =
          IntMember(Member(mesh_primitives[p], "attributes"), "TANGENT", -1);
      if (tangent >= 0 && static_cast<size_t>(tangent) < accessors.size()) {
        primitive.tangent_values = IntMember(accessors[tangent], "count", 0);
      }
      primitives.push_back(primitive);
    }
  }
  return primitives;
}

Status TranscodeGltfFileWithoutTangents(
    const std::string &input, const std::string &output,
    const DracoCompressionOptions &options) {
  DRACO_RETURN_IF_ERROR(options.Check());  // As DracoTranscoder::Create().
  DRACO_ASSIGN_OR_RETURN(std::unique_ptr<Scene> scene,
                         ReadSceneFromFile(input));
  for (MeshIndex i(0); i < scene->NumMeshes(); ++i) {
    Mesh &mesh = scene->GetMesh(i);
    if (mesh.NumNamedAttributes(GeometryAttribute::TANGENT) == 0) {
      continue;
    }
    while (mesh.NumNamedAttributes(GeometryAttribute::TANGENT) > 0) {
      mesh.DeleteAttribute(
          mesh.GetNamedAttributeId(GeometryAttribute::TANGENT));
    }
#ifdef DRACO_ATTRIBUTE_INDICES_DEDUPLICATION_SUPPORTED
    mesh.DeduplicatePointIds();
#endif
  }
  // What DracoTranscoder::Transcode() does after reading.
  SceneUtils::SetDracoCompressionOptions(&options, scene.get());
  GltfEncoder encoder;
  return encoder.EncodeFile<Scene>(*scene, output);
}

namespace {

// A transcoded file and, for an asset with tangents, the same without them.
struct TranscodedVariant {
  int64_t bytes = 0;
  std::vector<GltfDracoPrimitive> primitives;
  std::map<std::string, int64_t> draco_bytes_without_tangents;
};

bool HasTangents(const std::vector<GltfDracoPrimitive> &primitives) {
  for (const GltfDracoPrimitive &primitive : primitives) {
    if (primitive.tangent_values > 0) {
      return true;
    }
  }
  return false;
}

// Sizes of |file|, transcoded from |input| with |options|; with tangents
// also transcodes |input| without them into |file_without_tangents|.
StatusOr<TranscodedVariant> MeasureTranscoded(
    const std::string &input, const std::string &file,
    const std::string &file_without_tangents,
    const DracoCompressionOptions &options) {
  TranscodedVariant variant;
  DRACO_ASSIGN_OR_RETURN(variant.bytes, TranscodedGltfBytes(file));
  DRACO_ASSIGN_OR_RETURN(variant.primitives, ReadGltfDracoPrimitives(file));
  if (!HasTangents(variant.primitives)) {
    return variant;
  }
  DRACO_RETURN_IF_ERROR(
      TranscodeGltfFileWithoutTangents(input, file_without_tangents, options));
  DRACO_ASSIGN_OR_RETURN(const std::vector<GltfDracoPrimitive> without,
                         ReadGltfDracoPrimitives(file_without_tangents));
  for (const GltfDracoPrimitive &primitive : without) {
    variant.draco_bytes_without_tangents[primitive.primitive] =
        primitive.draco_bytes;
  }
  return variant;
}

int64_t DracoBytes(const TranscodedVariant &variant) {
  int64_t bytes = 0;
  for (const GltfDracoPrimitive &primitive : variant.primitives) {
    bytes += primitive.draco_bytes;
  }
  return bytes;
}

// What each primitive's TANGENT costs in |variant| and in |stock|.
StatusOr<std::vector<UvGltfTangentCost>> TangentCosts(
    const TranscodedVariant &stock, const TranscodedVariant &variant) {
  std::vector<UvGltfTangentCost> costs;
  for (size_t i = 0; i < variant.primitives.size(); ++i) {
    const GltfDracoPrimitive &primitive = variant.primitives[i];
    if (primitive.tangent_values == 0) {
      continue;
    }
    const auto without =
        variant.draco_bytes_without_tangents.find(primitive.primitive);
    const auto stock_without =
        stock.draco_bytes_without_tangents.find(primitive.primitive);
    if (i >= stock.primitives.size() ||
        stock.primitives[i].primitive != primitive.primitive ||
        without == variant.draco_bytes_without_tangents.end() ||
        stock_without == stock.draco_bytes_without_tangents.end()) {
      return ErrorStatus("Primitive " + primitive.primitive +
                         " has no counterpart without tangents or in stock "
                         "coding.");
    }
    UvGltfTangentCost cost;
    cost.primitive = primitive.primitive;
    cost.values = primitive.tangent_values;
    cost.stock_bytes = stock.primitives[i].draco_bytes - stock_without->second;
    cost.bytes = primitive.draco_bytes - without->second;
    costs.push_back(cost);
  }
  return costs;
}

void AddTangentCosts(std::vector<UvGltfTangentCost> costs, UvGltfEvalRow *row) {
  for (const UvGltfTangentCost &cost : costs) {
    row->tangent_values += cost.values;
    row->stock_tangent_bytes += cost.stock_bytes;
    row->tangent_bytes += cost.bytes;
  }
  row->tangent_costs = std::move(costs);
}

// One folder per variant and the same file name in each, so that the
// buffer and image names in the JSON have the same length.
class VariantFiles {
 public:
  VariantFiles(const std::string &work_dir, const std::string &name, bool glb)
      : work_dir_(work_dir),
        file_name_(SafeFileName(name) + (glb ? ".glb" : ".gltf")) {}

  std::string Path(const std::string &variant) const {
    const fs::path dir = fs::path(work_dir_) / SafeFileName(variant);
    fs::create_directories(dir);
    return (dir / file_name_).string();
  }

 private:
  std::string work_dir_;
  std::string file_name_;
};

// The stock transcode every variant is compared with.
struct StockReference {
  std::unique_ptr<Scene> scene;
  TranscodedVariant sizes;
};

StatusOr<StockReference> MeasureStock(const std::string &input,
                                      const UvGltfEvalOptions &options,
                                      const VariantFiles &files) {
  DracoCompressionOptions stock_options = options.compression;
  stock_options.uv = UvCompressionOptions();
  const std::string file = files.Path("reference");
  DRACO_RETURN_IF_ERROR(TranscodeGltfFile(input, file, stock_options));
  StockReference stock;
  auto scene = ReadSceneFromFile(file);
  if (!scene.ok()) {
    return ErrorStatus("Draco cannot read its own stock output: " +
                       scene.status().error_msg_string());
  }
  stock.scene = std::move(scene).value();
  DRACO_ASSIGN_OR_RETURN(
      stock.sizes,
      MeasureTranscoded(input, file, files.Path("reference_no_tangents"),
                        stock_options));
  return stock;
}

// Transcodes, reads back and measures one (scheme, tangents) variant into
// |row|; a failure of the variant is the row's detail.
Status MeasureVariant(const std::string &input, const StockReference &stock,
                      const DracoCompressionOptions &options,
                      const VariantFiles &files, UvGltfEvalRow *row) {
  const std::string variant = row->scheme + "_" + row->tangents;
  const std::string file = files.Path(variant);
  const auto scene = TranscodeAndRead(input, file, options);
  Status status = scene.status();
  if (status.ok()) {
    // The lossy Laplacians change the UVs by design.
    status = CompareSceneGeometry(*stock.scene, *scene.value(),
                                  !IsUvLaplacian(options.uv.prediction));
  }
  row->round_trip_ok = status.ok();
  row->detail = status.ok() ? "" : status.error_msg_string();
  if (!status.ok()) {
    return OkStatus();
  }
  DRACO_ASSIGN_OR_RETURN(
      const TranscodedVariant sizes,
      MeasureTranscoded(input, file, files.Path(variant + "_no_tangents"),
                        options));
  row->bytes = sizes.bytes;
  row->draco_bytes = DracoBytes(sizes);
  DRACO_ASSIGN_OR_RETURN(row->requires_extension,
                         RequiresUvGltfExtension(file));
  DRACO_ASSIGN_OR_RETURN(std::vector<UvGltfTangentCost> costs,
                         TangentCosts(stock.sizes, sizes));
  AddTangentCosts(std::move(costs), row);
  return OkStatus();
}

}  // namespace

StatusOr<std::vector<UvGltfEvalRow>> EvaluateGltfAsset(
    const std::string &input, const std::string &name,
    const UvGltfEvalOptions &options, const std::string &work_dir) {
  const VariantFiles files(work_dir, name, options.glb);
  DRACO_ASSIGN_OR_RETURN(const StockReference stock,
                         MeasureStock(input, options, files));
  std::vector<UvGltfEvalRow> rows;
  for (const std::string &scheme : options.schemes) {
    for (const std::string &tangents : options.tangents) {
      UvGltfEvalRow row;
      row.asset = name;
      row.scheme = scheme;
      row.tangents = tangents;
      row.qtg = options.compression.quantization_bits_tangent;
      row.primitives = stock.scene->NumMeshes();
      row.textured_primitives = CountTexturedMeshes(*stock.scene);
      row.stock_bytes = stock.sizes.bytes;
      row.stock_draco_bytes = DracoBytes(stock.sizes);
      DracoCompressionOptions variant = options.compression;
      DRACO_ASSIGN_OR_RETURN(variant.uv, ParseUvSchemeName(scheme));
      DRACO_ASSIGN_OR_RETURN(variant.uv.tangent.prediction,
                             ParseTangentPredictionName(tangents));
      DRACO_RETURN_IF_ERROR(MeasureVariant(input, stock, variant, files, &row));
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace draco
