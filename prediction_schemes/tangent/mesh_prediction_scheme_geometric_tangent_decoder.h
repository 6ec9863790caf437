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
// Decoder of MESH_PREDICTION_GEOMETRIC_TANGENT (see the encoder).
#ifndef PREDICTION_SCHEMES_TANGENT_MESH_PREDICTION_SCHEME_GEOMETRIC_TANGENT_DECODER_H_
#define PREDICTION_SCHEMES_TANGENT_MESH_PREDICTION_SCHEME_GEOMETRIC_TANGENT_DECODER_H_

#include <algorithm>
#include <type_traits>

#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_decoder.h"
#include "draco_ext/common/uv_bitstream_guard.h"
#include "draco_ext/common/uv_residual_coder.h"
#include "prediction_schemes/tangent/mesh_prediction_scheme_geometric_tangent_shared.h"

namespace draco {

// The CoderT of CodeGeometricTangents() that decodes: values from the
// residual streams, the handedness and copies from exceptions where the
// configuration says so.
class GeometricTangentDecodingCoder {
 public:
  GeometricTangentDecodingCoder(UvResidualDecoder *residuals,
                                const GeometricTangentConfig &config,
                                TangentExceptions *handedness_exceptions,
                                TangentExceptions *copy_exceptions)
      : residuals_(residuals),
        max_value_(config.coding.grid.max_value),
        handedness_exceptions_(config.handedness_exceptions
                                   ? handedness_exceptions
                                   : nullptr),
        copy_exceptions_(config.copy_exceptions ? copy_exceptions : nullptr) {}
  bool Value(int context, int32_t predicted, int32_t sign, int32_t *value) {
    int32_t residual;
    if (!residuals_->Next(context, &residual)) {
      return false;
    }
    const int64_t result = int64_t{predicted} + int64_t{sign} * residual;
    if (static_cast<uint64_t>(result) > static_cast<uint64_t>(max_value_)) {
      return false;
    }
    *value = static_cast<int32_t>(result);
    return true;
  }
  bool Handedness(int entry, const std::array<int32_t, 2> &predicted,
                  int32_t *w) {
    int32_t symbol = 0;
    if (handedness_exceptions_ != nullptr) {
      handedness_exceptions_->Take(entry, &symbol);
    } else if (!residuals_->Next(kTangentHandednessContext, &symbol)) {
      return false;
    }
    return HandednessFromSymbol(symbol, predicted, max_value_, w);
  }
  bool Copy(int entry, const int32_t *source, int32_t *v) {
    int32_t unused;
    if (copy_exceptions_ != nullptr &&
        !copy_exceptions_->Take(entry, &unused)) {
      std::copy(source, source + kTangentNumComponents, v);
      return true;
    }
    for (int c = 0; c < kTangentNumComponents; ++c) {
      if (!Value(kTangentCopyContext, source[c], 1, &v[c])) {
        return false;
      }
    }
    return true;
  }

