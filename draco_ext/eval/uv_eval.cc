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
#include "draco_ext/eval/uv_eval.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include "draco/compression/bit_coders/rans_bit_encoder.h"
#include "draco/compression/decode.h"
#include "draco/mesh/mesh_attribute_corner_table.h"
#include "draco/mesh/mesh_misc_functions.h"
#include "draco_ext/common/uv_vertices.h"
#include "draco_ext/eval/uv_seam_stats.h"
#include "draco_ext/options/tangent_prediction_options.h"
#include "draco_ext/options/uv_encode_settings.h"
#include "draco_ext/options/uv_error_target.h"

namespace draco {

namespace {

std::vector<const PointAttribute *> TexCoordAttributes(const Mesh &mesh) {
  std::vector<const PointAttribute *> atts;
  for (int i = 0; i < mesh.NumNamedAttributes(GeometryAttribute::TEX_COORD);
       ++i) {
    atts.push_back(mesh.GetNamedAttribute(GeometryAttribute::TEX_COORD, i));
  }
  return atts;
}

std::array<float, 2> UvAt(const PointAttribute &att, PointIndex point) {
  std::array<float, 2> uv = {0.f, 0.f};
  att.ConvertValue(att.mapped_index(point), 2, uv.data());
  return uv;
}

// The mesh without its texture coordinates, as draco_encoder's
// --skip TEX_COORD makes it.
std::unique_ptr<Mesh> WithoutTexCoords(const Mesh &mesh) {
  std::unique_ptr<Mesh> copy(new Mesh());
  copy->Copy(mesh);
  while (copy->NumNamedAttributes(GeometryAttribute::TEX_COORD) > 0) {
    copy->DeleteAttribute(
        copy->GetNamedAttributeId(GeometryAttribute::TEX_COORD, 0));
  }
#ifdef DRACO_ATTRIBUTE_INDICES_DEDUPLICATION_SUPPORTED
  copy->DeduplicatePointIds();
#endif
  return copy;
}

double MillisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(
             std::chrono::steady_clock::now() - start)
      .count();
}

struct TimedEncoding {
  EncoderBuffer buffer;
  std::string summary;
  double ms = std::numeric_limits<double>::max();
};

Status EncodeTimed(const Mesh &mesh, const UvEncodeSettings &settings,
                   int repeat, TimedEncoding *out) {
  for (int i = 0; i < std::max(1, repeat); ++i) {
    const auto start = std::chrono::steady_clock::now();
    out->buffer.Clear();
    DRACO_RETURN_IF_ERROR(
        EncodeMeshWithSettings(mesh, settings, &out->buffer, &out->summary));
    out->ms = std::min(out->ms, MillisecondsSince(start));
  }
  return OkStatus();
}

StatusOr<std::unique_ptr<Mesh>> DecodeTimed(const EncoderBuffer &encoded,
                                            int repeat, double *ms) {
  std::unique_ptr<Mesh> mesh;
  *ms = std::numeric_limits<double>::max();
  for (int i = 0; i < std::max(1, repeat); ++i) {
    DecoderBuffer buffer;
    buffer.Init(encoded.data(), encoded.size());
    Decoder decoder;
    const auto start = std::chrono::steady_clock::now();
    DRACO_ASSIGN_OR_RETURN(mesh, decoder.DecodeMeshFromBuffer(&buffer));
    *ms = std::min(*ms, MillisecondsSince(start));
  }
  return mesh;
}

StatusOr<int64_t> EncodedSize(const Mesh &mesh,
                              const UvEncodeSettings &settings) {
  EncoderBuffer buffer;
  DRACO_RETURN_IF_ERROR(EncodeMeshWithSettings(mesh, settings, &buffer));
  return static_cast<int64_t>(buffer.size());
}

// Texture coordinates at every face corner, all UV sets, in face order.
std::vector<float> CornerUvs(const Mesh &mesh) {
  std::vector<float> values;
  for (const PointAttribute *att : TexCoordAttributes(mesh)) {
    for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
      for (const PointIndex point : mesh.face(f)) {
        const auto uv = UvAt(*att, point);
        values.insert(values.end(), uv.begin(), uv.end());
      }
    }
  }
  return values;
}

}  // namespace

