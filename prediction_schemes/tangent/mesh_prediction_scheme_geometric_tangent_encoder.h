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
// Encoder of MESH_PREDICTION_GEOMETRIC_TANGENT: glTF TANGENTs (xyz a unit
// vector, w = +-1) predicted from the decoded positions, normals and
// texture coordinates (geometric_tangent_predictor.h) and coded one
// component after the other (geometric_tangent_coder.h).
#ifndef PREDICTION_SCHEMES_TANGENT_MESH_PREDICTION_SCHEME_GEOMETRIC_TANGENT_ENCODER_H_
#define PREDICTION_SCHEMES_TANGENT_MESH_PREDICTION_SCHEME_GEOMETRIC_TANGENT_ENCODER_H_

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "draco/attributes/attribute_quantization_transform.h"
#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_data.h"
#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_encoder.h"
#include "draco/compression/mesh/mesh_encoder.h"
#include "draco_ext/common/uv_bitstream_guard.h"
#include "draco_ext/common/uv_residual_coder.h"
#include "prediction_schemes/tangent/geometric_tangent_chooser.h"
#include "prediction_schemes/tangent/mesh_prediction_scheme_geometric_tangent_shared.h"

namespace draco {

// Encodes 4-component tangents with the predictions of
// GeometricTangentPredictor, coded as GeometricTangentChooser finds
// smallest over the conventions of |settings|.kinds. It codes the residuals
// itself with UvResidualEncoder and hands Draco all-zero corrections.
// Prediction data, before the base class's transform data: the 8-byte
// bitstream guard (uv_bitstream_guard.h), the format version,
// GeometricTangentConfig, the TangentExceptions its flags ask for (the
// handedness's, then the copies'), the number of tokens (varint) and their
// residual streams.
// Needs integer positions, octahedral normals and integer texture
// coordinates as parents, and quantised tangents within the grid of
// |settings| (at most 21 bits); ComputeCorrectionValues() fails otherwise.
template <typename DataTypeT, class TransformT, class MeshDataT>
class MeshPredictionSchemeGeometricTangentEncoder
    : public MeshPredictionSchemeEncoder<DataTypeT, TransformT, MeshDataT> {
 public:
  using CorrType = typename MeshPredictionSchemeEncoder<DataTypeT, TransformT,
                                                        MeshDataT>::CorrType;
  MeshPredictionSchemeGeometricTangentEncoder(
      const PointAttribute *attribute, const TransformT &transform,
      const MeshDataT &mesh_data,
      const GeometricTangentEncoderSettings &settings)
      : MeshPredictionSchemeEncoder<DataTypeT, TransformT, MeshDataT>(
            attribute, transform, mesh_data),
        settings_(settings) {}

  bool ComputeCorrectionValues(
      const DataTypeT *in_data, CorrType *out_corr, int size,
      int num_components, const PointIndex *entry_to_point_id_map) override;

  bool EncodePredictionData(EncoderBuffer *buffer) override {
    if (!chooser_.has_best()) {
      return false;
    }
    EncodeUvBitstreamGuard(buffer);
    buffer->Encode(kGeometricTangentFormatVersion);
    chooser_.best_config().Encode(buffer);
    buffer->Encode(chooser_.best_streams().data(),
                   chooser_.best_streams().size());
    return MeshPredictionSchemeEncoder<DataTypeT, TransformT,
                                       MeshDataT>::EncodePredictionData(buffer);
  }

  PredictionSchemeMethod GetPredictionMethod() const override {
    return MESH_PREDICTION_GEOMETRIC_TANGENT;
  }
  // The corrections are all zero: Draco need not zig-zag them (nor the
  // decoder undo it).
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
  const GeometricTangentEncoderSettings settings_;
  GeometricTangentPredictor predictor_;
  TangentConnectivity connectivity_;
  GeometricTangentChooser chooser_;
};

template <typename DataTypeT, class TransformT, class MeshDataT>
bool MeshPredictionSchemeGeometricTangentEncoder<DataTypeT, TransformT,
                                                 MeshDataT>::
    ComputeCorrectionValues(const DataTypeT *in_data, CorrType *out_corr,
                            int size, int num_components,
                            const PointIndex * /* entry_to_point_id_map */) {
  const int num_entries =
      static_cast<int>(this->mesh_data().data_to_corner_map()->size());
  if (num_components != kTangentNumComponents ||
      size != num_entries * kTangentNumComponents ||
      !settings_.grid.IsValid() ||
      std::any_of(in_data, in_data + size, [&](DataTypeT value) {
        return value < 0 || value > settings_.grid.max_value;
      })) {
    return false;
  }
  const std::vector<int32_t> values(in_data, in_data + size);
  InitTangentConnectivity(this->mesh_data(), &connectivity_);
  if (!chooser_.Choose(connectivity_, settings_, &predictor_, values.data(),
                       num_entries)) {
    return false;
  }
  // The residuals travel in our own streams; Draco codes zeros.
  this->transform().Init(in_data, size, num_components);
  std::fill(out_corr, out_corr + size, CorrType(0));
  return true;
}

// The grid on which Draco's SequentialQuantizationAttributeEncoder will
// quantise the tangent attribute |att| (|att_id| in |options|): explicit
// origin and range, else computed from the values. Invalid (IsValid()
// false) where the attribute is not quantised to 1 to 21 bits, is not 4
// float components, or where the grid is finer than the scheme's fixed
// point holds (more than 2^20 steps per unit: tangents whose values span
// less than (2^bits - 1) / 2^20 on every axis, such as nearly constant
// ones), which the decoder would refuse.
inline TangentGrid GeometricTangentGrid(const PointAttribute &att,
                                        const EncoderOptions &options,
                                        int att_id) {
  TangentGrid grid;
  const int bits = options.GetAttributeInt(att_id, "quantization_bits", -1);
  if (bits < 1 || bits > 21 || att.num_components() != kTangentNumComponents ||
      att.data_type() != DT_FLOAT32) {
    return grid;
  }
  AttributeQuantizationTransform quantization;
  if (options.IsAttributeOptionSet(att_id, "quantization_origin") &&
      options.IsAttributeOptionSet(att_id, "quantization_range")) {
    float origin[kTangentNumComponents];
    options.GetAttributeVector(att_id, "quantization_origin",
                               kTangentNumComponents, origin);
    if (!quantization.SetParameters(
            bits, origin, kTangentNumComponents,
            options.GetAttributeFloat(att_id, "quantization_range", 1.f))) {
      return grid;
    }
  } else if (!quantization.ComputeParameters(att, bits)) {
    return grid;
  }
  // Draco's Quantizer: q = floor((v - min) * inverse_delta + 0.5) with the
  // float inverse_delta = max / range.
  const int32_t max_value = (1 << bits) - 1;
  const double inverse_delta =
      static_cast<float>(max_value) / quantization.range();
  constexpr double kFraction = 1 << TangentGrid::kFractionBits;
  // Beyond the int64 range (a tiny range) llround's result is unspecified:
  // such a grid is invalid anyway.
  const double scale = inverse_delta * kFraction;
  if (!(scale > 0 && scale <= static_cast<double>(TangentGrid::kMaxScale))) {
    return grid;
  }
  grid.max_value = max_value;
  grid.scale = std::llround(scale);
  for (int c = 0; c < kTangentNumComponents; ++c) {
    const double offset =
        -static_cast<double>(quantization.min_value(c)) * inverse_delta *
        kFraction;
    if (!(std::fabs(offset) <= static_cast<double>(TangentGrid::kMaxOffset))) {
      return TangentGrid();
    }
    grid.offset[c] = std::llround(offset);
  }
  return grid;
}

// The settings of the tangent attribute |att_id| from |encoder|'s options:
// the kinds the options layer asked for (geometric_tangent_settings.h), the
// octahedral bits of the first NORMAL attribute, and the grid that Draco's
// SequentialQuantizationAttributeEncoder will quantise with
// (GeometricTangentGrid()).
inline GeometricTangentEncoderSettings GetGeometricTangentEncoderSettings(
    const PointCloudEncoder &encoder, int att_id) {
  GeometricTangentEncoderSettings settings;
  const EncoderOptions &options = *encoder.options();
  const PointCloud &pc = *encoder.point_cloud();
  settings.kinds = GetGeometricTangentKinds(options, att_id);
  const int normal_id = pc.GetNamedAttributeId(GeometryAttribute::NORMAL);
  settings.normal_bits =
      normal_id < 0
          ? 0
          : options.GetAttributeInt(normal_id, "quantization_bits", -1);
  settings.grid = GeometricTangentGrid(*pc.attribute(att_id), options, att_id);
  return settings;
}

// Draco's factory for the scheme, like CreateMeshPredictionScheme() but
// handing the encoder the settings from the encoder options; null where it
// cannot work (no mesh connectivity).
template <typename DataTypeT, class TransformT>
std::unique_ptr<PredictionSchemeEncoder<DataTypeT, TransformT>>
CreateMeshPredictionSchemeGeometricTangentEncoder(
    int att_id, const PointCloudEncoder *encoder, const TransformT &transform) {
  if (encoder->GetGeometryType() != TRIANGULAR_MESH) {
    return nullptr;
  }
  const auto *const mesh_encoder = static_cast<const MeshEncoder *>(encoder);
  const PointAttribute *const att = encoder->point_cloud()->attribute(att_id);
  const CornerTable *const table = mesh_encoder->GetCornerTable();
  const MeshAttributeIndicesEncodingData *const encoding_data =
      mesh_encoder->GetAttributeEncodingData(att_id);
  if (table == nullptr || encoding_data == nullptr) {
    return nullptr;
  }
  const GeometricTangentEncoderSettings settings =
      GetGeometricTangentEncoderSettings(*encoder, att_id);
  const MeshAttributeCornerTable *const att_table =
      mesh_encoder->GetAttributeCornerTable(att_id);
  if (att_table != nullptr) {
    using MeshData = MeshPredictionSchemeData<MeshAttributeCornerTable>;
    MeshData data;
    data.Set(mesh_encoder->mesh(), att_table,
             &encoding_data->encoded_attribute_value_index_to_corner_map,
             &encoding_data->vertex_to_encoded_attribute_value_index_map);
    return std::make_unique<MeshPredictionSchemeGeometricTangentEncoder<
        DataTypeT, TransformT, MeshData>>(att, transform, data, settings);
  }
  using MeshData = MeshPredictionSchemeData<CornerTable>;
  MeshData data;
  data.Set(mesh_encoder->mesh(), table,
           &encoding_data->encoded_attribute_value_index_to_corner_map,
           &encoding_data->vertex_to_encoded_attribute_value_index_map);
  return std::make_unique<MeshPredictionSchemeGeometricTangentEncoder<
      DataTypeT, TransformT, MeshData>>(att, transform, data, settings);
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_TANGENT_MESH_PREDICTION_SCHEME_GEOMETRIC_TANGENT_ENCODER_H_
