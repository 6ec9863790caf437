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
#include "draco_ext/web/uv_web_encoder.h"

#include <algorithm>
#include <limits>
#include <memory>

#include "draco/compression/config/compression_shared.h"
#include "draco_ext/common/uv_prediction_ids.h"
#include "draco_ext/gltf/uv_gltf.h"
#include "draco_ext/options/tangent_compression_options.h"
#include "draco_ext/options/uv_configure.h"
#include "draco_ext/options/uv_seam_options.h"

namespace draco {

namespace {

// Offsets in Draco's file header ("DRACO", major, minor, geometry type,
// encoder method, flags).
constexpr size_t kHeaderGeometryTypeOffset = 7;
constexpr size_t kHeaderEncoderMethodOffset = 8;

// True when the Edgebreaker mesh encode of |encoder| that wrote |out| wrote
// draco-uv ids: the context seams' connectivity method or a draco-uv
// prediction scheme of a TEX_COORD attribute. Draco's sequential mesh
// encoding writes neither (its prediction factory falls back to stock).
bool WroteDracoUvIds(const Mesh &mesh, const ExpertEncoder &encoder,
                     const EncoderBuffer &out) {
  if (out.size() <= kHeaderEncoderMethodOffset ||
      out.data()[kHeaderGeometryTypeOffset] != TRIANGULAR_MESH ||
      out.data()[kHeaderEncoderMethodOffset] != MESH_EDGEBREAKER_ENCODING) {
    return false;
  }
  return GetUvSeamCoding(encoder.options()) != UvSeamCoding::kDraco ||
         UsesDracoUvScheme(mesh, encoder);
}

// True when |encoder| codes an attribute of |mesh| with a draco-uv scheme
// that |per_attribute| named rather than left to the encoder (-uv_pred auto
// or an error target for TEX_COORD, -tangent_pred auto for the tangents):
// the native glTF encoder's rule (gltf/uv_gltf.cc), under which such a
// primitive needs the glTF extension whatever its coders save.
bool UsesNamedDracoUvScheme(
    const Mesh &mesh, const ExpertEncoder &encoder,
    const std::map<int, UvCompressionOptions> &per_attribute) {
  const bool tangents_chosen =
      TangentOptionsOf(per_attribute).prediction == TangentPrediction::kAuto;
  for (int att_id = 0; att_id < mesh.num_attributes(); ++att_id) {
    const int method = encoder.options().GetAttributeInt(
        att_id, "prediction_scheme", PREDICTION_UNDEFINED);
    if (!IsDracoUvPredictionMethod(method)) {
      continue;
    }
    const auto own = per_attribute.find(att_id);
    const bool chosen = own != per_attribute.end()
                            ? own->second.ChoosesPrediction()
                            : tangents_chosen;
    if (!chosen) {
      return true;
    }
  }
  return false;
}

}  // namespace

bool DracoUvOptions::Result(const Status &status) {
  error_ = status.ok() ? std::string() : status.error_msg_string();
  return status.ok();
}

bool DracoUvOptions::SetPrediction(const char *name) {
  const std::string value = name == nullptr ? "" : name;
  if (value.empty()) {
    options_.prediction = UvPrediction::kDraco;
    return Result(OkStatus());
  }
  const StatusOr<UvPrediction> prediction = ParseUvPredictionName(value);
  if (prediction.ok()) {
    options_.prediction = prediction.value();
  }
  return Result(prediction.status());
}

bool DracoUvOptions::SetSeams(const char *name) {
  const std::string value = name == nullptr ? "" : name;
  if (value.empty()) {
    options_.seams = UvSeamCoding::kDraco;
    return Result(OkStatus());
  }
  const StatusOr<UvSeamCoding> seams = ParseUvSeamCodingName(value);
  if (seams.ok()) {
    options_.seams = seams.value();
  }
  return Result(seams.status());
}

bool DracoUvOptions::SetAnchors(const char *spec) {
  const std::string value = spec == nullptr ? "" : spec;
  if (value.empty()) {
    options_.anchors.reset();
    return Result(OkStatus());
  }
  const StatusOr<UvAnchorSpec> anchors = ParseUvAnchorSpec(value);
  if (anchors.ok()) {
    options_.anchors = anchors.value();
  }
  return Result(anchors.status());
}

bool DracoUvOptions::SetTangentPrediction(const char *name) {
  const std::string value = name == nullptr ? "" : name;
  if (value.empty()) {
    options_.tangent.prediction = TangentPrediction::kDraco;
    return Result(OkStatus());
  }
  const StatusOr<TangentPrediction> prediction =
      ParseTangentPredictionName(value);
  if (prediction.ok()) {
    options_.tangent.prediction = prediction.value();
  }
  return Result(prediction.status());
}

bool DracoUvOptions::SetTangentQuantization(long bits) {
  if (bits == 0) {
    options_.tangent.quantization_bits.reset();
    return Result(OkStatus());
  }
  TangentCompressionOptions tangent;
  tangent.quantization_bits = static_cast<int>(
      std::clamp<long>(bits, -1, std::numeric_limits<int>::max()));
  const Status status = CheckTangentCompressionOptions(tangent);
  if (status.ok()) {
    options_.tangent.quantization_bits = tangent.quantization_bits;
  }
  return Result(status);
}

bool DracoUvOptions::SetRmse(double rmse) {
  UvCompressionOptions target;
  target.rmse = rmse;
  const Status status = CheckUvCompressionOptions(target);
  if (status.ok()) {
    options_.rmse = rmse;
    options_.texels.reset();
    options_.texture_size.reset();
  }
  return Result(status);
}

bool DracoUvOptions::SetTexels(double texels, long texture_size) {
  UvCompressionOptions target;
  target.texels = texels;
  target.texture_size = static_cast<int>(
      std::clamp<long>(texture_size, 0, std::numeric_limits<int>::max()));
  const Status status = CheckUvCompressionOptions(target);
  if (status.ok()) {
    options_.rmse.reset();
    options_.texels = target.texels;
    options_.texture_size = target.texture_size;
  }
  return Result(status);
}

UvWebModuleState &UvWebModuleState::Instance() {
  static UvWebModuleState *const state = new UvWebModuleState();
  return *state;
}

void UvWebModuleState::CountEncodeWithDracoUvIds() {
  ++num_encodes_with_draco_uv_ids_;
  if (gltf_write_ == GltfWrite::kExtensionNotYetPaid) {
    gltf_write_ = GltfWrite::kExtensionPaid;
  }
}

Status UvWebModuleState::SetDefault(const UvCompressionOptions &options) {
  DRACO_RETURN_IF_ERROR(CheckUvCompressionOptions(options));
  default_ = options;
  return OkStatus();
}

bool DracoUvModule::SetDefault(const DracoUvOptions *options) {
  const Status status =
      options == nullptr
          ? Status(Status::DRACO_ERROR, "SetDefault: no DracoUvOptions.")
          : state_->SetDefault(options->options());
  error_ = status.ok() ? std::string() : status.error_msg_string();
  return status.ok();
}

bool UvWebEncoder::Refuse(const std::string &message) {
  message_ = message;
  return false;
}

bool UvWebEncoder::SetForType(GeometryAttribute::Type type,
                              const DracoUvOptions *options) {
  if (options == nullptr) {
    return Refuse("SetAttributeUvCompression: no DracoUvOptions.");
  }
  if (type != GeometryAttribute::TEX_COORD) {
    return Refuse(
        "SetAttributeUvCompression: draco-uv codes TEX_COORD attributes "
        "only.");
  }
  const Status status = CheckUvCompressionOptions(options->options());
  if (!status.ok()) {
    return Refuse(status.error_msg_string());
  }
  for_type_ = options->options();
  message_.clear();
  return true;
}

bool UvWebEncoder::SetForAttribute(const PointCloud *pc, int att_id,
                                   const DracoUvOptions *options) {
  if (options == nullptr) {
    return Refuse("SetAttributeUvCompression: no DracoUvOptions.");
  }
  if (dynamic_cast<const Mesh *>(pc) == nullptr) {
    return Refuse(
        "SetAttributeUvCompression: draco-uv codes the texture coordinates "
        "of meshes, not of point clouds.");
  }
  if (att_id < 0 || att_id >= pc->num_attributes() ||
      pc->attribute(att_id)->attribute_type() !=
          GeometryAttribute::TEX_COORD) {
    return Refuse("SetAttributeUvCompression: attribute " +
                  std::to_string(att_id) + " is not a TEX_COORD attribute.");
  }
  const Status status = CheckUvCompressionOptions(options->options());
  if (!status.ok()) {
    return Refuse(status.error_msg_string());
  }
  for_attribute_[att_id] = options->options();
  message_.clear();
  return true;
}

std::map<int, UvCompressionOptions> UvWebEncoder::OptionsFor(
    const Mesh &mesh) const {
  std::map<int, UvCompressionOptions> options;
  for (int i = 0; i < mesh.NumNamedAttributes(GeometryAttribute::TEX_COORD);
       ++i) {
    const int att_id =
        mesh.GetNamedAttributeId(GeometryAttribute::TEX_COORD, i);
    const auto own = for_attribute_.find(att_id);
    if (own != for_attribute_.end()) {
      options[att_id] = own->second;
    } else if (for_type_.has_value()) {
      options[att_id] = *for_type_;
    } else if (module_->default_options().has_value()) {
      options[att_id] = *module_->default_options();
    }
  }
  return options;
}

Status UvWebEncoder::Finish(const Status &status, bool used_draco_uv_ids,
                            const std::string &summary) {
  used_draco_uv_coding_ = status.ok() && used_draco_uv_ids;
  message_ = status.ok() ? summary : status.error_msg_string();
  if (used_draco_uv_coding_) {
    module_->CountEncodeWithDracoUvIds();
  }
  return status;
}

Status UvWebEncoder::EncodeConfigured(const Mesh &mesh,
                                      const EncoderOptions &options,
                                      EncoderBuffer *out) {
  ExpertEncoder encoder(mesh);
  encoder.Reset(options);
  const std::map<int, UvCompressionOptions> per_attribute = OptionsFor(mesh);
  const StatusOr<std::string> summary =
      ConfigureUvCompression(per_attribute, &mesh, &encoder);
  if (!summary.ok()) {
    return Finish(summary.status(), false, "");
  }
  std::string chosen = summary.value();
  if (module_->gltf_extension_not_yet_paid() &&
      UsesDracoUvScheme(mesh, encoder) &&
      !UsesNamedDracoUvScheme(mesh, encoder, per_attribute)) {
    const Status status =
        KeepDracoUvOnlyIfItPaysForTheExtension(mesh, &encoder);
    if (!status.ok()) {
      return Finish(status, false, "");
    }
    if (!UsesDracoUvScheme(mesh, encoder)) {
      chosen += std::string(
                    "Prediction (auto): draco for every attribute "
                    "(draco-uv's saving does not pay for ") +
                kUvGltfExtension + ")\n";
    }
  }
  const Status status = encoder.EncodeToBuffer(out);
  num_encoded_points_ = encoder.num_encoded_points();
  num_encoded_faces_ = encoder.num_encoded_faces();
  return Finish(status, status.ok() && WroteDracoUvIds(mesh, encoder, *out),
                chosen);
}

Status UvWebEncoder::EncodeMesh(const Mesh &mesh, Encoder *encoder,
                                EncoderBuffer *out) {
  if (OptionsFor(mesh).empty()) {
    const Status status = encoder->EncodeMeshToBuffer(mesh, out);
    num_encoded_points_ = encoder->num_encoded_points();
    num_encoded_faces_ = encoder->num_encoded_faces();
    return Finish(status, false, "");
  }
  return EncodeConfigured(mesh, encoder->CreateExpertEncoderOptions(mesh),
                          out);
}

Status UvWebEncoder::EncodePointCloud(const PointCloud &pc, Encoder *encoder,
                                      EncoderBuffer *out) {
  const Status status = encoder->EncodePointCloudToBuffer(pc, out);
  num_encoded_points_ = encoder->num_encoded_points();
  num_encoded_faces_ = encoder->num_encoded_faces();
  return Finish(status, false, "");
}

Status UvWebEncoder::EncodeWithExpert(const PointCloud &pc,
                                      ExpertEncoder *encoder,
                                      EncoderBuffer *out) {
  const Mesh *const mesh = dynamic_cast<const Mesh *>(&pc);
  if (mesh == nullptr || OptionsFor(*mesh).empty()) {
    const Status status = encoder->EncodeToBuffer(out);
    num_encoded_points_ = encoder->num_encoded_points();
    num_encoded_faces_ = encoder->num_encoded_faces();
    return Finish(status, false, "");
  }
  return EncodeConfigured(*mesh, encoder->options(), out);
}

}  // namespace draco