std::vector<std::string> ListMeshFiles(const std::string &input) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(input)) {
    return {input};
  }
  std::vector<std::string> meshes;
  for (const auto &entry : fs::directory_iterator(input)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (entry.is_regular_file() &&
        (ext == ".obj" || ext == ".ply" || ext == ".gltf" || ext == ".glb")) {
      meshes.push_back(entry.path().string());
    }
  }
  std::sort(meshes.begin(), meshes.end());
  return meshes;
}

int64_t CountUvVertices(const Mesh &mesh) {
  int64_t count = 0;
  for (const PointAttribute *att : TexCoordAttributes(mesh)) {
    count += NumUvVertices(mesh, *att);
  }
  return count;
}

double StockSeamBytes(const Mesh &mesh) {
  const std::unique_ptr<CornerTable> table =
      CreateCornerTableFromPositionAttribute(&mesh);
  if (table == nullptr) {
    return 0;
  }
  double bytes = 0;
  for (const PointAttribute *att : TexCoordAttributes(mesh)) {
    MeshAttributeCornerTable att_table;
    if (!att_table.InitFromAttribute(&mesh, table.get(), att)) {
      continue;
    }
    RAnsBitEncoder encoder;
    encoder.StartEncoding();
    for (CornerIndex c(0); c < table->num_corners(); ++c) {
      const CornerIndex opposite = table->Opposite(c);
      if (opposite != kInvalidCornerIndex && c < opposite) {
        encoder.EncodeBit(att_table.IsCornerOppositeToSeamEdge(c));
      }
    }
    EncoderBuffer buffer;
    encoder.EndEncoding(&buffer);
    bytes += static_cast<double>(buffer.size());
  }
  return bytes;
}

