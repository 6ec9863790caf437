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
#include "draco_ext/options/uv_prediction_options.h"

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "draco/core/encoder_buffer.h"
#include "draco_ext/common/uv_prediction_ids.h"
#include "draco_ext/common/uv_vertices.h"
#include "draco_ext/options/trial_encoder.h"
#include "draco_ext/options/uv_laplacian_options.h"
#include "prediction_schemes/weighted/uv_stencil_geometry.h"

namespace draco {

namespace {

// At speed 10 (-cl 0) Draco encodes meshes sequentially, without the
// connectivity that mesh prediction schemes need.
constexpr int kSequentialEncodingSpeed = 10;

bool IsWeighted(PredictionSchemeMethod method) {
  return method == MESH_PREDICTION_TEX_COORDS_WEIGHTED ||
         method == MESH_PREDICTION_TEX_COORDS_WEIGHTED_MULTI;
}

std::vector<int> TexCoordAttributeIds(const Mesh &mesh) {
  std::vector<int> ids;
  for (int i = 0; i < mesh.NumNamedAttributes(GeometryAttribute::TEX_COORD);
       ++i) {
    ids.push_back(mesh.GetNamedAttributeId(GeometryAttribute::TEX_COORD, i));
  }
  return ids;
}

int QuantizationBits(const EncoderOptions &options, int att_id) {
  return options.GetAttributeInt(att_id, "quantization_bits", -1);
}

int QuantizationBits(const ExpertEncoder &encoder, int att_id) {
  return QuantizationBits(encoder.options(), att_id);
}

// Checks the settings every non-stock -uv_pred needs: Edgebreaker encoding
// and quantized texture coordinates.
Status CheckCommonSettings(const ExpertEncoder &encoder, int att_id) {
  if (encoder.options().GetSpeed() >= kSequentialEncodingSpeed) {
    return Status(Status::DRACO_ERROR,
                  "-uv_pred needs Edgebreaker encoding: use -cl 1 or higher.");
  }
  if (QuantizationBits(encoder, att_id) <= 0) {
    return Status(Status::DRACO_ERROR,
                  "-uv_pred needs quantized texture coordinates (-qt > 0).");
  }
  return OkStatus();
}

// True when the floating point attribute |att| holds a NaN or an infinity.
bool HasNonFiniteValue(const PointAttribute &att) {
  if (att.data_type() != DT_FLOAT32 && att.data_type() != DT_FLOAT64) {
    return false;
  }
  std::vector<double> value(att.num_components());
  for (AttributeValueIndex i(0); i < static_cast<uint32_t>(att.size()); ++i) {
    att.ConvertValue(i, att.num_components(), value.data());
    for (const double x : value) {
      if (!std::isfinite(x)) {
        return true;
      }
    }
  }
  return false;
}

// Draco quantizes NaN and infinities to arbitrary integers (only the first
// value is checked), so draco-uv's schemes refuse them instead of
// predicting from them.
Status CheckFiniteValues(PredictionSchemeMethod method, const Mesh &mesh,
                         int att_id) {
  const int pos_id = mesh.GetNamedAttributeId(GeometryAttribute::POSITION);
  for (const int id : {att_id, pos_id}) {
    if (id >= 0 && HasNonFiniteValue(*mesh.attribute(id))) {
      return Status(Status::DRACO_ERROR,
                    "-uv_pred " + UvPredictionNameOf(method) + ": " +
                        (id == pos_id ? std::string("POSITION")
                                      : UvAttributeLabel(mesh, att_id)) +
                        " has NaN or infinite values.");
    }
  }
  return OkStatus();
}

// Checks what |method| needs beyond CheckCommonSettings() to code the
// TEX_COORD attribute |att_id|.
Status CheckSettingsFor(PredictionSchemeMethod method, const Mesh &mesh,
                        const ExpertEncoder &encoder, int att_id) {
  if (IsWeighted(method) &&
      QuantizationBits(encoder, att_id) > kUvStencilMaxUvQuantizationBits) {
    return Status(Status::DRACO_ERROR,
                  "-uv_pred " + UvPredictionNameOf(method) +
                      " supports -qt up to " +
                      std::to_string(kUvStencilMaxUvQuantizationBits) + ".");
  }
  if (UvPredictionNeedsQuantizedPositions(method)) {
    const int pos_id = mesh.GetNamedAttributeId(GeometryAttribute::POSITION);
    if (pos_id < 0) {
      return Status(Status::DRACO_ERROR,
                    "-uv_pred: the mesh has no POSITION attribute.");
    }
    if (QuantizationBits(encoder, pos_id) <= 0 &&
        !IsDataTypeIntegral(mesh.attribute(pos_id)->data_type())) {
      return Status(Status::DRACO_ERROR,
                    "-uv_pred needs quantized positions (-qp > 0).");
    }
  }
  if (IsDracoUvPredictionMethod(method)) {
    return CheckFiniteValues(method, mesh, att_id);
  }
  return OkStatus();
}

StatusOr<size_t> EncodedSize(ExpertEncoder *encoder) {
  EncoderBuffer buffer;
  DRACO_RETURN_IF_ERROR(encoder->EncodeToBuffer(&buffer));
  return buffer.size();
}

// -uv_pred auto takes weighted_multi, which decodes in about 1.3x stock
// Draco's instructions where its other candidates take 1.0-1.05x
// (benchmarks/decode_speed.md), only where it saves at least half a bit per
// UV vertex over the smallest of them: 4-17 % of the UV bytes on the corpus
// meshes where it does.
constexpr size_t kUvVerticesPerByteSlowDecodeMustSave = 16;

bool IsSlowToDecode(PredictionSchemeMethod method) {
  return method == MESH_PREDICTION_TEX_COORDS_WEIGHTED_MULTI;
}

// The most bits Draco 1.5.5's TEX_COORDS_PORTABLE prediction accepts for
// floating point positions, and for twice those plus the UVs' bits.
constexpr int kPortableMaxPositionBits = 21;
constexpr int kPortableMaxProductBits = 63;

// Candidates of -uv_pred auto: every lossless scheme. Stock Draco's choice
// comes first so that it wins ties.
std::vector<PredictionSchemeMethod> AutoCandidates() {
  std::vector<PredictionSchemeMethod> candidates;
  for (const UvPredictionName &entry : UvPredictionNames()) {
    if (entry.prediction != UvPrediction::kAuto &&
        !IsLossyUvPrediction(entry.method)) {
      candidates.push_back(entry.method);
    }
  }
  return candidates;
}

// -uv_pred auto's choice, with its summary line; sets |encoded_size|, if not
// null, to the size of the file with it.
StatusOr<std::string> ChooseSmallestFor(const Mesh &mesh, int att_id,
                                        ExpertEncoder *encoder,
                                        std::optional<size_t> *encoded_size) {
  DRACO_ASSIGN_OR_RETURN(const UvAutoChoice choice,
                         ChooseSmallestUvPrediction(mesh, att_id, encoder));
  if (encoded_size != nullptr) {
    *encoded_size = choice.bytes;
  }
  return "UV prediction (auto): " + UvAttributeLabel(mesh, att_id) + " -> " +
         UvPredictionNameOf(choice.method) + ", " +
         std::to_string(choice.bytes) +
         " bytes in all (draco: " + std::to_string(choice.stock_bytes) + ")\n";
}

}  // namespace

std::string UvAttributeLabel(const Mesh &mesh, int att_id) {
  int index = 0;
  while (mesh.GetNamedAttributeId(GeometryAttribute::TEX_COORD, index) !=
         att_id) {
    ++index;
  }
  return "TEX_COORD " + std::to_string(index) + " (attribute " +
         std::to_string(att_id) + ")";
}

PredictionSchemeMethod StockUvPrediction(const Mesh &mesh,
                                         const EncoderOptions &options,
                                         int att_id) {
  const int speed = options.GetSpeed();
  if (speed >= kSequentialEncodingSpeed) {
    return PREDICTION_DIFFERENCE;
  }
  const int uv_bits = QuantizationBits(options, att_id);
  const int pos_id = mesh.GetNamedAttributeId(GeometryAttribute::POSITION);
  if (speed < 4 && uv_bits != -1 &&
      mesh.attribute(att_id)->num_components() == 2 && pos_id >= 0) {
    const int pos_bits = QuantizationBits(options, pos_id);
    if (IsDataTypeIntegral(mesh.attribute(pos_id)->data_type()) ||
        (pos_bits > 0 && pos_bits <= kPortableMaxPositionBits &&
         2 * pos_bits + uv_bits <= kPortableMaxProductBits)) {
      return MESH_PREDICTION_TEX_COORDS_PORTABLE;
    }
  }
  if (speed >= 8) {
    return PREDICTION_DIFFERENCE;
  }
  if (speed >= 2 || mesh.num_points() < 40) {
    return MESH_PREDICTION_PARALLELOGRAM;
  }
  return MESH_PREDICTION_CONSTRAINED_MULTI_PARALLELOGRAM;
}

StatusOr<UvAutoChoice> ChooseSmallestUvPrediction(const Mesh &mesh, int att_id,
                                                  ExpertEncoder *encoder) {
  const size_t slow_handicap = (NumUvVertices(mesh, *mesh.attribute(att_id)) +
                                kUvVerticesPerByteSlowDecodeMustSave - 1) /
                               kUvVerticesPerByteSlowDecodeMustSave;
  // The whole file with Draco's own choice, which comes first and so wins
  // ties: the other candidates' sizes are that plus what a trial encode of
  // the positions and these texture coordinates alone differs by.
  UvAutoChoice choice;
  DRACO_RETURN_IF_ERROR(
      encoder->SetAttributePredictionScheme(att_id, PREDICTION_UNDEFINED));
  DRACO_ASSIGN_OR_RETURN(choice.stock_bytes, EncodedSize(encoder));
  choice.num_encodes = 1;
  choice.bytes = choice.stock_bytes;
  size_t best_cost = choice.stock_bytes;
  TrialEncoder trial(
      mesh, {mesh.GetNamedAttributeId(GeometryAttribute::POSITION), att_id},
      *encoder);
  std::optional<size_t> trial_stock_bytes;
  // The candidate that stock Draco picks itself would encode the same bytes
  // as the `draco` candidate: its trial is left out.
  const PredictionSchemeMethod stock_pick =
      StockUvPrediction(mesh, encoder->options(), att_id);
  for (const PredictionSchemeMethod method : AutoCandidates()) {
    if (method == PREDICTION_UNDEFINED || method == stock_pick ||
        !CheckSettingsFor(method, mesh, *encoder, att_id).ok()) {
      continue;
    }
    if (!trial_stock_bytes.has_value()) {
      DRACO_ASSIGN_OR_RETURN(
          trial_stock_bytes, trial.EncodedSizeWith(1, PREDICTION_UNDEFINED));
      ++choice.num_encodes;
    }
    const StatusOr<size_t> trial_size = trial.EncodedSizeWith(1, method);
    ++choice.num_encodes;
    if (!trial_size.ok()) {
      continue;
    }
    const size_t size =
        choice.stock_bytes + trial_size.value() - *trial_stock_bytes;
    const size_t cost = size + (IsSlowToDecode(method) ? slow_handicap : 0);
    if (cost < best_cost) {
      best_cost = cost;
      choice.bytes = size;
      choice.method = method;
    }
  }
  DRACO_RETURN_IF_ERROR(
      encoder->SetAttributePredictionScheme(att_id, choice.method));
  return choice;
}

StatusOr<std::string> ConfigureUvPredictionOf(
    const UvCompressionOptions &options, const Mesh *mesh, int att_id,
    ExpertEncoder *encoder, std::optional<size_t> *encoded_size) {
  if (encoded_size != nullptr) {
    encoded_size->reset();
  }
  if (options.prediction == UvPrediction::kDraco) {
    return std::string();
  }
  if (mesh == nullptr) {
    return Status(Status::DRACO_ERROR,
                  "-uv_pred applies to meshes, not to point clouds.");
  }
  if (att_id < 0 || att_id >= mesh->num_attributes() ||
      mesh->attribute(att_id)->attribute_type() !=
          GeometryAttribute::TEX_COORD) {
    return Status(Status::DRACO_ERROR,
                  "-uv_pred: attribute " + std::to_string(att_id) +
                      " is not a TEX_COORD attribute of the mesh.");
  }
  DRACO_RETURN_IF_ERROR(CheckCommonSettings(*encoder, att_id));
  if (options.prediction == UvPrediction::kAuto) {
    return ChooseSmallestFor(*mesh, att_id, encoder, encoded_size);
  }
  const PredictionSchemeMethod method = UvPredictionMethod(options.prediction);
  DRACO_RETURN_IF_ERROR(CheckSettingsFor(method, *mesh, *encoder, att_id));
  DRACO_RETURN_IF_ERROR(encoder->SetAttributePredictionScheme(att_id, method));
  if (IsUvLaplacian(options.prediction)) {
    DRACO_RETURN_IF_ERROR(ConfigureUvLaplacian(
        options.prediction, options.anchors, *mesh, att_id, encoder));
  }
  return "UV prediction: " + UvAttributeLabel(*mesh, att_id) + " -> " +
         UvPredictionNameOf(options.prediction) + "\n";
}

StatusOr<std::string> ConfigureUvPrediction(
    const UvCompressionOptions &options, const Mesh *mesh,
    ExpertEncoder *encoder, std::optional<size_t> *encoded_size) {
  if (encoded_size != nullptr) {
    encoded_size->reset();
  }
  if (options.prediction == UvPrediction::kDraco) {
    return std::string();
  }
  if (mesh == nullptr) {
    return Status(Status::DRACO_ERROR,
                  "-uv_pred applies to meshes, not to point clouds.");
  }
  std::string summary;
  for (const int att_id : TexCoordAttributeIds(*mesh)) {
    DRACO_ASSIGN_OR_RETURN(
        const std::string line,
        ConfigureUvPredictionOf(options, mesh, att_id, encoder,
                                encoded_size));
    summary += line;
  }
  return summary;
}

}  // namespace draco
