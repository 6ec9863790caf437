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
#include "draco_ext/options/tangent_prediction_options.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "draco/core/encoder_buffer.h"
#include "draco/draco_features.h"
#include "draco_ext/options/uv_compression_options.h"
#include "prediction_schemes/tangent/geometric_tangent_coder.h"
#include "prediction_schemes/tangent/geometric_tangent_settings.h"
#include "prediction_schemes/tangent/mesh_prediction_scheme_geometric_tangent_encoder.h"

namespace draco {

namespace {

// At speed 10 (-cl 0) Draco encodes meshes sequentially; at 6 to 9 (-cl 1 to
// 4), unless told otherwise, it splits the mesh on seams and codes every
// attribute in one attributes encoder, whose dependency order
// (PointCloudEncoder::RearrangeAttributesEncoders()) accepts no parent but
// attribute 0: it then fails to encode a scheme with the tangent's parents.
std::string WhyNotTheConnectivity(const EncoderOptions &options) {
  const int speed = options.GetSpeed();
  if (speed >= 10 || options.GetGlobalInt("encoding_method", -1) ==
                         MESH_SEQUENTIAL_ENCODING) {
    return "needs Edgebreaker encoding (-cl 5 or higher)";
  }
  const bool split = options.IsGlobalOptionSet("split_mesh_on_seams")
                         ? options.GetGlobalBool("split_mesh_on_seams", false)
                         : speed >= 6;
  return split ? "needs attribute seams of its own (-cl 5 or higher; -cl 1 "
                 "to 4 split the mesh on seams)"
               : "";
}

bool HasFiniteValues(const PointAttribute &att) {
  if (att.data_type() != DT_FLOAT32 && att.data_type() != DT_FLOAT64) {
    return true;
  }
  std::vector<double> value(att.num_components());
  for (AttributeValueIndex i(0); i < static_cast<uint32_t>(att.size()); ++i) {
    att.ConvertValue(i, att.num_components(), value.data());
    for (const double x : value) {
      if (!std::isfinite(x)) {
        return false;
      }
    }
  }
  return true;
}

int QuantizationBits(const ExpertEncoder &encoder, int att_id) {
  return encoder.options().GetAttributeInt(att_id, "quantization_bits", -1);
}

bool IsQuantized(const ExpertEncoder &encoder, int att_id) {
  return QuantizationBits(encoder, att_id) > 0;
}

// What the first attribute of |type| lacks for the prediction, or "".
std::string WhyNotTheParent(const Mesh &mesh, const ExpertEncoder &encoder,
                            GeometryAttribute::Type type, const char *name) {
  const int id = mesh.GetNamedAttributeId(type);
  if (id < 0) {
    return std::string("the mesh has no ") + name;
  }
  const PointAttribute &att = *mesh.attribute(id);
  if (!IsQuantized(encoder, id) && !(type == GeometryAttribute::POSITION &&
                                     IsDataTypeIntegral(att.data_type()))) {
    return std::string(name) + " is not quantized";
  }
  if (!HasFiniteValues(att)) {
    return std::string(name) + " has NaN or infinite values";
  }
  if (type == GeometryAttribute::TEX_COORD &&
      IsLossyUvPrediction(static_cast<PredictionSchemeMethod>(
          encoder.options().GetAttributeInt(id, "prediction_scheme",
                                            PREDICTION_UNDEFINED)))) {
    return std::string(name) +
           " is coded lossily (its decoded values may differ between "
           "platforms)";
  }
  return "";
}

StatusOr<size_t> EncodedSize(ExpertEncoder *encoder) {
  EncoderBuffer buffer;
  DRACO_RETURN_IF_ERROR(encoder->EncodeToBuffer(&buffer));
  return buffer.size();
}

std::string TangentLabel(const Mesh &mesh, int att_id) {
  const char *const type =
      mesh.attribute(att_id)->attribute_type() == GeometryAttribute::GENERIC
          ? "GENERIC"
          : "TANGENT";
  return std::string(type) + " (attribute " + std::to_string(att_id) + ")";
}

// -tangent_pred auto for |att_id|, set to the geometric scheme: keeps it
// where it makes the file smaller, else stock coding. |encoded_size|, when
// it holds the file's size with |att_id| coded stock and the other settings
// as they are, spares the stock trial encode (the geometric kinds option
// that ConfigureOne() sets is read by the geometric scheme only); it is set
// to the size with the coding kept.
StatusOr<std::string> KeepSmaller(const Mesh &mesh, int att_id,
                                  ExpertEncoder *encoder,
                                  std::optional<size_t> *encoded_size) {
  const StatusOr<size_t> geometric = EncodedSize(encoder);
  DRACO_RETURN_IF_ERROR(
      encoder->SetAttributePredictionScheme(att_id, PREDICTION_UNDEFINED));
  if (!encoded_size->has_value()) {
    DRACO_ASSIGN_OR_RETURN(*encoded_size, EncodedSize(encoder));
  }
  const size_t stock = encoded_size->value();
  const std::string label =
      "Tangent prediction (auto): " + TangentLabel(mesh, att_id) + " -> ";
  if (!geometric.ok() || geometric.value() >= stock) {
    return label + "draco, " + std::to_string(stock) + " bytes in all" +
           (geometric.ok()
                ? " (geometric: " + std::to_string(geometric.value()) + ")\n"
                : " (geometric failed: " +
                      std::string(geometric.status().error_msg()) + ")\n");
  }
  DRACO_RETURN_IF_ERROR(encoder->SetAttributePredictionScheme(
      att_id, MESH_PREDICTION_GEOMETRIC_TANGENT));
  *encoded_size = geometric.value();
  return label + "geometric, " + std::to_string(geometric.value()) +
         " bytes in all (draco: " + std::to_string(stock) + ")\n";
}

// |options| for tangent attribute |att_id| (quantization already set).
// |encoded_size| holds the file's size with |encoder|'s settings where
// known; it is kept up to date.
StatusOr<std::string> ConfigureOne(const TangentCompressionOptions &options,
                                   const Mesh &mesh, int att_id,
                                   ExpertEncoder *encoder,
                                   std::optional<size_t> *encoded_size) {
  const std::string reason =
      WhyNoGeometricTangentPrediction(mesh, *encoder, att_id);
  if (!reason.empty()) {
    return "Tangent prediction: " + TangentLabel(mesh, att_id) +
           " keeps stock coding: " + reason + "\n";
  }
  if (encoder->options().GetAttributeInt(att_id, "prediction_scheme",
                                         PREDICTION_UNDEFINED) !=
      PREDICTION_UNDEFINED) {
    // Not the stock coding that KeepSmaller() measures.
    encoded_size->reset();
  }
  DRACO_RETURN_IF_ERROR(encoder->SetAttributePredictionScheme(
      att_id, MESH_PREDICTION_GEOMETRIC_TANGENT));
  SetGeometricTangentKinds(GeometricTangentKindsOf(options.prediction), att_id,
                           &encoder->options());
  if (options.prediction == TangentPrediction::kAuto) {
    return KeepSmaller(mesh, att_id, encoder, encoded_size);
  }
  encoded_size->reset();
  return "Tangent prediction: " + TangentLabel(mesh, att_id) + " -> " +
         TangentPredictionNameOf(options.prediction) + "\n";
}

}  // namespace

bool HasTangentValues(const PointAttribute &att) {
  if (att.num_components() != 4 || att.data_type() != DT_FLOAT32 ||
      att.size() == 0) {
    return false;
  }
  // Values with a NaN or an infinity say nothing either way: tangents with
  // a few of them are still tangents (which ConfigureTangentPrediction()
  // then refuses with a message, rather than leaving them to Draco's
  // quantization as GENERIC values).
  size_t off_unit = 0, finite = 0;
  for (AttributeValueIndex i(0); i < static_cast<uint32_t>(att.size()); ++i) {
    float v[4];
    att.GetValue(i, v);
    if (!std::all_of(v, v + 4, [](float x) { return std::isfinite(x); })) {
      continue;
    }
    ++finite;
    if (v[3] != 1.f && v[3] != -1.f) {
      return false;
    }
    const double length =
        std::sqrt(double{v[0]} * v[0] + double{v[1]} * v[1] +
                  double{v[2]} * v[2]);
    off_unit += !(std::fabs(length - 1) <= 0.01);
  }
  return finite > 0 && off_unit * 100 <= finite;
}

std::vector<int> TangentAttributeIds(const Mesh &mesh) {
  std::vector<int> ids;
  for (int i = 0; i < mesh.num_attributes(); ++i) {
    const PointAttribute &att = *mesh.attribute(i);
#ifdef DRACO_TRANSCODER_SUPPORTED
    if (att.attribute_type() == GeometryAttribute::TANGENT) {
      ids.push_back(i);
      continue;
    }
#endif
    if (att.attribute_type() == GeometryAttribute::GENERIC &&
        HasTangentValues(att)) {
      ids.push_back(i);
    }
  }
  return ids;
}

std::string WhyNoGeometricTangentPrediction(const Mesh &mesh,
                                            const ExpertEncoder &encoder,
                                            int att_id) {
  std::string reason = WhyNotTheConnectivity(encoder.options());
  for (const auto &[type, name] :
       {std::make_pair(GeometryAttribute::POSITION, "POSITION"),
        std::make_pair(GeometryAttribute::NORMAL, "NORMAL"),
        std::make_pair(GeometryAttribute::TEX_COORD, "TEX_COORD 0")}) {
    if (reason.empty()) {
      reason = WhyNotTheParent(mesh, encoder, type, name);
    }
  }
  const PointAttribute &att = *mesh.attribute(att_id);
  const int bits =
      encoder.options().GetAttributeInt(att_id, "quantization_bits", -1);
  if (!reason.empty()) {
    return reason;
  }
  if (att.num_components() != 4 || att.data_type() != DT_FLOAT32) {
    return "not 4 float components";
  }
  if (bits < 1 || bits > TangentCompressionOptions::kMaxQuantizationBits) {
    return "needs tangents quantized to 1 to " +
           std::to_string(TangentCompressionOptions::kMaxQuantizationBits) +
           " bits";
  }
  if (!HasFiniteValues(att)) {
    return "NaN or infinite values";
  }
  // The scheme's fixed point holds up to 2^20 quantization steps per unit;
  // Draco spreads the 2^bits steps over the values' range, which nearly
  // constant tangents make tiny (the encoder would fail, and the decoder
  // refuses such a grid).
  if (!GeometricTangentGrid(att, encoder.options(), att_id).IsValid()) {
    return "its values span too small a range for " + std::to_string(bits) +
           " bits (more than 2^20 quantization steps per unit)";
  }
  return "";
}

Status CheckTangentValues(const TangentCompressionOptions &options,
                          const Mesh *mesh) {
  if (options.IsStock() || mesh == nullptr) {
    return OkStatus();
  }
  for (const int att_id : TangentAttributeIds(*mesh)) {
    if (!HasFiniteValues(*mesh->attribute(att_id))) {
      // Draco's quantization cannot cope either (it throws or writes
      // arbitrary integers).
      return ErrorStatus(TangentLabel(*mesh, att_id) +
                         " has NaN or infinite values.");
    }
  }
  return OkStatus();
}

StatusOr<std::string> ConfigureTangentPrediction(
    const TangentCompressionOptions &options, const Mesh *mesh,
    ExpertEncoder *encoder, std::optional<size_t> encoded_size) {
  DRACO_RETURN_IF_ERROR(CheckTangentCompressionOptions(options));
  if (options.IsStock()) {
    return std::string();
  }
  if (mesh == nullptr) {
    return ErrorStatus("-tangent_pred applies to meshes, not to point clouds.");
  }
  DRACO_RETURN_IF_ERROR(CheckTangentValues(options, mesh));
  std::string summary;
  for (const int att_id : TangentAttributeIds(*mesh)) {
    const int bits = QuantizationBits(*encoder, att_id);
    if (options.quantization_bits.has_value()) {
      encoder->SetAttributeQuantization(att_id, *options.quantization_bits);
    } else if (!IsQuantized(*encoder, att_id)) {
      encoder->SetAttributeQuantization(
          att_id, TangentCompressionOptions::kDefaultQuantizationBits);
    }
    if (QuantizationBits(*encoder, att_id) != bits) {
      encoded_size.reset();
    }
    if (options.prediction == TangentPrediction::kDraco) {
      continue;
    }
    DRACO_ASSIGN_OR_RETURN(
        const std::string line,
        ConfigureOne(options, *mesh, att_id, encoder, &encoded_size));
    summary += line;
  }
  return summary;
}

}  // namespace draco