namespace {

// Everything measured once per mesh and qt that every scheme is compared to.
struct UvEvalBaseline {
  // At the evaluated -cl, per -uv_seams name (the seams of other
  // non-position attributes, e.g. normals, depend on it).
  std::map<UvSeamCoding, int64_t> size_without_uvs;
  int64_t stock_best_uv_bytes = 0;   // Best of -cl 7 and -cl 10.
  std::vector<float> reference_uvs;  // Stock Draco's decoded UVs.
};

// The measured scheme names: every scheme with every seam coding.
std::vector<std::string> MeasuredSchemes(const UvEvalOptions &options) {
  std::vector<std::string> names;
  for (const std::string &scheme : options.schemes) {
    if (scheme.find('+') != std::string::npos) {
      names.push_back(scheme);  // Its seam coding is given.
      continue;
    }
    for (const std::string &seams : options.seams) {
      names.push_back(seams == "draco" ? scheme : scheme + "+" + seams);
    }
  }
  return names;
}

StatusOr<int64_t> StockUvBytes(const Mesh &mesh, const Mesh &without,
                               UvEncodeSettings settings) {
  DRACO_ASSIGN_OR_RETURN(const int64_t with_uvs, EncodedSize(mesh, settings));
  settings.qt = 0;
  DRACO_ASSIGN_OR_RETURN(const int64_t no_uvs, EncodedSize(without, settings));
  return with_uvs - no_uvs;
}

StatusOr<UvEvalBaseline> MeasureBaseline(const Mesh &mesh, const Mesh &without,
                                         const UvEvalOptions &options, int qt) {
  UvEvalBaseline baseline;
  UvEncodeSettings settings{options.qp, 0, options.cl};
  for (const std::string &scheme : MeasuredSchemes(options)) {
    DRACO_ASSIGN_OR_RETURN(const UvCompressionOptions uv,
                           ParseUvSchemeName(scheme));
    settings.uv.seams = uv.seams;
    if (baseline.size_without_uvs.count(uv.seams) == 0) {
      DRACO_ASSIGN_OR_RETURN(baseline.size_without_uvs[uv.seams],
                             EncodedSize(without, settings));
    }
  }
  settings.uv.seams = UvSeamCoding::kDraco;
  settings.qt = qt;
  baseline.stock_best_uv_bytes = std::numeric_limits<int64_t>::max();
  for (const int cl : {7, 10}) {
    settings.cl = cl;
    DRACO_ASSIGN_OR_RETURN(const int64_t bytes,
                           StockUvBytes(mesh, without, settings));
    baseline.stock_best_uv_bytes =
        std::min(baseline.stock_best_uv_bytes, bytes);
  }
  settings.cl = options.cl;
  TimedEncoding stock;
  DRACO_RETURN_IF_ERROR(EncodeTimed(mesh, settings, 1, &stock));
  double ms;
  DRACO_ASSIGN_OR_RETURN(const auto decoded, DecodeTimed(stock.buffer, 1, &ms));
  baseline.reference_uvs = CornerUvs(*decoded);
  return baseline;
}

// Seam bytes of |mesh| encoded with |settings| (see UvEvalRow::seam_bytes).
StatusOr<double> SeamBytes(const Mesh &mesh, const UvEncodeSettings &settings) {
  if (settings.uv.seams == UvSeamCoding::kDraco) {
    return StockSeamBytes(mesh);
  }
  DRACO_ASSIGN_OR_RETURN(const UvSeamProblem problem,
                         BuildUvSeamProblem(mesh, settings));
  return static_cast<double>(ContextSeamStreamBytes(problem));
}

// Encodes |mesh| with |settings| and fills |row|'s sizes, times and error.
Status MeasureSettings(const Mesh &mesh, const UvEvalOptions &options,
                       const UvEncodeSettings &settings,
                       const UvEvalBaseline &baseline, UvEvalRow *row) {
  row->uv_vertices = CountUvVertices(mesh);
  const int64_t size_without_uvs =
      baseline.size_without_uvs.at(settings.uv.seams);
  TimedEncoding encoding;
  DRACO_RETURN_IF_ERROR(EncodeTimed(mesh, settings, options.repeat, &encoding));
  row->enc_ms = encoding.ms;
  DRACO_ASSIGN_OR_RETURN(
      const auto decoded,
      DecodeTimed(encoding.buffer, options.repeat, &row->dec_ms));
  row->uv_bytes =
      static_cast<int64_t>(encoding.buffer.size()) - size_without_uvs;
  DRACO_ASSIGN_OR_RETURN(row->seam_bytes, SeamBytes(mesh, settings));
  row->bpv =
      row->uv_vertices > 0 ? 8.0 * row->uv_bytes / row->uv_vertices : 0.0;
  row->ratio_vs_draco =
      static_cast<double>(row->uv_bytes) / baseline.stock_best_uv_bytes;
  if (row->target_rmse > 0) {  // Lossless choices decode to stock's UVs.
    row->lossy = encoding.summary.find("-> laplacian") != std::string::npos;
  }
  row->round_trip_ok =
      row->lossy || CornerUvs(*decoded) == baseline.reference_uvs;
  DRACO_ASSIGN_OR_RETURN(row->rmse, UvRmse(mesh, *decoded, options.qp));
  if (row->target_rmse > 0) {  // Each UV set meets the target.
    for (int i = 0; i < mesh.NumNamedAttributes(GeometryAttribute::TEX_COORD);
         ++i) {
      DRACO_ASSIGN_OR_RETURN(const double rmse,
                             UvRmseOf(mesh, *decoded, options.qp, i));
      row->round_trip_ok = row->round_trip_ok && rmse <= row->target_rmse;
    }
  }
  row->detail = encoding.summary;
  return OkStatus();
}

StatusOr<UvEvalRow> MeasureScheme(const std::string &name, const Mesh &mesh,
                                  const UvEvalOptions &options, int qt,
                                  const std::string &scheme,
                                  const UvEvalBaseline &baseline) {
  UvEvalRow row;
  row.mesh = name;
  row.scheme = scheme;
  row.qt = qt;
  UvEncodeSettings settings{options.qp, qt, options.cl};
  DRACO_ASSIGN_OR_RETURN(settings.uv, ParseUvSchemeName(scheme));
  row.lossy = IsUvLaplacian(settings.uv.prediction);
  if (row.lossy) {
    settings.uv.anchors = options.uv_anchors;
  }
  DRACO_RETURN_IF_ERROR(
      MeasureSettings(mesh, options, settings, baseline, &row));
  return row;
}

// The coarsest -qt whose quantisation grid meets |max_rmse| in every UV
// set: where the lossless codings that meet it are smallest.
StatusOr<int> LosslessQtFor(const Mesh &mesh, double max_rmse) {
  int qt = 1;
  for (int i = 0; i < mesh.NumNamedAttributes(GeometryAttribute::TEX_COORD);
       ++i) {
    DRACO_ASSIGN_OR_RETURN(
        const int bits,
        SmallestQuantizationBitsFor(
            mesh, *mesh.GetNamedAttribute(GeometryAttribute::TEX_COORD, i),
            max_rmse, 30));
    if (bits < 0) {
      return ErrorStatus("No quantization meets RMSE " +
                         std::to_string(max_rmse) + ".");
    }
    qt = std::max(qt, bits);
  }
  return qt;
}

// The rows of error target |max_rmse|, one per -uv_seams name.
Status MeasureErrorTarget(const std::string &name, const Mesh &mesh,
                          const Mesh &without, const UvEvalOptions &options,
                          double max_rmse, std::vector<UvEvalRow> *rows) {
  DRACO_ASSIGN_OR_RETURN(const int lossless_qt, LosslessQtFor(mesh, max_rmse));
  DRACO_ASSIGN_OR_RETURN(const UvEvalBaseline baseline,
                         MeasureBaseline(mesh, without, options, lossless_qt));
  for (const std::string &seams : options.seams) {
    const std::string suffix = seams == "draco" ? "" : "+" + seams;
    UvEvalRow row;
    row.mesh = name;
    row.scheme = "rmse" + suffix;
    row.target_rmse = max_rmse;
    row.lossless_qt = lossless_qt;
    DRACO_ASSIGN_OR_RETURN(const UvEvalRow lossless,
                           MeasureScheme(name, mesh, options, lossless_qt,
                                         "auto" + suffix, baseline));
    row.lossless_uv_bytes = lossless.uv_bytes;
    UvEncodeSettings settings{options.qp, lossless_qt, options.cl};
    DRACO_ASSIGN_OR_RETURN(settings.uv, ParseUvSchemeName("draco" + suffix));
    settings.uv.rmse = max_rmse;
    DRACO_RETURN_IF_ERROR(
        MeasureSettings(mesh, options, settings, baseline, &row));
    rows->push_back(std::move(row));
  }
  return OkStatus();
}

}  // namespace

