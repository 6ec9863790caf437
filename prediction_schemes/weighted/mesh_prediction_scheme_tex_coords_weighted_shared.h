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
// Constants, configuration and checks shared by the encoder and the decoder
// of MESH_PREDICTION_TEX_COORDS_WEIGHTED.
#ifndef PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_SHARED_H_
#define PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_SHARED_H_

#include <algorithm>
#include <cstdint>

#include "draco/attributes/point_attribute.h"
#include "draco/compression/config/compression_shared.h"
#include "prediction_schemes/weighted/uv_stencil_geometry.h"

namespace draco {

constexpr int kUvNumComponents = 2;

// Version of the scheme's prediction data; decoders reject other values.
constexpr uint8_t kTexCoordsWeightedFormatVersion = 3;

// Which stencils a vertex uses and how their predictions become one.
enum class UvPredictorKind : uint8_t {
  // Up to three stencils per vertex (UvStencilPlanner); per vertex the
  // candidate combination whose predictions had the smallest recent errors (a sum over the vertices decoded so far
  // that decays by 15/16 per vertex).
  kAdaptive = 0,
  // Up to three stencils per vertex; the mean of the weighted parallelogram
  // and the similarity prediction of every stencil, weighted by how much the
  // two agree.
  kAgreementWeighted = 1,
  // Only the stencil of the face through which Draco's traversal reaches
  // the vertex, as Draco's own texture coordinate predictors do: about half
  // the arithmetic of the others, for stock decoding speed. Needs Draco's
  // entry order. Per vertex, the candidate with the smallest recent errors
  // among its weighted parallelogram, similarity and parallelogram.
  kReachAdaptive = 2,
  // The reach stencil; the mean of its weighted parallelogram and its
  // similarity prediction.
  kReachMean = 3,
};

inline bool UsesReachStencil(UvPredictorKind kind) {
  return kind == UvPredictorKind::kReachAdaptive ||
         kind == UvPredictorKind::kReachMean;
}

// Per-attribute choices the encoder makes and the decoder reads.
struct UvPredictionConfig {
  bool max_degree_order = true;  // Else Draco's own entry order.
  UvPredictorKind kind = UvPredictorKind::kAdaptive;

  uint8_t ToByte() const {
    return static_cast<uint8_t>((max_degree_order ? 1 : 0) |
                                (static_cast<uint8_t>(kind) << 1));
  }
  // False for bytes no encoder writes.
  bool FromByte(uint8_t byte) {
    max_degree_order = (byte & 1) != 0;
    kind = static_cast<UvPredictorKind>(byte >> 1);
    return byte >> 1 <= static_cast<uint8_t>(UvPredictorKind::kReachMean) &&
           !(max_degree_order && UsesReachStencil(kind));
  }
};

// Largest valid UvPredictionConfig byte.
constexpr uint8_t kMaxUvPredictionConfigByte = 6;

// MESH_PREDICTION_TEX_COORDS_WEIGHTED promises stock decoding speed, so it
// only uses the reach stencil; its _MULTI variant may use every
// configuration.
inline bool IsAllowedUvConfig(PredictionSchemeMethod method,
                              const UvPredictionConfig &config) {
  return method == MESH_PREDICTION_TEX_COORDS_WEIGHTED_MULTI ||
         UsesReachStencil(config.kind);
}

// The parent attribute must be the integer (quantised) 3D position.
inline bool IsSupportedUvPositionAttribute(const PointAttribute *att) {
  return att != nullptr &&
         att->attribute_type() == GeometryAttribute::POSITION &&
         att->num_components() == 3 && IsDataTypeIntegral(att->data_type());
}

// True when the |size| values of |data| span fewer than
// 2^kUvStencilMaxUvQuantizationBits integers.
template <typename DataTypeT>
bool HasSupportedUvRange(const DataTypeT *data, int size) {
  if (size == 0) {
    return true;
  }
  const auto bounds = std::minmax_element(data, data + size);
  const int64_t span =
      static_cast<int64_t>(*bounds.second) - static_cast<int64_t>(*bounds.first);
  return span < (int64_t{1} << kUvStencilMaxUvQuantizationBits);
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_SHARED_H_
