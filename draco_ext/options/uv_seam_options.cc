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
#include "draco_ext/options/uv_seam_options.h"

#include "draco/compression/config/compression_shared.h"

namespace draco {

namespace {

// At speed 10 (-cl 0) Draco encodes meshes sequentially, without
// Edgebreaker; from speed 6 (-cl 4) down it cuts meshes along attribute
// seams unless told otherwise (MeshEdgebreakerEncoderImpl::Init()).
constexpr int kSequentialEncodingSpeed = 10;
constexpr int kSplitOnSeamsSpeed = 6;

bool SplitsMeshOnSeams(const EncoderOptions &options) {
  if (options.IsGlobalOptionSet("split_mesh_on_seams")) {
    return options.GetGlobalBool("split_mesh_on_seams", false);
  }
  return options.GetSpeed() >= kSplitOnSeamsSpeed;
}

}  // namespace

UvSeamCoding GetUvSeamCoding(const EncoderOptions &options) {
  return options.GetGlobalInt(kUvSeamCodingOption, 0) ==
                 static_cast<int>(UvSeamCoding::kContext)
             ? UvSeamCoding::kContext
             : UvSeamCoding::kDraco;
}

int UvSeamEdgebreakerMethodFor(const EncoderOptions &options,
                               int stock_method) {
  if (GetUvSeamCoding(options) != UvSeamCoding::kContext) {
    return stock_method;
  }
  switch (stock_method) {
    case MESH_EDGEBREAKER_STANDARD_ENCODING:
      return MESH_EDGEBREAKER_STANDARD_CONTEXT_SEAMS_ENCODING;
    case MESH_EDGEBREAKER_VALENCE_ENCODING:
      return MESH_EDGEBREAKER_VALENCE_CONTEXT_SEAMS_ENCODING;
    default:
      return stock_method;
  }
}

StatusOr<std::string> ConfigureUvSeams(UvSeamCoding coding, const Mesh *mesh,
                                       ExpertEncoder *encoder) {
  if (coding == UvSeamCoding::kDraco) {
    return std::string();
  }
  if (mesh == nullptr) {
    return Status(Status::DRACO_ERROR,
                  "-uv_seams applies to meshes, not to point clouds.");
  }
  if (encoder->options().GetSpeed() >= kSequentialEncodingSpeed) {
    return Status(Status::DRACO_ERROR,
                  "-uv_seams needs Edgebreaker encoding: use -cl 1 or higher.");
  }
  const int num_seam_sets = mesh->num_attributes() - 1;
  if (num_seam_sets < 1) {
    return std::string(
        "UV seams: the mesh has no attribute besides positions; stock coding "
        "kept.\n");
  }
  if (SplitsMeshOnSeams(encoder->options())) {
    return std::string(
        "UV seams: Draco cuts the mesh along seams at -cl 1..4 and codes "
        "none; stock coding kept.\n");
  }
  SetUvSeamCoding(coding, &encoder->options());
  return std::string("UV seams: ") + UvSeamCodingNameOf(coding) + ", " + std::to_string(num_seam_sets) +
         " seam set(s)\n";
}

}  // namespace draco