StatusOr<UvCompressionOptions> ParseUvSchemeName(const std::string &scheme) {
  const size_t plus = scheme.find('+');
  UvCompressionOptions options;
  DRACO_ASSIGN_OR_RETURN(options.prediction,
                         ParseUvPredictionName(scheme.substr(0, plus)));
  if (plus != std::string::npos) {
    DRACO_ASSIGN_OR_RETURN(options.seams,
                           ParseUvSeamCodingName(scheme.substr(plus + 1)));
  }
  return options;
}

std::unique_ptr<Mesh> MeshWithoutTangents(const Mesh &mesh) {
  std::unique_ptr<Mesh> copy(new Mesh());
  copy->Copy(mesh);
  const std::vector<int> ids = TangentAttributeIds(mesh);
  for (auto it = ids.rbegin(); it != ids.rend(); ++it) {
    copy->DeleteAttribute(*it);
  }
#ifdef DRACO_ATTRIBUTE_INDICES_DEDUPLICATION_SUPPORTED
  copy->DeduplicatePointIds();
#endif
  return copy;
}

namespace {

// Tangent values at every face corner, all tangent attributes, in face
// order.
std::vector<float> CornerTangents(const Mesh &mesh) {
  std::vector<float> values;
  for (const int att_id : TangentAttributeIds(mesh)) {
    const PointAttribute &att = *mesh.attribute(att_id);
    std::vector<float> value(att.num_components());
    for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
      for (const PointIndex point : mesh.face(f)) {
        att.ConvertValue(att.mapped_index(point), att.num_components(),
                         value.data());
        values.insert(values.end(), value.begin(), value.end());
      }
    }
  }
  return values;
}

// draco_encoder -qp -qt -cl with |scheme| and -tangent_pred |tangents|
// -qtg |qtg|.
StatusOr<UvEncodeSettings> TangentSettings(const UvEvalOptions &options, int qt,
                                           const std::string &scheme,
                                           const std::string &tangents,
                                           int qtg) {
  UvEncodeSettings settings{options.qp, qt, options.cl};
  DRACO_ASSIGN_OR_RETURN(settings.uv, ParseUvSchemeName(scheme));
  DRACO_ASSIGN_OR_RETURN(settings.uv.tangent.prediction,
                         ParseTangentPredictionName(tangents));
  settings.uv.tangent.quantization_bits = qtg;
  return settings;
}

// One encode with tangents, decoded, and one without them.
struct TangentEncoding {
  int64_t bytes = 0;
  int64_t tangent_bytes = 0;
  std::vector<float> tangents;  // Decoded, at every corner.
  std::string summary;
};

