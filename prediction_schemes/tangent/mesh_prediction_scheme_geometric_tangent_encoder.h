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
#include "prediction_schemes/tangent/mesh_prediction_scheme_geometric_tangent_shared.h"

namespace draco {

// What the encoder needs besides the data: the conventions to try, the
// normals' octahedral bits and where Draco's quantisation puts a tangent.
struct GeometricTangentEncoderSettings {
  uint8_t kinds = kAllGeometricTangentKinds;
  int normal_bits = 0;
  TangentGrid grid;
};

// Encodes 4-component tangents with the predictions of
// GeometricTangentPredictor: tries every convention of |settings|.kinds,
// with per convention the handedness sign that most entries follow and the
// step-2 gain their first residuals call for (eq. (2)), and keeps the
// smallest residual streams. It codes the residuals itself with
// UvResidualEncoder and hands Draco all-zero corrections.
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
    if (!has_best_) {
      return false;
    }
    EncodeUvBitstreamGuard(buffer);
    buffer->Encode(kGeometricTangentFormatVersion);
    best_config_.Encode(buffer);
    buffer->Encode(best_streams_.data(), best_streams_.size());
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
  // The four ways of coding the handedness and the copies (bit 0 of the
  // index: the handedness as exceptions, bit 1: the copies as exceptions;
  // else as tokens). They differ only in the tokens they leave out, so one
  // pass over the entries codes all four.
  static constexpr int kNumExceptionChoices = 4;
  class Coder {
   public:
    explicit Coder(int expected_tokens) {
      for (Choice &choice : choices_) {
        choice.residuals.Reset(expected_tokens);
      }
    }
    bool Value(int context, int32_t predicted, int32_t sign,
               const int32_t *value) {
      for (Choice &choice : choices_) {
        choice.Add(context, sign * (*value - predicted));
      }
      return true;
    }
    bool Handedness(int entry, const std::array<int32_t, 2> &predicted,
                    const int32_t *w) {
      const int32_t symbol = HandednessSymbol(*w, predicted);
      if (symbol != 0) {
        handedness_exceptions_.Add(entry, symbol);
      }
      for (int i = 0; i < kNumExceptionChoices; ++i) {
        if ((i & 1) == 0) {
          choices_[i].Add(kTangentHandednessContext, symbol);
        }
      }
      return true;
    }
    bool Copy(int entry, const int32_t *source, const int32_t *v) {
      const bool exact = std::equal(v, v + kTangentNumComponents, source);
      if (!exact) {
        copy_exceptions_.Add(entry, 1);
      }
      for (int i = 0; i < kNumExceptionChoices; ++i) {
        if ((i & 2) != 0 && exact) {
          continue;
        }
        for (int c = 0; c < kTangentNumComponents; ++c) {
          choices_[i].Add(kTangentCopyContext, v[c] - source[c]);
        }
      }
      return true;
    }
    // The prediction-data streams of choice |i| (after the config).
    bool Encode(int i, EncoderBuffer *streams) const {
      if ((i & 1) != 0) {
        handedness_exceptions_.Encode(true, streams);
      }
      if ((i & 2) != 0) {
        copy_exceptions_.Encode(false, streams);
      }
      EncodeVarint<uint32_t>(choices_[i].num_tokens, streams);
      return choices_[i].residuals.Encode(streams);
    }

   private:
    struct Choice {
      void Add(int context, int32_t residual) {
        residuals.Add(context, residual);
        ++num_tokens;
      }
      UvResidualEncoder residuals{kTangentNumContexts};
      uint32_t num_tokens = 0;
    };
    std::array<Choice, kNumExceptionChoices> choices_;
    TangentExceptions handedness_exceptions_, copy_exceptions_;
  };
  // Records nothing: for the pass that only collects neighbour sums.
  struct NullCoder {
    bool Value(int, int32_t, int32_t, const int32_t *) { return true; }
    bool Handedness(int, const std::array<int32_t, 2> &, const int32_t *) {
      return true;
    }
    bool Copy(int, const int32_t *, const int32_t *) { return true; }
  };

  // The handedness sign and step-2 gain that suit |predictions| of |values|.
  TangentCodingParameters FitParameters(
      const std::vector<GeometricTangentPrediction> &predictions,
      const int32_t *values) const;
  // The neighbour class thresholds that split |sums| (-1: none) into
  // thirds.
  static std::array<uint8_t, 2> NeighbourThresholds(
      const std::vector<int8_t> &sums);
  // Codes |values| with |config| (and the neighbour thresholds its first
  // pass finds) and keeps the streams if they are the smallest so far.
  bool TryConfig(const GeometricTangentConfig &config,
                 const std::vector<GeometricTangentPrediction> &predictions,
                 const int32_t *values);

  const GeometricTangentEncoderSettings settings_;
  GeometricTangentPredictor predictor_;
  TangentConnectivity connectivity_;
  GeometricTangentConfig best_config_;
  std::vector<char> best_streams_;
  bool has_best_ = false;
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
  std::vector<GeometricTangentPrediction> predictions(num_entries);
  InitTangentConnectivity(this->mesh_data(), &connectivity_);
  has_best_ = false;
  for (int k = 0; k < kNumGeometricTangentKinds; ++k) {
    const auto kind = static_cast<GeometricTangentKind>(k);
    if ((settings_.kinds & GeometricTangentKindBit(kind)) == 0) {
      continue;
    }
    predictor_.ComputeSums(connectivity_, kind, settings_.normal_bits);
    for (int entry = 0; entry < num_entries; ++entry) {
      predictions[entry] = predictor_.Predict(connectivity_, entry);
    }
    GeometricTangentConfig config;
    config.kind = kind;
    config.normal_bits = settings_.normal_bits;
    config.coding = FitParameters(predictions, values.data());
    if (!TryConfig(config, predictions, values.data())) {
      return false;
    }
  }
  // The residuals travel in our own streams; Draco codes zeros.
  this->transform().Init(in_data, size, num_components);
  std::fill(out_corr, out_corr + size, CorrType(0));
  return has_best_;
}

