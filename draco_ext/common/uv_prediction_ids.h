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
// Which prediction scheme ids are draco-uv's. Draco's patched sources ask
// through hooks/prediction_scheme_ids.h; the options and the glTF marker ask
// here.
#ifndef DRACO_EXT_COMMON_UV_PREDICTION_IDS_H_
#define DRACO_EXT_COMMON_UV_PREDICTION_IDS_H_

#include "draco/attributes/geometry_attribute.h"
#include "draco/compression/config/compression_shared.h"
#include "draco/draco_features.h"

namespace draco {

// True for the ids that draco-uv adds after stock Draco's last one
// (MESH_PREDICTION_GEOMETRIC_NORMAL in Draco 1.5.5, 1.5.7 and upstream
// HEAD); a file using one needs a decoder with draco-uv.
// Takes an int like the prediction scheme options of Draco's encoder.
constexpr bool IsDracoUvPredictionMethod(int method) {
  return method > MESH_PREDICTION_GEOMETRIC_NORMAL &&
         method < NUM_PREDICTION_SCHEMES;
}

// Whether draco-uv's scheme |method| may code an attribute of |type|: the
// texture coordinate schemes TEX_COORD; the tangent scheme GENERIC (how
// Draco's bitstream and its JavaScript API carry glTF tangents) and, with
// Draco's transcoder, TANGENT (Draco's glTF reader's type, which its glTF
// encoder turns into GENERIC just before encoding).
inline bool IsDracoUvPredictionMethodFor(int method,
                                         GeometryAttribute::Type type) {
  if (method == MESH_PREDICTION_GEOMETRIC_TANGENT) {
#ifdef DRACO_TRANSCODER_SUPPORTED
    if (type == GeometryAttribute::TANGENT) {
      return true;
    }
#endif
    return type == GeometryAttribute::GENERIC;
  }
  return IsDracoUvPredictionMethod(method) &&
         type == GeometryAttribute::TEX_COORD;
}

}  // namespace draco

#endif  // DRACO_EXT_COMMON_UV_PREDICTION_IDS_H_
