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
// Encoder of MESH_PREDICTION_TEX_COORDS_WEIGHTED, the mesh-guided texture
// coordinate prediction based on [Váša & Brunnett 2014] L. Váša,
// G. Brunnett: Efficient encoding of texture coordinates guided by mesh
// geometry. CGF 33(5).
#ifndef PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_ENCODER_H_
#define PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_ENCODER_H_

#include <algorithm>
#include <vector>

#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_encoder.h"
#include "draco_ext/common/uv_bitstream_guard.h"
#include "draco_ext/common/uv_corner_graph.h"
#include "draco_ext/common/uv_residual_coder.h"
#include "prediction_schemes/weighted/mesh_prediction_scheme_tex_coords_weighted_predictor.h"
#include "prediction_schemes/weighted/mesh_prediction_scheme_tex_coords_weighted_shared.h"
#include "prediction_schemes/weighted/uv_processing_order.h"

namespace draco {

// Encodes 2-component texture coordinates with the predictions of
// MeshPredictionSchemeTexCoordsWeightedPredictor (see there for what is
// predicted, the fallbacks and the weak cases).
//
// The encoder tries both processing orders (max prediction degree, Draco's
// own) and both predictor kinds, and keeps the smallest. It codes the
// corrections itself with UvResidualEncoder and hands Draco all-zero
// corrections, which Draco's symbol coder stores in a few bytes.
//
// Prediction data, before the base class's transform data: the 8-byte
// bitstream guard (uv_bitstream_guard.h), the format version byte, the
// UvPredictionConfig byte and the residual streams.
//
// Needs integer (quantised) positions and texture coordinates spanning less
// than 2^20 values (-qt up to 20); ComputeCorrectionValues() fails otherwise.
template <typename DataTypeT, class TransformT, class MeshDataT>
class MeshPredictionSchemeTexCoordsWeightedEncoder
    : public MeshPredictionSchemeEncoder<DataTypeT, TransformT, MeshDataT> {
 public:
  using CorrType = typename MeshPredictionSchemeEncoder<DataTypeT, TransformT,
                                                        MeshDataT>::CorrType;
  // |method| is MESH_PREDICTION_TEX_COORDS_WEIGHTED or its _MULTI variant.
  MeshPredictionSchemeTexCoordsWeightedEncoder(
      const PointAttribute *attribute, const TransformT &transform,
      const MeshDataT &mesh_data,
      PredictionSchemeMethod method = MESH_PREDICTION_TEX_COORDS_WEIGHTED)
      : MeshPredictionSchemeEncoder<DataTypeT, TransformT, MeshDataT>(
            attribute, transform, mesh_data),
        method_(method) {}

  bool ComputeCorrectionValues(
      const DataTypeT *in_data, CorrType *out_corr, int size,
      int num_components, const PointIndex *entry_to_point_id_map) override;

  bool EncodePredictionData(EncoderBuffer *buffer) override;

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
  // Predicts every entry with |config| and collects the residuals.
  void RunPass(const UvPredictionConfig &config, const DataTypeT *in_data);
  // Keeps the residual streams of the last pass if they are the smallest.
  bool KeepIfSmaller(const UvPredictionConfig &config);

  // Every configuration the encoder tries for |method_|.
  std::vector<UvPredictionConfig> CandidateConfigs() const {
    std::vector<UvPredictionConfig> configs;
    for (uint8_t byte = 0; byte <= kMaxUvPredictionConfigByte; ++byte) {
      UvPredictionConfig config;
      if (config.FromByte(byte) && IsAllowedUvConfig(method_, config)) {
        configs.push_back(config);
      }
    }
    return configs;
  }

  const PredictionSchemeMethod method_;
  MeshPredictionSchemeTexCoordsWeightedPredictor<DataTypeT> predictor_;
  UvResidualEncoder residuals_;
  UvPredictionConfig config_;
  std::vector<char> best_streams_;
  bool has_best_ = false;
};

template <typename DataTypeT, class TransformT, class MeshDataT>
void MeshPredictionSchemeTexCoordsWeightedEncoder<DataTypeT, TransformT,
                                                  MeshDataT>::
    RunPass(const UvPredictionConfig &config, const DataTypeT *in_data) {
  residuals_.Reset(static_cast<int>(
      this->mesh_data().data_to_corner_map()->size() * kUvNumComponents));
  RunUvPrediction(
      this->mesh_data(), config, in_data, &predictor_, [&](int step, int entry) {
        CorrType correction[kUvNumComponents];
        this->transform().ComputeCorrection(in_data + entry * kUvNumComponents,
                                            predictor_.predicted_value(),
                                            correction);
        for (int i = 0; i < kUvNumComponents; ++i) {
          residuals_.Add(predictor_.context(), correction[i]);
        }
        predictor_.Update(step, in_data, correction);
        return true;
      });
}

template <typename DataTypeT, class TransformT, class MeshDataT>
bool MeshPredictionSchemeTexCoordsWeightedEncoder<
    DataTypeT, TransformT, MeshDataT>::KeepIfSmaller(const UvPredictionConfig
                                                         &config) {
  EncoderBuffer streams;
  if (!residuals_.Encode(&streams)) {
    return false;
  }
  if (!has_best_ || streams.size() < best_streams_.size()) {
    best_streams_.assign(streams.data(), streams.data() + streams.size());
    config_ = config;
    has_best_ = true;
  }
  return true;
}

template <typename DataTypeT, class TransformT, class MeshDataT>
bool MeshPredictionSchemeTexCoordsWeightedEncoder<DataTypeT, TransformT,
                                                  MeshDataT>::
    ComputeCorrectionValues(const DataTypeT *in_data, CorrType *out_corr,
                            int size, int num_components,
                            const PointIndex *entry_to_point_id_map) {
  if (num_components != kUvNumComponents ||
      size != static_cast<int>(this->mesh_data().data_to_corner_map()->size()) *
                  kUvNumComponents ||
      !HasSupportedUvRange(in_data, size)) {
    return false;
  }
  predictor_.SetEntryToPointIdMap(entry_to_point_id_map);
  this->transform().Init(in_data, size, num_components);
  has_best_ = false;
  for (const UvPredictionConfig &config : CandidateConfigs()) {
    RunPass(config, in_data);
    if (!KeepIfSmaller(config)) {
      return false;
    }
  }
  // The residuals travel in our own streams; Draco codes zeros.
  std::fill(out_corr, out_corr + size, CorrType(0));
  return true;
}

template <typename DataTypeT, class TransformT, class MeshDataT>
bool MeshPredictionSchemeTexCoordsWeightedEncoder<
    DataTypeT, TransformT, MeshDataT>::EncodePredictionData(EncoderBuffer
                                                                *buffer) {
  if (!has_best_) {
    return false;
  }
  EncodeUvBitstreamGuard(buffer);
  buffer->Encode(kTexCoordsWeightedFormatVersion);
  buffer->Encode(config_.ToByte());
  buffer->Encode(best_streams_.data(), best_streams_.size());
  return MeshPredictionSchemeEncoder<DataTypeT, TransformT,
                                     MeshDataT>::EncodePredictionData(buffer);
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_WEIGHTED_MESH_PREDICTION_SCHEME_TEX_COORDS_WEIGHTED_ENCODER_H_
