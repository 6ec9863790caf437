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
// The encoder side of draco-uv's prediction schemes, as Draco's encoder
// factory calls it (patches/0002): CreatePredictionSchemeForEncoder() hands
// every draco-uv id to CreateDracoUvPredictionSchemeEncoder() before its own
// dispatch, because the Laplacian scheme needs the encoder's options, which
// Draco's mesh factories do not receive.
#ifndef DRACO_EXT_HOOKS_PREDICTION_SCHEME_ENCODERS_H_
#define DRACO_EXT_HOOKS_PREDICTION_SCHEME_ENCODERS_H_

#include <memory>

#include "draco/compression/attributes/prediction_schemes/prediction_scheme_delta_encoder.h"
#include "draco/compression/attributes/prediction_schemes/prediction_scheme_factory.h"
#include "draco/compression/mesh/mesh_encoder.h"
#include "draco_ext/hooks/prediction_scheme_ids.h"
#include "prediction_schemes/tangent/mesh_prediction_scheme_geometric_tangent_encoder.h"
#include "prediction_schemes/weighted/mesh_prediction_scheme_tex_coords_weighted_encoder.h"
#ifdef DRACO_UV_LAPLACIAN
#include "prediction_schemes/laplacian/mesh_prediction_scheme_tex_coords_laplacian_encoder.h"
#endif

namespace draco {

// Draco's MeshPredictionSchemeEncoderFactory for draco-uv's mesh-data
// schemes (used through CreateMeshPredictionScheme()).
template <typename DataTypeT>
struct DracoUvMeshPredictionSchemeEncoderFactory {
  template <class TransformT, class MeshDataT>
  std::unique_ptr<PredictionSchemeEncoder<DataTypeT, TransformT>> operator()(
      PredictionSchemeMethod method, const PointAttribute *attribute,
      const TransformT &transform, const MeshDataT &mesh_data,
      uint16_t /* bitstream_version */) {
    if (method != MESH_PREDICTION_TEX_COORDS_WEIGHTED &&
        method != MESH_PREDICTION_TEX_COORDS_WEIGHTED_MULTI) {
      return nullptr;
    }
    return std::make_unique<MeshPredictionSchemeTexCoordsWeightedEncoder<
        DataTypeT, TransformT, MeshDataT>>(attribute, transform, mesh_data,
                                           method);
  }
};

// The encoder of draco-uv scheme |method| for attribute |att_id| of
// |encoder|'s geometry. Where a weighted scheme has no connectivity to work
// on, it falls back to delta coding like Draco's own mesh schemes; the
// Laplacian and tangent schemes return null there (and the Laplacian one in a
// lossless-only build).
template <typename DataTypeT, class TransformT>
std::unique_ptr<PredictionSchemeEncoder<DataTypeT, TransformT>>
CreateDracoUvPredictionSchemeEncoder(PredictionSchemeMethod method,
                                     int att_id,
                                     const PointCloudEncoder *encoder,
                                     const TransformT &transform) {
  if (method == MESH_PREDICTION_GEOMETRIC_TANGENT) {
    return CreateMeshPredictionSchemeGeometricTangentEncoder<DataTypeT>(
        att_id, encoder, transform);
  }
  if (method == MESH_PREDICTION_TEX_COORDS_LAPLACIAN) {
#ifdef DRACO_UV_LAPLACIAN
    return CreateMeshPredictionSchemeTexCoordsLaplacianEncoder<DataTypeT>(
        att_id, encoder, transform);
#else
    return nullptr;
#endif
  }
  if (encoder->GetGeometryType() == TRIANGULAR_MESH) {
    auto scheme = CreateMeshPredictionScheme<
        MeshEncoder, PredictionSchemeEncoder<DataTypeT, TransformT>,
        DracoUvMeshPredictionSchemeEncoderFactory<DataTypeT>>(
        static_cast<const MeshEncoder *>(encoder), method, att_id, transform,
        kDracoMeshBitstreamVersion);
    if (scheme) {
      return scheme;
    }
  }
  return std::make_unique<PredictionSchemeDeltaEncoder<DataTypeT, TransformT>>(
      encoder->point_cloud()->attribute(att_id), transform);
}

}  // namespace draco

#endif  // DRACO_EXT_HOOKS_PREDICTION_SCHEME_ENCODERS_H_
