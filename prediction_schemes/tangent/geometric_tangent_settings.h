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
// The conventions MESH_PREDICTION_GEOMETRIC_TANGENT can predict, and how
// the options layer tells the scheme's encoder which to try: it stores them
// in Draco's encoder options (SetGeometricTangentKinds()), and the encoder,
// which Draco's factory hands only those options, reads them back. Light on
// purpose: the options layer includes it.
#ifndef PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_SETTINGS_H_
#define PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_SETTINGS_H_

#include <cstdint>

#include "draco/compression/config/encoder_options.h"

namespace draco {

// How a vertex's tangent follows from the UV gradients (dP/du) of the
// triangles around it.
enum class GeometricTangentKind : uint8_t {
  // MikkTSpace: each corner's gradient projected onto the vertex normal and
  // normalised, weighted by the corner's angle, summed, normalised.
  kMikkTSpace = 0,
  // The same with every corner weighted equally.
  kUniform = 1,
  // The corners' gradients normalised and averaged without projecting onto
  // the normal: one triangle's own gradient where every corner has its own
  // vertex (exporters that write per-face tangents).
  kFace = 2,
};
constexpr int kNumGeometricTangentKinds = 3;

constexpr uint8_t GeometricTangentKindBit(GeometricTangentKind kind) {
  return static_cast<uint8_t>(1u << static_cast<int>(kind));
}
constexpr uint8_t kAllGeometricTangentKinds = (1u << kNumGeometricTangentKinds) - 1;

// The attribute option that holds the kinds to try, a mask of
// GeometricTangentKindBit().
constexpr char kGeometricTangentKindsOption[] = "draco_uv_tangent_kinds";

inline void SetGeometricTangentKinds(uint8_t kinds, int att_id,
                                     EncoderOptions *options) {
  options->SetAttributeInt(att_id, kGeometricTangentKindsOption, kinds);
}

// The kinds stored for |att_id|; all of them where none are.
inline uint8_t GetGeometricTangentKinds(const EncoderOptions &options,
                                        int att_id) {
  const int kinds = options.GetAttributeInt(
      att_id, kGeometricTangentKindsOption, kAllGeometricTangentKinds);
  return kinds > 0 && kinds <= kAllGeometricTangentKinds
             ? static_cast<uint8_t>(kinds)
             : kAllGeometricTangentKinds;
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_SETTINGS_H_
