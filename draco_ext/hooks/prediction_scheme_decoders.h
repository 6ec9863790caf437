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
// The decoder side of draco-uv's prediction schemes, as Draco's decoder
// factory calls it (patches/0002): one branch of
// MeshPredictionSchemeDecoderFactory hands every draco-uv id to
// CreateDracoUvPredictionSchemeDecoder(). Without DRACO_UV_LAPLACIAN (a
// lossless-only build) the Laplacian id gets no decoder, so such files fail
// to decode with an error.
#ifndef DRACO_EXT_HOOKS_PREDICTION_SCHEME_DECODERS_H_
#define DRACO_EXT_HOOKS_PREDICTION_SCHEME_DECODERS_H_

#include <memory>

#include "draco_ext/hooks/prediction_scheme_ids.h"
#include "prediction_schemes/tangent/mesh_prediction_scheme_geometric_tangent_decoder.h"
#include "prediction_schemes/weighted/mesh_prediction_scheme_tex_coords_weighted_decoder.h"
#ifdef DRACO_UV_LAPLACIAN
#include "prediction_schemes/laplacian/mesh_prediction_scheme_tex_coords_laplacian_decoder.h"
#endif

namespace draco {

// The decoder of draco-uv scheme |method| for |attribute| on |mesh_data|;
// null for an id this build does not decode.
template <typename DataTypeT, class TransformT, class MeshDataT>
std::unique_ptr<PredictionSchemeDecoder<DataTypeT, TransformT>>
CreateDracoUvPredictionSchemeDecoder(PredictionSchemeMethod method,
                                     const PointAttribute *attribute,
                                     const TransformT &transform,
                                     const MeshDataT &mesh_data) {
  switch (method) {
    case MESH_PREDICTION_TEX_COORDS_WEIGHTED:
    case MESH_PREDICTION_TEX_COORDS_WEIGHTED_MULTI:
      return std::make_unique<MeshPredictionSchemeTexCoordsWeightedDecoder<
          DataTypeT, TransformT, MeshDataT>>(attribute, transform, mesh_data,
                                             method);
    case MESH_PREDICTION_GEOMETRIC_TANGENT:
      return std::make_unique<MeshPredictionSchemeGeometricTangentDecoder<
          DataTypeT, TransformT, MeshDataT>>(attribute, transform, mesh_data);
#ifdef DRACO_UV_LAPLACIAN
    case MESH_PREDICTION_TEX_COORDS_LAPLACIAN:
      return std::make_unique<MeshPredictionSchemeTexCoordsLaplacianDecoder<
          DataTypeT, TransformT, MeshDataT>>(attribute, transform, mesh_data);
#endif
    default:
      return nullptr;
  }
}

}  // namespace draco

#endif  // DRACO_EXT_HOOKS_PREDICTION_SCHEME_DECODERS_H_
