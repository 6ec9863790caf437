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
// draco-uv's prediction scheme ids as Draco's patched sources see them
// (patches/0001): Draco's factory gate (CreateMeshPredictionScheme()) and
// its TEX_COORD-only check (EncoderBase::CheckPredictionScheme()) ask
// IsDracoUvPredictionMethod() instead of naming each id, so a new draco-uv
// scheme adds one line to PredictionSchemeMethod and none elsewhere in Draco.
#ifndef DRACO_EXT_HOOKS_PREDICTION_SCHEME_IDS_H_
#define DRACO_EXT_HOOKS_PREDICTION_SCHEME_IDS_H_

#include "draco_ext/common/uv_prediction_ids.h"  // IWYU pragma: export

#endif  // DRACO_EXT_HOOKS_PREDICTION_SCHEME_IDS_H_
