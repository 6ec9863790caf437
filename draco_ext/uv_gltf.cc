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
#include "draco_ext/uv_gltf.h"

#ifdef DRACO_TRANSCODER_SUPPORTED
#include "draco/compression/draco_compression_options.h"
#include "draco_ext/uv_prediction_options.h"

namespace draco {

bool UsesDracoUvScheme(const Mesh &mesh, const ExpertEncoder &encoder) {
  for (int i = 0; i < mesh.NumNamedAttributes(GeometryAttribute::TEX_COORD);
       ++i) {
    const int att_id =
        mesh.GetNamedAttributeId(GeometryAttribute::TEX_COORD, i);
    const int method = encoder.options().GetAttributeInt(
        att_id, "prediction_scheme", PREDICTION_UNDEFINED);
    if (IsDracoUvPredictionMethod(
            static_cast<PredictionSchemeMethod>(method))) {
      return true;
    }
  }
  return false;
}

Status ConfigureUvCompressionForGltf(
    const Mesh &mesh, ExpertEncoder &encoder,
    std::set<std::string> *extensions_used,
    std::set<std::string> *extensions_required) {
  const UvCompressionOptions &options = mesh.GetCompressionOptions().uv;
  if (options.IsStock()) {
    return OkStatus();
  }
  // The per-attribute summary is for command-line tools; a library stays
  // quiet.
  DRACO_RETURN_IF_ERROR(
      ConfigureUvPrediction(options.prediction, &mesh, &encoder).status());
  if (UsesDracoUvScheme(mesh, encoder)) {
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

}  // namespace draco

#endif  // DRACO_TRANSCODER_SUPPORTED
