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
#include "draco_ext/options/uv_configure.h"

#include <optional>

#include "draco_ext/options/uv_error_target.h"
#include "draco_ext/options/uv_prediction_options.h"
#include "draco_ext/options/uv_seam_options.h"
#include "draco_ext/options/tangent_prediction_options.h"

namespace draco {

namespace {

Status ErrorTargetNeedsMesh() {
  return ErrorStatus(
      "An error target (-uv_rmse, -uv_texels) applies to meshes, not to "
      "point clouds.");
}

// The prediction of TEX_COORD attribute |att_id|: by the error target when
// |options| set one, else by -uv_pred. Sets |encoded_size| as
// ConfigureUvPredictionOf() does.
StatusOr<std::string> ConfigurePredictionOf(
    const UvCompressionOptions &options, const Mesh *mesh, int att_id,
    ExpertEncoder *encoder, std::optional<size_t> *encoded_size) {
  if (!options.MaxUvRmse().has_value()) {
    return ConfigureUvPredictionOf(options, mesh, att_id, encoder,
                                   encoded_size);
  }
  encoded_size->reset();
  if (mesh == nullptr) {
    return ErrorTargetNeedsMesh();
  }
  return ConfigureUvErrorTarget(options, *mesh, att_id, encoder);
}

}  // namespace

StatusOr<std::string> ConfigureUvCompression(
    const UvCompressionOptions &options, const Mesh *mesh,
    ExpertEncoder *encoder) {
  DRACO_RETURN_IF_ERROR(CheckUvCompressionOptions(options));
  // Before the UV coders' trial encodes, which would quantize them.
  DRACO_RETURN_IF_ERROR(CheckTangentValues(options.tangent, mesh));
  DRACO_ASSIGN_OR_RETURN(const std::string seams,
                         ConfigureUvSeams(options.seams, mesh, encoder));
  std::string summary = seams;
  // The file's size with the settings so far, where a trial encode measured
  // it: spares the tangents' trial encode of those settings.
  std::optional<size_t> encoded_size;
  if (!options.MaxUvRmse().has_value()) {
    DRACO_ASSIGN_OR_RETURN(
        const std::string prediction,
        ConfigureUvPrediction(options, mesh, encoder, &encoded_size));
    summary += prediction;
  } else if (mesh == nullptr) {
    return ErrorTargetNeedsMesh();
  } else {
    for (int i = 0;
         i < mesh->NumNamedAttributes(GeometryAttribute::TEX_COORD); ++i) {
      DRACO_ASSIGN_OR_RETURN(
          const std::string prediction,
          ConfigureUvErrorTarget(
              options, *mesh,
              mesh->GetNamedAttributeId(GeometryAttribute::TEX_COORD, i),
              encoder));
      summary += prediction;
    }
  }
  // Last: the tangents' prediction must know how the UVs are coded.
  DRACO_ASSIGN_OR_RETURN(
      const std::string tangents,
      ConfigureTangentPrediction(options.tangent, mesh, encoder, encoded_size));
  return summary + tangents;
}

StatusOr<std::string> ConfigureUvCompression(
    const std::map<int, UvCompressionOptions> &per_attribute,
    const Mesh *mesh, ExpertEncoder *encoder) {
  UvSeamCoding seam_coding = UvSeamCoding::kDraco;
  for (const auto &[att_id, options] : per_attribute) {
    DRACO_RETURN_IF_ERROR(CheckUvCompressionOptions(options));
    if (mesh != nullptr &&
        (att_id < 0 || att_id >= mesh->num_attributes() ||
         mesh->attribute(att_id)->attribute_type() !=
             GeometryAttribute::TEX_COORD)) {
      return Status(Status::DRACO_ERROR,
                    "Attribute " + std::to_string(att_id) +
                        " is not a TEX_COORD attribute of the mesh.");
    }
    if (options.seams != UvSeamCoding::kDraco) {
      seam_coding = options.seams;
    }
  }
  const TangentCompressionOptions tangent = TangentOptionsOf(per_attribute);
  DRACO_RETURN_IF_ERROR(CheckTangentValues(tangent, mesh));
  DRACO_ASSIGN_OR_RETURN(std::string summary,
                         ConfigureUvSeams(seam_coding, mesh, encoder));
  // As in the overload above.
  std::optional<size_t> encoded_size;
  for (const auto &[att_id, options] : per_attribute) {
    DRACO_ASSIGN_OR_RETURN(
        const std::string prediction,
        ConfigurePredictionOf(options, mesh, att_id, encoder, &encoded_size));
    summary += prediction;
  }
  DRACO_ASSIGN_OR_RETURN(
      const std::string tangents,
      ConfigureTangentPrediction(tangent, mesh, encoder, encoded_size));
  return summary + tangents;
}

TangentCompressionOptions TangentOptionsOf(
    const std::map<int, UvCompressionOptions> &per_attribute) {
  TangentCompressionOptions tangent;
  for (const auto &entry : per_attribute) {
    if (!entry.second.tangent.IsStock()) {
      tangent = entry.second.tangent;
    }
  }
  return tangent;
}

}  // namespace draco
