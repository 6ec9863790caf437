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
// The per-mesh options of draco-uv as Draco's DracoCompressionOptions
// carries them (patches/0008): the typed UvCompressionOptions member and
// CheckUvCompressionOptions(), which DracoCompressionOptions::Check() calls.
#ifndef DRACO_EXT_HOOKS_COMPRESSION_OPTIONS_H_
#define DRACO_EXT_HOOKS_COMPRESSION_OPTIONS_H_

#include "draco_ext/options/uv_compression_options.h"  // IWYU pragma: export

#endif  // DRACO_EXT_HOOKS_COMPRESSION_OPTIONS_H_
