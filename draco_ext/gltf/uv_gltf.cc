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
#include "draco_ext/gltf/uv_gltf.h"

#include <utility>
#include <vector>

#include "draco/core/encoder_buffer.h"
#include "draco_ext/common/uv_prediction_ids.h"
#include "draco_ext/options/uv_seam_options.h"

#ifdef DRACO_TRANSCODER_SUPPORTED
#include "draco/compression/draco_compression_options.h"
#include "draco_ext/options/tangent_prediction_options.h"
#include "draco_ext/options/uv_configure.h"
#endif

namespace draco {

bool UsesDracoUvScheme(const Mesh &mesh, const ExpertEncoder &encoder) {
  for (int att_id = 0; att_id < mesh.num_attributes(); ++att_id) {
    const int method = encoder.options().GetAttributeInt(
        att_id, "prediction_scheme", PREDICTION_UNDEFINED);
    if (IsDracoUvPredictionMethod(
            static_cast<PredictionSchemeMethod>(method))) {
      return true;
    }
  }
  return false;
}

namespace {

StatusOr<size_t> EncodedSize(ExpertEncoder *encoder) {
  EncoderBuffer buffer;
  DRACO_RETURN_IF_ERROR(encoder->EncodeToBuffer(&buffer));
  return buffer.size();
}

}  // namespace

Status KeepDracoUvOnlyIfItPaysForTheExtension(const Mesh &mesh,
                                              ExpertEncoder *encoder) {
  if (GetUvSeamCoding(encoder->options()) != UvSeamCoding::kDraco ||
      !UsesDracoUvScheme(mesh, *encoder)) {
    return OkStatus();
  }
  DRACO_ASSIGN_OR_RETURN(const size_t chosen_size, EncodedSize(encoder));
  std::vector<std::pair<int, int>> chosen_methods;
  for (int att_id = 0; att_id < mesh.num_attributes(); ++att_id) {
    const int method = encoder->options().GetAttributeInt(
        att_id, "prediction_scheme", PREDICTION_UNDEFINED);
    if (!IsDracoUvPredictionMethod(method)) {
      continue;
    }
    chosen_methods.emplace_back(att_id, method);
    DRACO_RETURN_IF_ERROR(
        encoder->SetAttributePredictionScheme(att_id, PREDICTION_UNDEFINED));
  }
  DRACO_ASSIGN_OR_RETURN(const size_t stock_size, EncodedSize(encoder));
  if (chosen_size + kUvGltfExtensionJsonBytes >= stock_size) {
    return OkStatus();
  }
  for (const auto &[att_id, method] : chosen_methods) {
    DRACO_RETURN_IF_ERROR(
        encoder->SetAttributePredictionScheme(att_id, method));
  }
  return OkStatus();
}

#ifdef DRACO_TRANSCODER_SUPPORTED

namespace {

// True when |encoder| codes an attribute of |mesh| with a draco-uv scheme
// that |options| named rather than left to the encoder (-uv_pred auto or an
// error target for TEX_COORD, -tangent_pred auto for tangents): the
// primitive then needs the extension whatever its coders save.
bool UsesNamedDracoUvScheme(const Mesh &mesh, const ExpertEncoder &encoder,
                            const UvCompressionOptions &options) {
  for (int att_id = 0; att_id < mesh.num_attributes(); ++att_id) {
    const int method = encoder.options().GetAttributeInt(
        att_id, "prediction_scheme", PREDICTION_UNDEFINED);
    if (!IsDracoUvPredictionMethod(method)) {
      continue;
    }
    const bool chosen =
        mesh.attribute(att_id)->attribute_type() == GeometryAttribute::TEX_COORD
            ? options.ChoosesPrediction()
            : options.tangent.prediction == TangentPrediction::kAuto;
    if (!chosen) {
      return true;
    }
  }
  return false;
}

// Sets |tangent| to stock prediction, saying why, when a tangent prediction
// is asked for on a primitive whose tangents follow other texture
// coordinates than the first TEX_COORD attribute of |mesh|.
std::string KeepStockTangentsThatFollowOtherTexCoords(
    const Mesh &mesh, const Material *material,
    TangentCompressionOptions *tangent) {
  const int follows = GltfTangentTexCoordSet(material);
  const int predicted_from = GltfTexCoordSetOfFirstTexCoord(mesh);
  if (tangent->prediction == TangentPrediction::kDraco ||
      follows == predicted_from) {
    return "";
  }
  tangent->prediction = TangentPrediction::kDraco;
  std::string summary;
  for (const int att_id : TangentAttributeIds(mesh)) {
    summary += "Tangent prediction: " +
               GeometryAttribute::TypeToString(
                   mesh.attribute(att_id)->attribute_type()) +
               " (attribute " + std::to_string(att_id) +
               ") keeps stock coding: the material's normal texture uses "
               "TEXCOORD_" +
               std::to_string(follows) + ", the prediction reads TEXCOORD_" +
               std::to_string(predicted_from) + "\n";
  }
  return summary;
}

}  // namespace

int GltfTangentTexCoordSet(const Material *material) {
  const TextureMap *const normal_map =
      material == nullptr
          ? nullptr
          : material->GetTextureMapByType(TextureMap::NORMAL_TANGENT_SPACE);
  return normal_map == nullptr ? 0 : normal_map->tex_coord_index();
}

int GltfTexCoordSetOfFirstTexCoord(const Mesh &mesh) {
  const int att_id = mesh.GetNamedAttributeId(GeometryAttribute::TEX_COORD);
  const AttributeMetadata *const metadata =
      att_id < 0 ? nullptr : mesh.GetAttributeMetadataByAttributeId(att_id);
  std::string name;
  return metadata != nullptr &&
                 metadata->GetEntryString("attribute_name", &name) &&
                 name == "TEXCOORD_1"
             ? 1
             : 0;
}

StatusOr<std::string> ConfigureUvCompressionForGltfPrimitive(
    const Mesh &mesh, const Material *material, ExpertEncoder *encoder,
    std::set<std::string> *extensions_used,
    std::set<std::string> *extensions_required) {
  UvCompressionOptions options = mesh.GetCompressionOptions().uv;
  std::string summary = KeepStockTangentsThatFollowOtherTexCoords(
      mesh, material, &options.tangent);
  // Checks the options even when they are stock, like every entry point;
  // stock options leave the encoder untouched.
  DRACO_ASSIGN_OR_RETURN(const std::string configured,
                         ConfigureUvCompression(options, &mesh, encoder));
  summary += configured;
  if (extensions_required->count(kUvGltfExtension) == 0 &&
      UsesDracoUvScheme(mesh, *encoder) &&
      !UsesNamedDracoUvScheme(mesh, *encoder, options)) {
    DRACO_RETURN_IF_ERROR(
        KeepDracoUvOnlyIfItPaysForTheExtension(mesh, encoder));
    if (!UsesDracoUvScheme(mesh, *encoder)) {
      summary += std::string(
                     "Prediction (auto): draco for every attribute "
                     "(draco-uv's saving does not pay for ") +
                 kUvGltfExtension + ")\n";
    }
  }
  if (UsesDracoUvScheme(mesh, *encoder) ||
      GetUvSeamCoding(encoder->options()) != UvSeamCoding::kDraco) {
    extensions_used->insert(kUvGltfExtension);
    extensions_required->insert(kUvGltfExtension);
  }
  return summary;
}

Status ConfigureUvCompressionForGltf(
    const Mesh &mesh, const Material *material, ExpertEncoder &encoder,
    std::set<std::string> *extensions_used,
    std::set<std::string> *extensions_required) {
  return ConfigureUvCompressionForGltfPrimitive(
             mesh, material, &encoder, extensions_used, extensions_required)
      .status();
}

Status ConfigureUvCompressionForGltf(
    const Mesh &mesh, const Material *material,
    const std::unique_ptr<ExpertEncoder> &encoder,
    std::set<std::string> *extensions_used,
    std::set<std::string> *extensions_required) {
  if (encoder == nullptr) {
    return ErrorStatus("No encoder for the glTF primitive.");
  }
  return ConfigureUvCompressionForGltf(mesh, material, *encoder,
                                       extensions_used, extensions_required);
}

#endif  // DRACO_TRANSCODER_SUPPORTED

}  // namespace draco
