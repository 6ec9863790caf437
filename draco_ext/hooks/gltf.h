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
// What Draco's glTF encoder (patches/0009) and decoder (patches/0010) call:
// ConfigureUvCompressionForGltf() applies a primitive's UvCompressionOptions
// (its material tells which texture coordinates its tangents follow) and
// marks the file with draco-uv's glTF extension where needed;
// IsUvGltfExtension() lets the decoder accept that extension.
#ifndef DRACO_EXT_HOOKS_GLTF_H_
#define DRACO_EXT_HOOKS_GLTF_H_

#include "draco_ext/gltf/uv_gltf.h"  // IWYU pragma: export
#include "draco_ext/gltf/uv_gltf_extension.h"  // IWYU pragma: export

#endif  // DRACO_EXT_HOOKS_GLTF_H_
