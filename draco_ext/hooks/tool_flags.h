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
// draco-uv's command-line flags as draco_encoder (patches/0004) and
// draco_transcoder (patches/0011) take them: IsUvCompressionFlag() and
// ParseUvCompressionFlag() read -uv_pred, -uv_seams, -uv_anchors and the
// error target (-uv_rmse, -uv_texels, -uv_texture_size, -uv_decode_limit)
// into a UvCompressionOptions, UvCompressionUsage() is their help text, and
// ConfigureUvCompression() applies them to draco_encoder's ExpertEncoder.
// CheckUnhandledToolArg(), the last branch of both tools' argument loops,
// takes what no flag took: a flag that looks like draco-uv's is an error
// that names the closest one (-uv_prd: "did you mean -uv_pred?"), another
// flag is ignored with a warning, anything else silently, as in stock Draco.
// A new flag changes none of the patches (one entry of DracoUvFlagNames()).
#ifndef DRACO_EXT_HOOKS_TOOL_FLAGS_H_
#define DRACO_EXT_HOOKS_TOOL_FLAGS_H_

#include "draco_ext/options/draco_uv_flags.h"  // IWYU pragma: export
#include "draco_ext/options/uv_compression_options.h"  // IWYU pragma: export
#include "draco_ext/options/uv_configure.h"  // IWYU pragma: export

#endif  // DRACO_EXT_HOOKS_TOOL_FLAGS_H_
