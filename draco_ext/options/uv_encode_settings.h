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
// Encoding a mesh exactly as draco_encoder does for a given command line
// (-qp, -qt, -cl, -uv_pred, -uv_seams, -uv_anchors), for draco_uv_eval,
// benchmarks and tests.
#ifndef DRACO_EXT_OPTIONS_UV_ENCODE_SETTINGS_H_
#define DRACO_EXT_OPTIONS_UV_ENCODE_SETTINGS_H_

#include <string>

#include "draco/core/encoder_buffer.h"
#include "draco/core/status.h"
#include "draco/mesh/mesh.h"
#include "draco_ext/options/uv_compression_options.h"

namespace draco {

// draco_encoder's settings, with its defaults for -qn and -qg.
struct UvEncodeSettings {
  int qp = 14;
  int qt = 12;
  int cl = 10;
  UvCompressionOptions uv;  // -uv_pred, -uv_seams, -uv_anchors.
};

// Encodes |mesh| like
// `draco_encoder -qp -qt -cl [-uv_pred] [-uv_seams] [-uv_anchors]` into
// |out|. |summary|, if given, receives ConfigureUvCompression()'s summary.
Status EncodeMeshWithSettings(const Mesh &mesh,
                              const UvEncodeSettings &settings,
                              EncoderBuffer *out,
                              std::string *summary = nullptr);

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_UV_ENCODE_SETTINGS_H_
