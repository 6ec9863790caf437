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

#include <algorithm>

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

const std::vector<UvSeamCodingName> &UvSeamCodingNames() {
  static const std::vector<UvSeamCodingName> names = {
      {"draco", UvSeamCoding::kDraco,
       "stock Draco: a static-probability bit per edge (default)"},
      {"context", UvSeamCoding::kContext,
       "context-modelled crease bits (draco-uv)"},
  };
  return names;
}

std::string UvSeamCodingUsage() {
  std::string usage =
      "  -uv_seams <name>      coding of attribute seams (needs -cl 5..10 "
      "to matter):\n";
  for (const UvSeamCodingName &entry : UvSeamCodingNames()) {
    std::string line = "                          " + std::string(entry.name);
    line.resize(std::max<size_t>(line.size() + 1, 48), ' ');
    usage += line + entry.description + "\n";
  }
  return usage;
}

StatusOr<UvSeamCoding> ParseUvSeamCodingName(const std::string &name) {
  std::string valid;
  for (const UvSeamCodingName &entry : UvSeamCodingNames()) {
    if (name == entry.name) {
      return entry.coding;
    }
    valid += (valid.empty() ? "" : ", ") + std::string(entry.name);
  }
  return Status(Status::DRACO_ERROR, "Unknown -uv_seams name '" + name +
                                         "'. Valid names: " + valid + ".");
}

UvSeamCoding GetUvSeamCoding(const EncoderOptions &options) {
  return options.GetGlobalInt(kUvSeamCodingOption, 0) ==
                 static_cast<int>(UvSeamCoding::kContext)
             ? UvSeamCoding::kContext
             : UvSeamCoding::kDraco;
}

StatusOr<std::string> ConfigureUvSeams(const std::string &name,
                                       const Mesh *mesh,
                                       ExpertEncoder *encoder) {
  if (name.empty()) {
    return std::string();
  }
  DRACO_ASSIGN_OR_RETURN(const UvSeamCoding coding,
                         ParseUvSeamCodingName(name));
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
  return "UV seams: " + name + ", " + std::to_string(num_seam_sets) +
         " seam set(s)\n";
}

}  // namespace draco
