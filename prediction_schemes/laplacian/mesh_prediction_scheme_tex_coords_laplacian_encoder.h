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
// Encoder of MESH_PREDICTION_TEX_COORDS_LAPLACIAN, the lossy Laplacian
// texture coordinate coder of [Váša & Brunnett 2014] L. Váša, G. Brunnett:
// Efficient encoding of texture coordinates guided by mesh geometry.
// CGF 33(5), section 5.
#ifndef PREDICTION_SCHEMES_LAPLACIAN_MESH_PREDICTION_SCHEME_TEX_COORDS_LAPLACIAN_ENCODER_H_
#define PREDICTION_SCHEMES_LAPLACIAN_MESH_PREDICTION_SCHEME_TEX_COORDS_LAPLACIAN_ENCODER_H_

#include <algorithm>
#include <memory>
#include <vector>

#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_data.h"
#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_encoder.h"
#include "draco/compression/mesh/mesh_encoder.h"
#include "draco/core/varint_encoding.h"
#include "draco_ext/common/uv_bitstream_guard.h"
#include "prediction_schemes/laplacian/mesh_prediction_scheme_tex_coords_laplacian_shared.h"
#include "prediction_schemes/laplacian/uv_laplacian_coder.h"
#include "prediction_schemes/laplacian/uv_laplacian_settings.h"

