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
// Decoder of MESH_PREDICTION_TEX_COORDS_WEIGHTED, the mesh-guided texture
// coordinate prediction based on [Váša & Brunnett 2014] L. Váša,
// G. Brunnett: Efficient encoding of texture coordinates guided by mesh
// geometry. CGF 33(5).
#ifndef PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_DECODER_H_
#define PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_DECODER_H_

#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_decoder.h"
#include "draco_ext/common/uv_bitstream_guard.h"
#include "draco_ext/common/uv_corner_graph.h"
#include "draco_ext/common/uv_residual_coder.h"
#include "prediction_schemes/weighted/mesh_prediction_scheme_tex_coords_weighted_predictor.h"
#include "prediction_schemes/weighted/mesh_prediction_scheme_tex_coords_weighted_shared.h"
#include "prediction_schemes/weighted/uv_processing_order.h"

namespace draco {

// Decodes texture coordinates written by
// MeshPredictionSchemeTexCoordsWeightedEncoder: checks the bitstream guard,
// the format version and the configuration byte, reads the residual streams
// and the transform data, then rebuilds every entry in the encoder's order
// from the same integer predictions.
//
// Treats its input as hostile: a wrong guard, version or configuration (a
// multi-stencil configuration under MESH_PREDICTION_TEX_COORDS_WEIGHTED too),
// non-zero Draco corrections, inconsistent stream counts, exhausted streams
// or anything but 2 components fail; out-of-range values only weaken the
// prediction (uv_stencil_geometry.h bounds every product).
template <typename DataTypeT, class TransformT, class MeshDataT>
class MeshPredictionSchemeTexCoordsWeightedDecoder
    : public MeshPredictionSchemeDecoder<DataTypeT, TransformT, MeshDataT> {
 public:
  using CorrType = typename MeshPredictionSchemeDecoder<DataTypeT, TransformT,
                                                        MeshDataT>::CorrType;
  // |method| is MESH_PREDICTION_TEX_COORDS_WEIGHTED or its _MULTI variant.
  MeshPredictionSchemeTexCoordsWeightedDecoder(
      const PointAttribute *attribute, const TransformT &transform,
      const MeshDataT &mesh_data,
      PredictionSchemeMethod method = MESH_PREDICTION_TEX_COORDS_WEIGHTED)
      : MeshPredictionSchemeDecoder<DataTypeT, TransformT, MeshDataT>(
            attribute, transform, mesh_data),
        method_(method) {}

  bool ComputeOriginalValues(const CorrType *in_corr, DataTypeT *out_data,
                             int size, int num_components,
                             const PointIndex *entry_to_point_id_map) override;

  bool DecodePredictionData(DecoderBuffer *buffer) override;

  PredictionSchemeMethod GetPredictionMethod() const override {
    return method_;
  }

  bool IsInitialized() const override {
    return predictor_.IsInitialized() && this->mesh_data().IsInitialized();
  }

  int GetNumParentAttributes() const override { return 1; }

  GeometryAttribute::Type GetParentAttributeType(int i) const override {
    DRACO_DCHECK_EQ(i, 0);
    (void)i;
    return GeometryAttribute::POSITION;
  }

  bool SetParentAttribute(const PointAttribute *att) override {
    if (!IsSupportedUvPositionAttribute(att)) {
      return false;
    }
    predictor_.SetPositionAttribute(*att);
    return true;
  }

 private:
  int NumEntries() const {
    return static_cast<int>(this->mesh_data().data_to_corner_map()->size());
  }

  const PredictionSchemeMethod method_;
  MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT> predictor_;
  UvResidualDecoder residuals_;
  UvPredictionConfig config_;
};

template <typename DataTypeT, class TransformT, class MeshDataT>
bool MeshPredictionSchemeTexCoordsWeightedDecoder<DataTypeT, TransformT,
                                                  MeshDataT>::
    ComputeOriginalValues(const CorrType *in_corr, DataTypeT *out_data,
                          int size, int num_components,
                          const PointIndex *entry_to_point_id_map) {
  if (num_components != kUvNumComponents ||
      size != NumEntries() * kUvNumComponents ||
      std::any_of(in_corr, in_corr + size,
                  [](CorrType c) { return c != CorrType(0); })) {
    return false;
  }
  predictor_.SetEntryToPointIdMap(entry_to_point_id_map);
  this->transform().Init(num_components);
  return RunUvPrediction(
      this->mesh_data(), config_, out_data, &predictor_,
      [&](int step, int entry) {
        CorrType correction[kUvNumComponents];
        for (int i = 0; i < kUvNumComponents; ++i) {
          int32_t residual;
          if (!residuals_.Next(predictor_.context(), &residual)) {
            return false;
          }
          correction[i] = static_cast<CorrType>(residual);
        }
        this->transform().ComputeOriginalValue(
            predictor_.predicted_value(), correction,
            out_data + entry * kUvNumComponents);
        predictor_.Update(step, out_data, correction);
        return true;
      });
}

template <typename DataTypeT, class TransformT, class MeshDataT>
bool MeshPredictionSchemeTexCoordsWeightedDecoder<
    DataTypeT, TransformT, MeshDataT>::DecodePredictionData(DecoderBuffer
                                                                *buffer) {
  uint8_t version, config;
  if (!DecodeUvBitstreamGuard(buffer) || !buffer->Decode(&version) ||
      version != kTexCoordsWeightedFormatVersion ||
      !buffer->Decode(&config) || !config_.FromByte(config) ||
      !IsAllowedUvConfig(method_, config_) ||
      !residuals_.Decode(NumEntries() * kUvNumComponents, buffer)) {
    return false;
  }
  return MeshPredictionSchemeDecoder<DataTypeT, TransformT,
                                     MeshDataT>::DecodePredictionData(buffer);
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_DECODER_H_
