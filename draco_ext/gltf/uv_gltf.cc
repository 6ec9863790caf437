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

Status ConfigureUvCompressionForGltf(
    const Mesh &mesh, ExpertEncoder &encoder,
    std::set<std::string> *extensions_used,
    std::set<std::string> *extensions_required) {
  const UvCompressionOptions &options = mesh.GetCompressionOptions().uv;
  // Checks the options even when they are stock, like every entry point;
  // stock options leave the encoder untouched. The per-attribute summaries
  // are for command-line tools; a library stays quiet.
  DRACO_RETURN_IF_ERROR(
      ConfigureUvCompression(options, &mesh, &encoder).status());
  if ((options.ChoosesPrediction() ||
       options.tangent.prediction == TangentPrediction::kAuto) &&
      extensions_required->count(kUvGltfExtension) == 0) {
    DRACO_RETURN_IF_ERROR(
        KeepDracoUvOnlyIfItPaysForTheExtension(mesh, &encoder));
  }
  if (UsesDracoUvScheme(mesh, encoder) ||
      GetUvSeamCoding(encoder.options()) != UvSeamCoding::kDraco) {
    extensions_used->insert(kUvGltfExtension);
    extensions_required->insert(kUvGltfExtension);
  }
  return OkStatus();
}

Status ConfigureUvCompressionForGltf(
    const Mesh &mesh, const std::unique_ptr<ExpertEncoder> &encoder,
    std::set<std::string> *extensions_used,
    std::set<std::string> *extensions_required) {
  if (encoder == nullptr) {
    return ErrorStatus("No encoder for the glTF primitive.");
  }
  return ConfigureUvCompressionForGltf(mesh, *encoder, extensions_used,
                                       extensions_required);
}

#endif  // DRACO_TRANSCODER_SUPPORTED

}  // namespace draco