namespace draco {

// Codes a 2-component texture coordinate attribute with the Laplacian coder
// (uv_laplacian_coder.h): lossy, with the decoded values off the user's
// quantisation grid.
//
// How a lossy coder fits Draco's lossless integer pipeline: Draco quantises
// the attribute before any prediction scheme sees it and dequantises the
// integers the decoder's scheme returns. For this scheme the quantisation
// only frames the data: ConfigureUvCompression() (-uv_pred laplacian_*)
// sets the attribute's quantisation to a frame 8 bits finer than the -qt the
// user asked for (at most 30 bits) and passes -qt on as the step bits of
// the scheme's settings (uv_laplacian_settings.h). The scheme reads the
// frame integers (the original coordinates within 2^-(qt+9) of the
// range), quantises residuals and anchors with the -qt step,
// range / (2^qt - 1), and writes the whole result in its prediction data; Draco codes all-zero corrections,
// a few bytes. The decoder rounds its least-squares solution to the frame,
// 256 times finer than the step, so the decoded floats carry the solver's
// result rather than a -qt grid, at no cost in bits.
//
// Prediction data: the 8-byte bitstream guard (uv_bitstream_guard.h), the
// format version byte, a varint length and the coder's stream. No data of
// Draco's prediction transform follows: nothing uses it.
//
// Fails (ComputeCorrectionValues() returns false) on anything but two
// components, unsupported options, or a system even the Tutte fallback
// cannot solve. Created by CreateMeshPredictionSchemeTexCoordsLaplacianEncoder
// (below), which hands it the encoder options.
template <typename DataTypeT, class TransformT, class MeshDataT>
class MeshPredictionSchemeTexCoordsLaplacianEncoder
    : public MeshPredictionSchemeEncoder<DataTypeT, TransformT, MeshDataT> {
 public:
  using CorrType = typename MeshPredictionSchemeEncoder<DataTypeT, TransformT,
                                                        MeshDataT>::CorrType;
  MeshPredictionSchemeTexCoordsLaplacianEncoder(
      const PointAttribute *attribute, const TransformT &transform,
      const MeshDataT &mesh_data, const UvLaplacianEncoderOptions &options)
      : MeshPredictionSchemeEncoder<DataTypeT, TransformT, MeshDataT>(
            attribute, transform, mesh_data),
        options_(options) {}

  bool ComputeCorrectionValues(
      const DataTypeT *in_data, CorrType *out_corr, int size,
      int num_components, const PointIndex *entry_to_point_id_map) override {
    const int num_entries =
        static_cast<int>(this->mesh_data().data_to_corner_map()->size());
    if (num_components != 2 || size != 2 * num_entries) {
      return false;
    }
    const UvLaplacianMesh mesh = BuildUvLaplacianMesh(
        this->mesh_data(), *positions_, entry_to_point_id_map);
    UvValues uv(num_entries, 2);
    for (int entry = 0; entry < num_entries; ++entry) {
      uv(entry, 0) = static_cast<double>(in_data[2 * entry]);
      uv(entry, 1) = static_cast<double>(in_data[2 * entry + 1]);
    }
    stream_.Clear();
    if (!EncodeUvLaplacian(mesh, uv, options_, &stream_)) {
      return false;
    }
    // The values travel in the prediction data; Draco codes zeros.
    std::fill(out_corr, out_corr + size, CorrType(0));
    return true;
  }

  bool EncodePredictionData(EncoderBuffer *buffer) override {
    EncodeUvBitstreamGuard(buffer);
    buffer->Encode(kTexCoordsLaplacianFormatVersion);
    EncodeVarint(static_cast<uint64_t>(stream_.size()), buffer);
    return buffer->Encode(stream_.data(), stream_.size());
  }

  PredictionSchemeMethod GetPredictionMethod() const override {
    return MESH_PREDICTION_TEX_COORDS_LAPLACIAN;
  }

  bool IsInitialized() const override {
    return positions_ != nullptr && this->mesh_data().IsInitialized();
  }

  int GetNumParentAttributes() const override { return 1; }

  GeometryAttribute::Type GetParentAttributeType(int i) const override {
    DRACO_DCHECK_EQ(i, 0);
    (void)i;
    return GeometryAttribute::POSITION;
  }

  bool SetParentAttribute(const PointAttribute *att) override {
    if (!IsLaplacianPositionAttribute(att)) {
      return false;
    }
    positions_ = att;
    return true;
  }

 private:
  UvLaplacianEncoderOptions options_;
  const PointAttribute *positions_ = nullptr;
  EncoderBuffer stream_;
};

// Creates the encoder for attribute |att_id| of |encoder|'s mesh, like
// CreateMeshPredictionScheme() does for Draco's own schemes, but with the
// encoder options. Null when the encoder has no mesh connectivity.
template <typename DataTypeT, class TransformT>
std::unique_ptr<PredictionSchemeEncoder<DataTypeT, TransformT>>
CreateMeshPredictionSchemeTexCoordsLaplacianEncoder(
    int att_id, const PointCloudEncoder *encoder, const TransformT &transform) {
  if (encoder->GetGeometryType() != TRIANGULAR_MESH) {
    return nullptr;
  }
  const MeshEncoder *const mesh_encoder =
      static_cast<const MeshEncoder *>(encoder);
  const PointAttribute *const att = encoder->point_cloud()->attribute(att_id);
  const CornerTable *const table = mesh_encoder->GetCornerTable();
  const MeshAttributeIndicesEncodingData *const encoding_data =
      mesh_encoder->GetAttributeEncodingData(att_id);
  if (table == nullptr || encoding_data == nullptr) {
    return nullptr;
  }
  const UvLaplacianEncoderOptions options =
      GetUvLaplacianSettings(*encoder->options(), att_id);
  const MeshAttributeCornerTable *const att_table =
      mesh_encoder->GetAttributeCornerTable(att_id);
  if (att_table != nullptr) {
    typedef MeshPredictionSchemeData<MeshAttributeCornerTable> MeshData;
    MeshData data;
    data.Set(mesh_encoder->mesh(), att_table,
             &encoding_data->encoded_attribute_value_index_to_corner_map,
             &encoding_data->vertex_to_encoded_attribute_value_index_map);
    return std::unique_ptr<PredictionSchemeEncoder<DataTypeT, TransformT>>(
        new MeshPredictionSchemeTexCoordsLaplacianEncoder<DataTypeT, TransformT,
                                                          MeshData>(
            att, transform, data, options));
  }
  typedef MeshPredictionSchemeData<CornerTable> MeshData;
  MeshData data;
  data.Set(mesh_encoder->mesh(), table,
           &encoding_data->encoded_attribute_value_index_to_corner_map,
           &encoding_data->vertex_to_encoded_attribute_value_index_map);
  return std::unique_ptr<PredictionSchemeEncoder<DataTypeT, TransformT>>(
      new MeshPredictionSchemeTexCoordsLaplacianEncoder<DataTypeT, TransformT,
                                                        MeshData>(
          att, transform, data, options));
}

}  // namespace draco

#endif  // PREDICTION_SCHEMES_LAPLACIAN_MESH_PREDICTION_SCHEME_TEX_COORDS_LAPLACIAN_ENCODER_H_
