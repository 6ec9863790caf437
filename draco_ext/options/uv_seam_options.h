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
// The -uv_seams contract shared by draco_encoder, draco_transcoder and
// draco_uv_eval: how Draco's Edgebreaker codes the seams of texture
// coordinates and every other non-position attribute.
//
//   draco     stock Draco: one static-probability bit per interior edge and
//             attribute (the default; changes nothing)
//   context   draco-uv's crease-bit coder with context modelling
//             (uv_seam_coder.h); files need draco-uv's decoder
//
// From C++, SetUvSeamCoding() sets the same option on Encoder or
// ExpertEncoder options.
#ifndef DRACO_EXT_OPTIONS_UV_SEAM_OPTIONS_H_
#define DRACO_EXT_OPTIONS_UV_SEAM_OPTIONS_H_

#include <string>
#include <vector>

#include "draco/compression/config/encoder_options.h"
#include "draco/compression/expert_encode.h"
#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"

namespace draco {

enum class UvSeamCoding { kDraco = 0, kContext = 1 };

// The global encoder option read by MeshEdgebreakerEncoder (patch 0006).
constexpr char kUvSeamCodingOption[] = "draco_uv_seams";

struct UvSeamCodingName {
  const char *name;
  UvSeamCoding coding;
  const char *description;
};

// All names, in the order -h lists them.
const std::vector<UvSeamCodingName> &UvSeamCodingNames();

// Help text for the tools' -h.
std::string UvSeamCodingUsage();

// Resolves a -uv_seams name; an unknown name is an error listing the valid
// names.
StatusOr<UvSeamCoding> ParseUvSeamCodingName(const std::string &name);

// Selects |coding| on Draco encoder options (EncoderOptions or the options
// of draco::Encoder). Only the Edgebreaker encoder reads the option, so
// kDraco output is byte-identical to stock Draco.
template <class OptionsT>
void SetUvSeamCoding(UvSeamCoding coding, OptionsT *options) {
  options->SetGlobalInt(kUvSeamCodingOption, static_cast<int>(coding));
}

// The coding selected on |options| (kDraco unless SetUvSeamCoding() chose
// another).
UvSeamCoding GetUvSeamCoding(const EncoderOptions &options);

// Applies -uv_seams |name| for |mesh| on |encoder|, whose options must
// already be set. An empty name or "draco" leaves the encoder untouched.
// "context" needs Edgebreaker encoding (fails at -cl 0 and for point
// clouds, |mesh| null); where Draco codes no seams (no attribute besides
// positions, or -cl 1 to 4, where Draco cuts the mesh along seams) it keeps
// stock coding and says so. Returns a one-line summary for the tools to
// print ("" when nothing changed).
StatusOr<std::string> ConfigureUvSeams(const std::string &name,
                                       const Mesh *mesh,
                                       ExpertEncoder *encoder);

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_UV_SEAM_OPTIONS_H_