StatusOr<TangentEncoding> EncodeTangents(const Mesh &mesh, const Mesh &without,
                                         const UvEncodeSettings &settings) {
  TangentEncoding encoding;
  EncoderBuffer buffer;
  DRACO_RETURN_IF_ERROR(
      EncodeMeshWithSettings(mesh, settings, &buffer, &encoding.summary));
  double ms;
  DRACO_ASSIGN_OR_RETURN(const auto decoded, DecodeTimed(buffer, 1, &ms));
  encoding.tangents = CornerTangents(*decoded);
  encoding.bytes = static_cast<int64_t>(buffer.size());
  DRACO_ASSIGN_OR_RETURN(const int64_t without_bytes,
                         EncodedSize(without, settings));
  encoding.tangent_bytes = encoding.bytes - without_bytes;
  return encoding;
}

// The rows of one qt and qtg, against stock coding there.
Status MeasureTangentsAt(const std::string &name, const Mesh &mesh,
                         const Mesh &without, const UvEvalOptions &options,
                         int qt, int qtg, std::vector<TangentEvalRow> *rows) {
  DRACO_ASSIGN_OR_RETURN(const UvEncodeSettings stock_settings,
                         TangentSettings(options, qt, "draco", "draco", qtg));
  DRACO_ASSIGN_OR_RETURN(const TangentEncoding stock,
                         EncodeTangents(mesh, without, stock_settings));
  for (const std::string &scheme : MeasuredSchemes(options)) {
    for (const std::string &tangents : options.tangents) {
      DRACO_ASSIGN_OR_RETURN(
          const UvEncodeSettings settings,
          TangentSettings(options, qt, scheme, tangents, qtg));
      DRACO_ASSIGN_OR_RETURN(const TangentEncoding encoding,
                             EncodeTangents(mesh, without, settings));
      TangentEvalRow row;
      row.mesh = name;
      row.scheme = scheme;
      row.tangents = tangents;
      row.qt = qt;
      row.qtg = qtg;
      row.tangent_values = mesh.num_points();
      row.tangent_bytes = encoding.tangent_bytes;
      row.stock_tangent_bytes = stock.tangent_bytes;
      row.bytes = encoding.bytes;
      row.stock_bytes = stock.bytes;
      row.round_trip_ok = encoding.tangents == stock.tangents;
      row.detail = encoding.summary;
      rows->push_back(std::move(row));
    }
  }
  return OkStatus();
}

}  // namespace

bool HasTangents(const Mesh &mesh) {
  return !TangentAttributeIds(mesh).empty();
}

StatusOr<std::vector<TangentEvalRow>> EvaluateMeshTangents(
    const std::string &name, const Mesh &mesh, const UvEvalOptions &options) {
  std::vector<TangentEvalRow> rows;
  if (!HasTangents(mesh)) {
    return rows;
  }
  const std::unique_ptr<Mesh> without = MeshWithoutTangents(mesh);
  for (const int qt : options.qt) {
    for (const int qtg : options.qtg) {
      DRACO_RETURN_IF_ERROR(
          MeasureTangentsAt(name, mesh, *without, options, qt, qtg, &rows));
    }
  }
  return rows;
}

StatusOr<std::vector<UvEvalRow>> EvaluateMesh(const std::string &name,
                                              const Mesh &mesh,
                                              const UvEvalOptions &options) {
  if (mesh.num_faces() == 0 ||
      mesh.NumNamedAttributes(GeometryAttribute::TEX_COORD) == 0) {
    return Status(Status::DRACO_ERROR,
                  name + ": not a mesh with texture coordinates.");
  }
  const std::unique_ptr<Mesh> without = WithoutTexCoords(mesh);
  std::vector<UvEvalRow> rows;
  for (const int qt : options.qt) {
    DRACO_ASSIGN_OR_RETURN(const UvEvalBaseline baseline,
                           MeasureBaseline(mesh, *without, options, qt));
    for (const std::string &scheme : MeasuredSchemes(options)) {
      DRACO_ASSIGN_OR_RETURN(
          UvEvalRow row,
          MeasureScheme(name, mesh, options, qt, scheme, baseline));
      rows.push_back(std::move(row));
    }
  }
  for (const double max_rmse : options.rmse_targets) {
    DRACO_RETURN_IF_ERROR(
        MeasureErrorTarget(name, mesh, *without, options, max_rmse, &rows));
  }
  return rows;
}

}  // namespace draco
