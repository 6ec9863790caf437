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
#include "draco_ext/options/uv_error_target.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "draco/attributes/attribute_quantization_transform.h"
#include "draco/core/encoder_buffer.h"
#include "draco/core/quantization_utils.h"
#include "draco_ext/options/uv_prediction_options.h"
#include "prediction_schemes/laplacian/uv_laplacian_settings.h"

// The WebAssembly encoder links no decoder, so it cannot measure a lossy
// trial encode.
#ifndef __EMSCRIPTEN__
#define DRACO_UV_DECODES_TRIALS
#include "draco/compression/decode.h"
#include "draco_ext/common/uv_rmse.h"
#ifdef DRACO_UV_LAPLACIAN
#define DRACO_UV_ESTIMATES_LAPLACIAN_DECODE
#include "prediction_schemes/laplacian/uv_laplacian_coder.h"
#endif
#endif

namespace draco {

namespace {

// Draco quantises with at most 30 bits.
constexpr int kMaxQuantizationBits = 30;
// The bits decoded faces are matched by when positions are not quantised.
constexpr int kUnquantizedPositionKeyBits = 14;
// At speed 10 (-cl 0) Draco encodes meshes sequentially, without the
// connectivity the UV schemes need.
constexpr int kSequentialEncodingSpeed = 10;

// The decode cost model of EstimateUvLaplacianDecode(), in instructions
// inside Decoder::DecodeMeshFromBuffer (-O3 x86-64 build, one thread, the
// AVX2 dense kernels), least-squares fitted to the relative error on the
// 22 real corpus meshes at -qp 14 -qt 12 -cl 10 (benchmarks/laplacian.md,
// "Decode cost of the error target's choice"; each term within 0.86-1.11x
// of the measured cost, the ratio within 0.89-1.11x). The stock-coded
// file: per face (connectivity, and every attribute's prediction per
// corner) and per component of an attribute value. The Laplacian coding
// adds, net of the stock coding of the attribute it replaces: per flop and
// per entry of the factor, and per texture vertex (ordering, operator,
// residual decoding and the solve).
constexpr double kStockInstructionsPerFace = 2350;
constexpr double kStockInstructionsPerValueComponent = 65;
constexpr double kLaplacianInstructionsPerFlop = 0.082;
constexpr double kLaplacianInstructionsPerFactorEntry = 180;
constexpr double kLaplacianInstructionsPerVertex = 2300;

// One coding of the attribute and what it gives.
struct Coding {
  UvPrediction prediction = UvPrediction::kDraco;  // A Laplacian or kDraco.
  PredictionSchemeMethod method = PREDICTION_UNDEFINED;
  int qt = 0;
  size_t bytes = 0;  // The whole file.
  double rmse = 0;
};

std::string Format(const char *format, double value) {
  char text[32];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

// Searches the codings of one attribute; every trial leaves its settings
// on the encoder until Apply() sets the chosen one.
class ErrorTargetSearch {
 public:
  ErrorTargetSearch(const UvCompressionOptions &options, const Mesh &mesh,
                    int att_id, ExpertEncoder *encoder)
      : options_(options),
        max_rmse_(*options.MaxUvRmse()),
        mesh_(mesh),
        att_id_(att_id),
        encoder_(encoder) {}

  // The smallest lossless coding that meets the target, if any.
  StatusOr<std::optional<Coding>> Lossless();
  // The smallest Laplacian coding that meets the target, if any; gives up
  // early when it cannot be smaller than |bytes_to_beat|.
  StatusOr<std::optional<Coding>> Laplacian(size_t bytes_to_beat);
  // Sets |coding| on the encoder.
  Status Apply(const Coding &coding);
  int num_encodes() const { return num_encodes_; }

 private:
  void SetQuantizationBits(int qt) {
    encoder_->options().SetAttributeInt(att_id_, "quantization_bits", qt);
  }
  // Applies |prediction| (not auto) through -uv_pred's own checks.
  Status SetPrediction(UvPrediction prediction) {
    UvCompressionOptions fixed;
    fixed.prediction = prediction;
    fixed.anchors = IsUvLaplacian(prediction) ? options_.anchors
                                              : std::optional<UvAnchorSpec>();
    return ConfigureUvPredictionOf(fixed, &mesh_, att_id_, encoder_).status();
  }
  StatusOr<size_t> EncodedSize(EncoderBuffer *buffer) {
    ++num_encodes_;
    DRACO_RETURN_IF_ERROR(encoder_->EncodeToBuffer(buffer));
    return buffer->size();
  }
  StatusOr<Coding> LaplacianAt(UvPrediction prediction, int qt);
  int TexCoordIndex() const;
  int PositionKeyBits() const;

  const UvCompressionOptions &options_;
  const double max_rmse_;
  const Mesh &mesh_;
  const int att_id_;
  ExpertEncoder *const encoder_;
  int num_encodes_ = 0;
};

StatusOr<std::optional<Coding>> ErrorTargetSearch::Lossless() {
  const PointAttribute &att = *mesh_.attribute(att_id_);
  DRACO_ASSIGN_OR_RETURN(
      const int qt,
      SmallestQuantizationBitsFor(mesh_, att, max_rmse_, kMaxQuantizationBits));
  if (qt < 0) {
    return std::optional<Coding>();
  }
  Coding coding;
  coding.qt = qt;
  DRACO_ASSIGN_OR_RETURN(coding.rmse, QuantizationRmse(mesh_, att, qt));
  SetQuantizationBits(qt);
  if (options_.ChoosesPrediction()) {
    DRACO_ASSIGN_OR_RETURN(
        const UvAutoChoice choice,
        ChooseSmallestUvPrediction(mesh_, att_id_, encoder_));
    num_encodes_ += choice.num_encodes;
    coding.method = choice.method;
    coding.bytes = choice.bytes;
    return std::optional<Coding>(coding);
  }
  DRACO_RETURN_IF_ERROR(SetPrediction(options_.prediction));
  coding.method = UvPredictionMethod(options_.prediction);
  EncoderBuffer buffer;
  DRACO_ASSIGN_OR_RETURN(coding.bytes, EncodedSize(&buffer));
  return std::optional<Coding>(coding);
}

int ErrorTargetSearch::TexCoordIndex() const {
  int index = 0;
  while (mesh_.GetNamedAttributeId(GeometryAttribute::TEX_COORD, index) !=
         att_id_) {
    ++index;
  }
  return index;
}

int ErrorTargetSearch::PositionKeyBits() const {
  const int pos_id = mesh_.GetNamedAttributeId(GeometryAttribute::POSITION);
  const int qp =
      encoder_->options().GetAttributeInt(pos_id, "quantization_bits", -1);
  return qp > 0 ? qp : kUnquantizedPositionKeyBits;
}

StatusOr<Coding> ErrorTargetSearch::LaplacianAt(UvPrediction prediction,
                                                int qt) {
#ifdef DRACO_UV_DECODES_TRIALS
  Coding coding;
  coding.prediction = prediction;
  coding.method = UvPredictionMethod(prediction);
  coding.qt = qt;
  SetQuantizationBits(qt);
  DRACO_RETURN_IF_ERROR(SetPrediction(prediction));
  EncoderBuffer encoded;
  DRACO_ASSIGN_OR_RETURN(coding.bytes, EncodedSize(&encoded));
  DecoderBuffer buffer;
  buffer.Init(encoded.data(), encoded.size());
  Decoder decoder;
  DRACO_ASSIGN_OR_RETURN(const std::unique_ptr<Mesh> decoded,
                         decoder.DecodeMeshFromBuffer(&buffer));
  DRACO_ASSIGN_OR_RETURN(
      coding.rmse,
      UvRmseOf(mesh_, *decoded, PositionKeyBits(), TexCoordIndex()));
  return coding;
#else
  return ErrorStatus(std::string("-uv_pred ") + UvPredictionNameOf(prediction) +
                     " with an error target needs Draco's decoder, which "
                     "this build lacks.");
#endif
}

StatusOr<std::optional<Coding>> ErrorTargetSearch::Laplacian(
    size_t bytes_to_beat) {
  const UvPrediction prediction = options_.ChoosesPrediction()
                                      ? UvPrediction::kLaplacianMeanValue
                                      : options_.prediction;
  // Its error at a -qt is near the grid's: start at the grid's -qt.
  DRACO_ASSIGN_OR_RETURN(
      const int grid_qt,
      SmallestQuantizationBitsFor(mesh_, *mesh_.attribute(att_id_), max_rmse_,
                                  kUvLaplacianMaxStepBits));
  int qt = grid_qt > 0 ? grid_qt : kUvLaplacianMaxStepBits;
  std::map<int, Coding> tried;
  const auto meets = [&](int qt) { return tried.at(qt).rmse <= max_rmse_; };
  while (true) {
    if (tried.count(qt) == 0) {
      DRACO_ASSIGN_OR_RETURN(tried[qt], LaplacianAt(prediction, qt));
      if (!meets(qt) && tried[qt].bytes >= bytes_to_beat) {
        return std::optional<Coding>();  // Finer steps only cost more.
      }
      if (tried.size() == 1) {  // RMSE ~ 2^-qt: jump to the predicted qt.
        const double bits = std::ceil(std::log2(tried[qt].rmse / max_rmse_));
        qt = std::clamp(qt + static_cast<int>(std::clamp(bits, -30.0, 30.0)), 1,
                        kUvLaplacianMaxStepBits);
        continue;
      }
    }
    if (meets(qt)) {
      if (qt > 1 && (tried.count(qt - 1) == 0 || meets(qt - 1))) {
        --qt;
        continue;
      }
      return std::optional<Coding>(tried[qt]);
    }
    if (qt == kUvLaplacianMaxStepBits) {
      return std::optional<Coding>();
    }
    ++qt;
  }
}

Status ErrorTargetSearch::Apply(const Coding &coding) {
  SetQuantizationBits(coding.qt);
  if (IsUvLaplacian(coding.prediction)) {
    return SetPrediction(coding.prediction);
  }
  return encoder_->SetAttributePredictionScheme(att_id_, coding.method);
}

// |spec| as -uv_anchors takes it.
std::string AnchorText(const UvAnchorSpec &spec) {
  return (spec.random ? "random:" : "") +
         (spec.is_percent ? Format("%g", spec.percent) + "%"
                          : std::to_string(spec.count));
}

// "<-uv_pred name> -qt <bits>[ -uv_anchors <spec>], <bytes> bytes".
std::string Describe(const Coding &coding,
                     const std::optional<UvAnchorSpec> &anchors) {
  const bool laplacian = IsUvLaplacian(coding.prediction);
  std::string text = (laplacian ? UvPredictionNameOf(coding.prediction)
                                : UvPredictionNameOf(coding.method)) +
                     std::string(" -qt ") + std::to_string(coding.qt);
  if (laplacian) {
    text += " -uv_anchors " +
            (anchors.has_value() ? AnchorText(*anchors) : "default");
  }
  return text + ", " + std::to_string(coding.bytes) + " bytes";
}

std::string TargetLabel(const UvCompressionOptions &options) {
  std::string label = "RMSE " + Format("%g", *options.MaxUvRmse());
  if (options.texels.has_value()) {
    label += " (" + Format("%g", *options.texels) + " texels of " +
             std::to_string(options.texture_size.value_or(
                 UvCompressionOptions::kDefaultTextureSize)) +
             ")";
  }
  return label;
}

// The summary line of |chosen| for the attribute |label|, naming the other
// |candidates| that met the target.
std::string Summary(const UvCompressionOptions &options,
                    const std::string &label, const Coding &chosen,
                    std::initializer_list<std::optional<Coding>> candidates,
                    const std::string &laplacian_note, int num_encodes) {
  std::string summary = "UV error target " + TargetLabel(options) + ": " +
                        label + " -> " + Describe(chosen, options.anchors) +
                        " in all, RMSE " + Format("%.3g", chosen.rmse) + " (";
  for (const std::optional<Coding> &other : candidates) {
    if (other && (other->method != chosen.method || other->qt != chosen.qt)) {
      summary += "also met: " + Describe(*other, options.anchors) + "; ";
    }
  }
  if (!laplacian_note.empty()) {
    summary += laplacian_note + "; ";
  }
  return summary + std::to_string(num_encodes) + " trial encodes)\n";
}

#ifdef DRACO_UV_ESTIMATES_LAPLACIAN_DECODE
// The texture connectivity of |att| as the Laplacian coder sees it: one
// texture vertex per distinct pair of position and texture coordinate
// (NumUvVertices()), numbered in the order of those pairs.
UvLaplacianMesh TextureConnectivity(const Mesh &mesh,
                                    const PointAttribute &att) {
  const PointAttribute *const position =
      mesh.GetNamedAttribute(GeometryAttribute::POSITION);
  std::vector<uint64_t> key(mesh.num_points());
  for (PointIndex p(0); p < mesh.num_points(); ++p) {
    const uint64_t pos =
        position == nullptr ? 0 : position->mapped_index(p).value();
    key[p.value()] = (pos << 32) | att.mapped_index(p).value();
  }
  std::vector<uint64_t> vertices = key;
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  UvLaplacianMesh texture;
  texture.positions.resize(vertices.size());  // Unused by the ordering.
  texture.faces.resize(mesh.num_faces());
  for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (int c = 0; c < 3; ++c) {
      texture.faces[f.value()][c] =
          static_cast<int>(std::lower_bound(vertices.begin(), vertices.end(),
                                            key[mesh.face(f)[c].value()]) -
                           vertices.begin());
    }
  }
  return texture;
}

// The stock-coded file's decode instructions (kStockInstructionsPerFace).
double StockDecodeInstructions(const Mesh &mesh) {
  double value_components = 0;
  for (int i = 0; i < mesh.num_attributes(); ++i) {
    value_components += static_cast<double>(mesh.attribute(i)->size()) *
                        mesh.attribute(i)->num_components();
  }
  return kStockInstructionsPerFace * mesh.num_faces() +
         kStockInstructionsPerValueComponent * value_components;
}
#endif  // DRACO_UV_ESTIMATES_LAPLACIAN_DECODE

// Why the Laplacian was or was not tried, for the summary line.
std::string LaplacianDecodeNote(
    const UvCompressionOptions &options,
    const StatusOr<UvLaplacianDecodeEstimate> &estimate, bool within_limit) {
  if (!estimate.ok()) {
    return "Laplacian not tried: " + estimate.status().error_msg_string();
  }
  std::string note = "Laplacian decode estimated at " +
                     Format("%.2g", estimate.value().ratio) +
                     "x the stock-coded file's";
  if (!options.ChoosesPrediction()) {
    return note;
  }
  if (std::isinf(options.DecodeLimit())) {
    return note + ", no -uv_decode_limit";
  }
  const std::string limit = Format("%g", options.DecodeLimit());
  return note + (within_limit
                     ? ", within -uv_decode_limit " + limit
                     : ", above -uv_decode_limit " + limit + ": not tried");
}

}  // namespace

StatusOr<UvLaplacianDecodeEstimate> EstimateUvLaplacianDecode(const Mesh &mesh,
                                                              int att_id) {
#ifdef DRACO_UV_ESTIMATES_LAPLACIAN_DECODE
  UvLaplacianDecodeEstimate estimate;
  if (!ComputeUvLaplacianDecodeWork(
          TextureConnectivity(mesh, *mesh.attribute(att_id)), &estimate.work)) {
    return ErrorStatus("its factor is too large for the decoder");
  }
  const UvLaplacianDecodeWork &work = estimate.work;
  const double extra = kLaplacianInstructionsPerFlop * work.factor_flops +
                       kLaplacianInstructionsPerFactorEntry *
                           static_cast<double>(work.factor_entries) +
                       kLaplacianInstructionsPerVertex * work.num_vertices;
  const double stock = StockDecodeInstructions(mesh);
  estimate.ratio = stock > 0 ? 1 + extra / stock : 1;
  return estimate;
#else
  (void)mesh;
  (void)att_id;
  return ErrorStatus(
      "this build has no Draco decoder to measure the Laplacian's trials");
#endif
}

StatusOr<double> QuantizationRmse(const Mesh &mesh, const PointAttribute &att,
                                  int quantization_bits) {
  AttributeQuantizationTransform transform;
  if (att.data_type() != DT_FLOAT32 ||
      !transform.ComputeParameters(att, quantization_bits)) {
    return ErrorStatus(
        "Quantization error: needs finite float values and 1 to 30 bits.");
  }
  const int32_t max_quantized_value = (1u << quantization_bits) - 1;
  Quantizer quantizer;
  quantizer.Init(transform.range(), max_quantized_value);
  Dequantizer dequantizer;
  dequantizer.Init(transform.range(), max_quantized_value);
  const std::vector<float> &min_values = transform.min_values();
  std::vector<float> value(att.num_components());
  std::vector<bool> counted(mesh.num_points(), false);
  int64_t num_points = 0;
  double sum2 = 0;
  for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (const PointIndex point : mesh.face(f)) {
      if (counted[point.value()]) {
        continue;
      }
      counted[point.value()] = true;
      ++num_points;
      att.GetValue(att.mapped_index(point), value.data());
      for (size_t c = 0; c < value.size(); ++c) {
        const int32_t q = quantizer.QuantizeFloat(value[c] - min_values[c]);
        const float decoded = dequantizer.DequantizeFloat(q) + min_values[c];
        const float error = value[c] - decoded;  // As UvRmse() subtracts.
        sum2 += error * static_cast<double>(error);
      }
    }
  }
  return num_points == 0 ? 0.0 : std::sqrt(sum2 / num_points);
}

