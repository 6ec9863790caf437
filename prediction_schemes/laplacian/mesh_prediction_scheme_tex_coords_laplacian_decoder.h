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
// Decoder of MESH_PREDICTION_TEX_COORDS_LAPLACIAN, the lossy Laplacian
// texture coordinate coder of [Váša & Brunnett 2014] L. Váša, G. Brunnett:
// Efficient encoding of texture coordinates guided by mesh geometry.
// CGF 33(5), section 5.
#ifndef PREDICTION_SCHEMES_LAPLACIAN_MESH_PREDICTION_SCHEME_TEX_COORDS_LAPLACIAN_DECODER_H_
#define PREDICTION_SCHEMES_LAPLACIAN_MESH_PREDICTION_SCHEME_TEX_COORDS_LAPLACIAN_DECODER_H_

#include <algorithm>
#include <cmath>
#include <vector>

#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_decoder.h"
#include "draco/core/varint_decoding.h"
#include "draco_ext/common/uv_bitstream_guard.h"
#include "prediction_schemes/laplacian/mesh_prediction_scheme_tex_coords_laplacian_shared.h"
#include "prediction_schemes/laplacian/uv_laplacian_decode.h"

namespace draco {

// Decodes texture coordinates written by
// MeshPredictionSchemeTexCoordsLaplacianEncoder (see there for the frame):
// solves the coder's least-squares system once and returns its solution
// rounded to the frame and clamped to the frame's range, for Draco to
// dequantise.
//
// Treats its input as hostile: a wrong guard or version, non-zero Draco
// corrections, a stream shorter than its stated length, anything the coder
// rejects (uv_laplacian_coder.h) or anything but 2 components fail. The
// solution is deterministic on one build, not bit-identical across
// platforms; nothing is predicted from it.
template <typename DataTypeT, class TransformT, class MeshDataT>
class MeshPredictionSchemeTexCoordsLaplacianDecoder
    : public MeshPredictionSchemeDecoder<DataTypeT, TransformT, MeshDataT> {
 public:
  using CorrType = typename MeshPredictionSchemeDecoder<DataTypeT, TransformT,
                                                        MeshDataT>::CorrType;
  MeshPredictionSchemeTexCoordsLaplacianDecoder(const PointAttribute *attribute,
                                                const TransformT &transform,
                                                const MeshDataT &mesh_data)
      : MeshPredictionSchemeDecoder<DataTypeT, TransformT, MeshDataT>(
            attribute, transform, mesh_data) {}

  bool ComputeOriginalValues(const CorrType *in_corr, DataTypeT *out_data,
                             int size, int num_components,
                             const PointIndex *entry_to_point_id_map) override {
    const int num_entries =
        static_cast<int>(this->mesh_data().data_to_corner_map()->size());
    if (num_components != 2 || size != 2 * num_entries ||
        std::any_of(in_corr, in_corr + size,
                    [](CorrType c) { return c != CorrType(0); })) {
      return false;
    }
    const UvLaplacianMesh mesh = BuildUvLaplacianMesh(
        this->mesh_data(), *positions_, entry_to_point_id_map);
    std::vector<double> uv;
    int frame_bits;
    if (!DecodeUvLaplacianValues(mesh, stream_.data(), stream_.size(),
                                 bitstream_version_, &uv, &frame_bits)) {
      return false;
    }
    const double max_value =
        static_cast<double>((int64_t{1} << frame_bits) - 1);
    for (int i = 0; i < size; ++i) {
      const double value =
          std::max(0.0, std::min(max_value, std::round(uv[i])));
      out_data[i] = static_cast<DataTypeT>(value);
    }
    return true;
  }

  bool DecodePredictionData(DecoderBuffer *buffer) override {
    uint8_t version;
    uint64_t length;
    if (!DecodeUvBitstreamGuard(buffer) || !buffer->Decode(&version) ||
        version != kTexCoordsLaplacianFormatVersion ||
        !DecodeVarint(&length, buffer) || length == 0 ||
        length > static_cast<uint64_t>(buffer->remaining_size())) {
      return false;  // A stream holds at least its header.
    }
    stream_.resize(length);
    bitstream_version_ = buffer->bitstream_version();
    return buffer->Decode(stream_.data(), length);
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
  const PointAttribute *positions_ = nullptr;
  std::vector<char> stream_;
  uint16_t bitstream_version_ = 0;
};

}  // namespace draco

#endif  // PREDICTION_SCHEMES_LAPLACIAN_MESH_PREDICTION_SCHEME_TEX_COORDS_LAPLACIAN_DECODER_H_
