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
// -uv_seams on a Draco encoder: how Draco's Edgebreaker codes the seams of
// texture coordinates and every other non-position attribute (kContext:
// draco-uv's crease-bit coder with context modelling, seams/uv_seam_coder.h;
// files need draco-uv's decoder). From C++, SetUvSeamCoding() sets the same
// option on Encoder or ExpertEncoder options.
#ifndef DRACO_EXT_OPTIONS_UV_SEAM_OPTIONS_H_
#define DRACO_EXT_OPTIONS_UV_SEAM_OPTIONS_H_

#include <string>

#include "draco/compression/config/encoder_options.h"
#include "draco/compression/expert_encode.h"
#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"
#include "draco_ext/options/uv_compression_options.h"

namespace draco {

// The global encoder option read by MeshEdgebreakerEncoder (patches/0006).
constexpr char kUvSeamCodingOption[] = "draco_uv_seams";

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

// The Edgebreaker method to write: |stock_method| (standard or valence) or
// its context-seams variant when |options| select -uv_seams context. Called
// by Draco's Edgebreaker encoder (patches/0006).
int UvSeamEdgebreakerMethodFor(const EncoderOptions &options, int stock_method);

// Applies -uv_seams |coding| for |mesh| on |encoder|, whose options must
// already be set. kDraco leaves the encoder untouched.
// "context" needs Edgebreaker encoding (fails at -cl 0 and for point
// clouds, |mesh| null); where Draco codes no seams (no attribute besides
// positions, or -cl 1 to 4, where Draco cuts the mesh along seams) it keeps
// stock coding and says so. Returns a one-line summary for the tools to
// print ("" when nothing changed).
StatusOr<std::string> ConfigureUvSeams(UvSeamCoding coding, const Mesh *mesh,
                                       ExpertEncoder *encoder);

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_UV_SEAM_OPTIONS_H_