 private:
  UvResidualDecoder *residuals_;
  int32_t max_value_;
  TangentExceptions *handedness_exceptions_;
  TangentExceptions *copy_exceptions_;
};

// Decodes the tangents of |connectivity| into |values| as |config| says,
// with |predictor|'s parents set; the work of
// MeshPredictionSchemeGeometricTangentDecoder::ComputeOriginalValues(),
// compiled once for both of Draco's corner tables.
inline bool DecodeGeometricTangents(const TangentConnectivity &connectivity,
                                    const GeometricTangentConfig &config,
                                    GeometricTangentPredictor *predictor,
                                    UvResidualDecoder *residuals,
                                    TangentExceptions *handedness_exceptions,
                                    TangentExceptions *copy_exceptions,
                                    int32_t *values) {
  predictor->ComputeSums(connectivity, config.kind, config.normal_bits);
  GeometricTangentDecodingCoder coder(residuals, config, handedness_exceptions,
                                      copy_exceptions);
  return CodeGeometricTangents(
      connectivity, config.coding,
      [&](int entry) { return predictor->Predict(connectivity, entry); },
      &coder, values);
}

// Decodes tangents written by MeshPredictionSchemeGeometricTangentEncoder:
// checks the guard, the format version and the configuration, reads the
// residual streams and the transform data, then rebuilds every entry in
// the encoder's order from the same integer predictions.
// Treats its input as hostile: a wrong guard, version or configuration,
// non-zero Draco corrections, exhausted streams, a decoded value outside
// the grid, parents of the wrong shape or anything but 4 components fail;
// out-of-range parent values only weaken the predictions
// (tangent_geometry.h bounds every product).
template <typename DataTypeT, class TransformT, class MeshDataT>
class MeshPredictionSchemeGeometricTangentDecoder
    : public MeshPredictionSchemeDecoder<DataTypeT, TransformT, MeshDataT> {
  static_assert(std::is_same<DataTypeT, int32_t>::value,
                "Draco decodes integer attributes as int32_t.");

 public:
  using CorrType = typename MeshPredictionSchemeDecoder<DataTypeT, TransformT,
                                                        MeshDataT>::CorrType;
  MeshPredictionSchemeGeometricTangentDecoder(const PointAttribute *attribute,
                                              const TransformT &transform,
                                              const MeshDataT &mesh_data)
      : MeshPredictionSchemeDecoder<DataTypeT, TransformT, MeshDataT>(
            attribute, transform, mesh_data) {}

  bool ComputeOriginalValues(const CorrType *in_corr, DataTypeT *out_data,
                             int size, int num_components,
                             const PointIndex *entry_to_point_id_map) override;

  bool DecodePredictionData(DecoderBuffer *buffer) override {
    uint8_t version;
    uint32_t num_tokens;
    if (!DecodeUvBitstreamGuard(buffer) || !buffer->Decode(&version) ||
        version != kGeometricTangentFormatVersion ||
        !config_.Decode(buffer) ||
        (config_.handedness_exceptions &&
         !handedness_exceptions_.Decode(true, NumEntries(), buffer)) ||
        (config_.copy_exceptions &&
         !copy_exceptions_.Decode(false, NumEntries(), buffer)) ||
        !DecodeVarint(&num_tokens, buffer) ||
        num_tokens > static_cast<uint32_t>(NumEntries()) *
                         kTangentNumComponents ||
        !residuals_.Decode(static_cast<int>(num_tokens), buffer)) {
      return false;
    }
    return MeshPredictionSchemeDecoder<DataTypeT, TransformT,
                                       MeshDataT>::DecodePredictionData(buffer);
  }

  PredictionSchemeMethod GetPredictionMethod() const override {
    return MESH_PREDICTION_GEOMETRIC_TANGENT;
  }
  // Draco's corrections are all zero (see the encoder): no sign to undo.
  bool AreCorrectionsPositive() override { return true; }
  bool IsInitialized() const override {
    return predictor_.IsInitialized() && this->mesh_data().IsInitialized();
  }
  int GetNumParentAttributes() const override {
    return kGeometricTangentNumParents;
  }
  GeometryAttribute::Type GetParentAttributeType(int i) const override {
    return GeometricTangentParentType(i);
  }
  bool SetParentAttribute(const PointAttribute *att) override {
    return predictor_.SetParentAttribute(att);
  }

 private:
  int NumEntries() const {
    return static_cast<int>(this->mesh_data().data_to_corner_map()->size());
  }

  GeometricTangentPredictor predictor_;
  TangentConnectivity connectivity_;
  UvResidualDecoder residuals_{kTangentNumContexts};
  GeometricTangentConfig config_;
  TangentExceptions handedness_exceptions_;
  TangentExceptions copy_exceptions_;
};

template <typename DataTypeT, class TransformT, class MeshDataT>
bool MeshPredictionSchemeGeometricTangentDecoder<DataTypeT, TransformT,
                                                 MeshDataT>::
    ComputeOriginalValues(const CorrType *in_corr, DataTypeT *out_data,
                          int size, int num_components,
                          const PointIndex * /* entry_to_point_id_map */) {
  if (num_components != kTangentNumComponents ||
      size != NumEntries() * kTangentNumComponents) {
    return false;
  }
  // Every correction must be zero: OR them all (a loop compilers
  // vectorise, unlike a search that stops early).
  CorrType any = 0;
  for (int i = 0; i < size; ++i) {
    any |= in_corr[i];
  }
  if (any != 0) {
    return false;
  }
  InitTangentConnectivity(this->mesh_data(), &connectivity_);
  return DecodeGeometricTangents(connectivity_, config_, &predictor_,
                                 &residuals_, &handedness_exceptions_,
                                 &copy_exceptions_,
                                 reinterpret_cast<int32_t *>(out_data));
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_TANGENT_MESH_PREDICTION_SCHEME_GEOMETRIC_TANGENT_DECODER_H_