StatusOr<int> SmallestQuantizationBitsFor(const Mesh &mesh,
                                          const PointAttribute &att,
                                          double max_rmse, int max_bits) {
  for (int bits = 1; bits <= max_bits; ++bits) {
    DRACO_ASSIGN_OR_RETURN(const double rmse,
                           QuantizationRmse(mesh, att, bits));
    if (rmse <= max_rmse) {
      return bits;
    }
  }
  return -1;
}

StatusOr<std::string> ConfigureUvErrorTarget(
    const UvCompressionOptions &options, const Mesh &mesh, int att_id,
    ExpertEncoder *encoder) {
  if (encoder->options().GetSpeed() >= kSequentialEncodingSpeed) {
    return ErrorStatus(
        "An error target (-uv_rmse, -uv_texels) needs Edgebreaker encoding: "
        "use -cl 1 or higher.");
  }
  ErrorTargetSearch search(options, mesh, att_id, encoder);
  std::optional<Coding> lossless;
  if (!IsUvLaplacian(options.prediction)) {
    DRACO_ASSIGN_OR_RETURN(lossless, search.Lossless());
  }
  std::optional<Coding> laplacian;
  std::string laplacian_note;
  if (IsUvLaplacian(options.prediction) ||
      (options.ChoosesPrediction() && HasUvLaplacianCoder())) {
    const StatusOr<UvLaplacianDecodeEstimate> estimate =
        EstimateUvLaplacianDecode(mesh, att_id);
    const bool within_limit =
        estimate.ok() && estimate.value().ratio <= options.DecodeLimit();
    laplacian_note = LaplacianDecodeNote(options, estimate, within_limit);
    if (IsUvLaplacian(options.prediction) || within_limit) {
      const auto result = search.Laplacian(
          lossless ? lossless->bytes : std::numeric_limits<size_t>::max());
      if (IsUvLaplacian(options.prediction) || result.ok()) {
        DRACO_ASSIGN_OR_RETURN(laplacian, result);
      }
    }
  }
  const std::optional<Coding> &best =
      laplacian && (!lossless || laplacian->bytes < lossless->bytes) ? laplacian
                                                                     : lossless;
  const std::string label = UvAttributeLabel(mesh, att_id);
  if (!best) {
    return ErrorStatus("No coding of " + label + " meets the error target " +
                       TargetLabel(options) + ".");
  }
  DRACO_RETURN_IF_ERROR(search.Apply(*best));
  return Summary(options, label, *best, {lossless, laplacian}, laplacian_note,
                 search.num_encodes());
}

}  // namespace draco
