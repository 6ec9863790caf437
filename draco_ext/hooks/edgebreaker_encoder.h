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
// What Draco's Edgebreaker encoder calls to code attribute seams with
// draco-uv's context model (patches/0006): UvSeamEdgebreakerMethodFor()
// turns the chosen method into its context-seam variant when the encoder
// options ask for it (-uv_seams context), IsUvSeamEdgebreakerMethod() and
// CreateUvSeamEdgebreakerEncoderImpl() create that variant, and the traversal
// encoders are instantiated in mesh_edgebreaker_encoder_impl.cc.
#ifndef DRACO_EXT_HOOKS_EDGEBREAKER_ENCODER_H_
#define DRACO_EXT_HOOKS_EDGEBREAKER_ENCODER_H_

#include "draco_ext/options/uv_seam_options.h"  // IWYU pragma: export
#include "draco_ext/seams/uv_seam_edgebreaker.h"  // IWYU pragma: export
#include "draco_ext/seams/mesh_edgebreaker_traversal_uv_seam_encoder.h"  // IWYU pragma: export

#endif  // DRACO_EXT_HOOKS_EDGEBREAKER_ENCODER_H_
