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
// Edgebreaker traversal decoders for the encoders of
// mesh_edgebreaker_traversal_uv_seam_encoder.h: Draco's traversal decoder
// for everything but the seams, which the crease-bit coder decodes in one
// pass over the corner table as soon as the connectivity is complete (the
// OnConnectivityDecoded() hook of patch 0007), in the order in which
// MeshEdgebreakerDecoderImpl then asks for them.
#ifndef DRACO_EXT_SEAMS_MESH_EDGEBREAKER_TRAVERSAL_UV_SEAM_DECODER_H_
#define DRACO_EXT_SEAMS_MESH_EDGEBREAKER_TRAVERSAL_UV_SEAM_DECODER_H_

#include <cstdint>
#include <vector>

#include "draco/compression/mesh/mesh_edgebreaker_traversal_decoder.h"
#include "draco/compression/mesh/mesh_edgebreaker_traversal_valence_decoder.h"
#include "draco/core/varint_decoding.h"
#include "draco/draco_features.h"
#include "draco_ext/seams/uv_seam_coder.h"

namespace draco {

// Draco's CornerTable seen as UvSeamContextCoder's table.
struct UvSeamDracoCornerTable {
  // kInvalidCornerIndex's value.
  static constexpr uint32_t kBoundary = 0xFFFFFFFFu;

  explicit UvSeamDracoCornerTable(const CornerTable *corner_table)
      : table(*corner_table), num_vertices(corner_table->num_vertices()) {}
  uint32_t num_corners() const { return table.num_corners(); }
  uint32_t Opposite(uint32_t corner) const {
    return table.Opposite(CornerIndex(corner)).value();
  }
  uint32_t Vertex(uint32_t corner) const {
    return table.Vertex(CornerIndex(corner)).value();
  }

  const CornerTable &table;
  const uint32_t num_vertices;
};

// |TraversalDecoderT| is MeshEdgebreakerTraversalDecoder or a class derived
// from it; MeshEdgebreakerDecoderImpl calls the methods below by name.
template <class TraversalDecoderT>
class MeshEdgebreakerTraversalUvSeamDecoder : public TraversalDecoderT {
 public:
  void Init(MeshEdgebreakerDecoderImplInterface *decoder) {
    decoder_impl_ = decoder;
    TraversalDecoderT::Init(decoder);
  }

  // The wrapped decoder reads no seams itself.
  void SetNumAttributeData(int num_data) {
    num_attribute_data_ = num_data;
    TraversalDecoderT::SetNumAttributeData(0);
  }

  // Reads the wrapped decoder's data and locates the seam bytes after it.
  bool Start(DecoderBuffer *out_buffer) {
    // The methods exist since bitstream 2.2 only.
    if (this->BitstreamVersion() < DRACO_BITSTREAM_VERSION(2, 2) ||
        !TraversalDecoderT::Start(out_buffer)) {
      return false;
    }
    uint32_t size;
    if (!DecodeVarint(&size, out_buffer) ||
        size > static_cast<uint64_t>(out_buffer->remaining_size())) {
      return false;
    }
    seam_data_ = reinterpret_cast<const uint8_t *>(out_buffer->data_head());
    seam_size_ = size;
    out_buffer->Advance(size);
    return true;
  }

  // Decodes all seams on the finished connectivity; false on corrupt data.
  bool OnConnectivityDecoded() {
    next_bit_ = 0;
    return DecodeUvSeams(
        UvSeamDracoCornerTable(decoder_impl_->GetCornerTable()),
        num_attribute_data_, seam_data_, seam_size_, &draco_order_bits_);
  }

  // Called in Draco's seam order, like the encoder's EncodeAttributeSeam().
  bool DecodeAttributeSeam(int /* attribute */) {
    return next_bit_ < draco_order_bits_.size() &&
           draco_order_bits_[next_bit_++] != 0;
  }

 private:
  const MeshEdgebreakerDecoderImplInterface *decoder_impl_ = nullptr;
  int num_attribute_data_ = 0;
  const uint8_t *seam_data_ = nullptr;
  size_t seam_size_ = 0;
  std::vector<uint8_t> draco_order_bits_;
  size_t next_bit_ = 0;
};

typedef MeshEdgebreakerTraversalUvSeamDecoder<MeshEdgebreakerTraversalDecoder>
    MeshEdgebreakerTraversalStandardUvSeamDecoder;
typedef MeshEdgebreakerTraversalUvSeamDecoder<
    MeshEdgebreakerTraversalValenceDecoder>
    MeshEdgebreakerTraversalValenceUvSeamDecoder;

}  // namespace draco

#endif  // DRACO_EXT_SEAMS_MESH_EDGEBREAKER_TRAVERSAL_UV_SEAM_DECODER_H_