// The handedness follows the majority; the gain is eq. (2),
// 256 s^2 / (s^2 + 1/12) with s^2 the variance of the turn that b1's coded
// value shows beyond the 1/12 its rounding adds, in integer arithmetic so
// that every build chooses the same.
template <typename DataTypeT, class TransformT, class MeshDataT>
TangentCodingParameters
MeshPredictionSchemeGeometricTangentEncoder<DataTypeT, TransformT, MeshDataT>::
    FitParameters(const std::vector<GeometricTangentPrediction> &predictions,
                  const int32_t *values) const {
  TangentCodingParameters params;
  params.grid = settings_.grid;
  int64_t agree = 0, disagree = 0;
  uint64_t sum_squares = 0, count = 0;
  TangentComponentPredictor components(params);
  for (size_t entry = 0; entry < predictions.size(); ++entry) {
    const GeometricTangentPrediction &prediction = predictions[entry];
    if (!prediction.valid) {
      continue;
    }
    const int32_t *const v = values + kTangentNumComponents * entry;
    const bool positive = params.grid.UnitComponent(3, v[3]) > 0;
    (positive == (prediction.handedness > 0) ? agree : disagree) += 1;
    components.Begin(prediction);
    const int b1 = components.Axis(0);
    // In units of 2^-8 of a step, capped at 256 steps.
    const int64_t moved = std::clamp<int64_t>(
        RoundedShiftHalfUp((int64_t{v[b1]} << TangentGrid::kFractionBits) -
                         components.Coordinate(b1),
                     8),
        -(1 << 16), 1 << 16);
    sum_squares += static_cast<uint64_t>(moved * moved);
    ++count;
  }
  params.flip_handedness = disagree > agree;
  constexpr uint64_t kRoundingVariance = (1u << 16) / 12;
  const uint64_t variance = count > 0 ? sum_squares / count : 0;
  const uint64_t turn =
      variance > kRoundingVariance ? variance - kRoundingVariance : 0;
  params.shift_gain =
      static_cast<int32_t>(256 * turn / (turn + kRoundingVariance));
  return params;
}

template <typename DataTypeT, class TransformT, class MeshDataT>
std::array<uint8_t, 2> MeshPredictionSchemeGeometricTangentEncoder<
    DataTypeT, TransformT, MeshDataT>::NeighbourThresholds(const std::vector<
                                                           int8_t> &sums) {
  std::array<uint64_t, 16> histogram = {};
  uint64_t total = 0;
  for (const int8_t sum : sums) {
    if (sum >= 0) {
      ++histogram[std::min<int>(sum, 15)];
      ++total;
    }
  }
  std::array<uint8_t, 2> thresholds = {0, 2};
  uint64_t seen = 0;
  int found = 0;
  for (int s = 0; s < 16 && found < 2; ++s) {
    seen += histogram[s];
    // The smallest sums with at least a third and two thirds at or below.
    while (found < 2 && 3 * seen >= (found + 1) * total) {
      thresholds[found++] = static_cast<uint8_t>(s);
    }
  }
  return thresholds;
}

template <typename DataTypeT, class TransformT, class MeshDataT>
bool MeshPredictionSchemeGeometricTangentEncoder<DataTypeT, TransformT,
                                                 MeshDataT>::
    TryConfig(const GeometricTangentConfig &config,
              const std::vector<GeometricTangentPrediction> &predictions,
              const int32_t *values) {
  const auto predict = [&](int entry) { return predictions[entry]; };
  // The encoder's coders only read the values.
  int32_t *const read_only = const_cast<int32_t *>(values);
  // A first pass for the neighbour sums, whose terciles become the
  // thresholds of the neighbour classes.
  GeometricTangentConfig tuned = config;
  std::vector<int8_t> sums(predictions.size(), -1);
  NullCoder null_coder;
  if (!CodeGeometricTangents(connectivity_, config.coding, predict,
                             &null_coder, read_only, &sums)) {
    return false;
  }
  tuned.coding.neighbour_thresholds = NeighbourThresholds(sums);
  // Then the handedness and the copies as tokens or as exceptions,
  // whichever is smaller.
  Coder coder(static_cast<int>(predictions.size()) * kTangentNumComponents);
  if (!CodeGeometricTangents(connectivity_, tuned.coding, predict, &coder,
                             read_only)) {
    return false;
  }
  for (int i = 0; i < kNumExceptionChoices; ++i) {
    tuned.handedness_exceptions = (i & 1) != 0;
    tuned.copy_exceptions = (i & 2) != 0;
    EncoderBuffer streams;
    if (!coder.Encode(i, &streams)) {
      return false;
    }
    if (!has_best_ || streams.size() < best_streams_.size()) {
      best_streams_.assign(streams.data(), streams.data() + streams.size());
      best_config_ = tuned;
      has_best_ = true;
    }
  }
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
