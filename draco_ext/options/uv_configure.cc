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

#include "draco_ext/options/uv_prediction_options.h"
#include "draco_ext/options/uv_seam_options.h"

namespace draco {

StatusOr<std::string> ConfigureUvCompression(
    const UvCompressionOptions &options, const Mesh *mesh,
    ExpertEncoder *encoder) {
  DRACO_RETURN_IF_ERROR(CheckUvCompressionOptions(options));
  DRACO_ASSIGN_OR_RETURN(const std::string seams,
                         ConfigureUvSeams(options.seams, mesh, encoder));
  DRACO_ASSIGN_OR_RETURN(const std::string prediction,
                         ConfigureUvPrediction(options, mesh, encoder));
  return seams + prediction;
}

}  // namespace draco
