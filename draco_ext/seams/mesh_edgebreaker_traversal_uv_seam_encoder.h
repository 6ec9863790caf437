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
// Edgebreaker traversal encoders that code attribute seams with draco-uv's
// crease-bit coder (uv_seam_coder.h) instead of Draco's static bit streams.
// Everything else (symbols, start faces, valence contexts) is the wrapped
// Draco traversal encoder's, unchanged.
#ifndef DRACO_EXT_SEAMS_MESH_EDGEBREAKER_TRAVERSAL_UV_SEAM_ENCODER_H_
#define DRACO_EXT_SEAMS_MESH_EDGEBREAKER_TRAVERSAL_UV_SEAM_ENCODER_H_

#include <cstdint>
#include <vector>

#include "draco/compression/mesh/mesh_edgebreaker_traversal_encoder.h"
#include "draco/compression/mesh/mesh_edgebreaker_traversal_valence_encoder.h"
#include "draco/core/macros.h"
#include "draco/core/varint_encoding.h"
#include "draco_ext/seams/uv_seam_coder.h"
#include "draco_ext/seams/uv_seam_edgebreaker.h"

namespace draco {

// |TraversalEncoderT| is MeshEdgebreakerTraversalEncoder or a class derived
// from it. MeshEdgebreakerEncoderImpl calls the methods below by name, so
// they replace the wrapped encoder's.
template <class TraversalEncoderT>
class MeshEdgebreakerTraversalUvSeamEncoder : public TraversalEncoderT {
 public:
  // The wrapped encoder codes no seams itself.
  void SetNumAttributeData(int num_data) {
    num_attribute_data_ = num_data;
    TraversalEncoderT::SetNumAttributeData(0);
  }

  // Called in Draco's seam order (see uv_seam_coder.h), every attribute
  // for one edge before the next edge.
  void EncodeAttributeSeam(int /* attribute */, bool is_seam) {
    draco_order_bits_.push_back(is_seam);
  }

  // Writes the wrapped encoder's data, then varint(n) and the n bytes of
  // the crease-bit coder.
  void Done() {
    TraversalEncoderT::Done();
    std::vector<uint8_t> bytes;
    if (!EncodeSeams(&bytes)) {
      // Cannot happen with Draco's encoder; a lone zero byte makes every
      // decoder reject the file rather than decode wrong seams.
      DRACO_DCHECK(false);
      bytes.assign(1, 0);
    }
    EncodeVarint(static_cast<uint32_t>(bytes.size()), this->GetOutputBuffer());
    this->GetOutputBuffer()->Encode(bytes.data(), bytes.size());
  }

 private:
  bool EncodeSeams(std::vector<uint8_t> *bytes) const {
    const MeshEdgebreakerEncoderImplInterface *const impl =
        this->encoder_impl();
    UvSeamCornerTable table;
    return CornerTableInDecoderOrder(*impl->GetCornerTable(),
                                     impl->GetProcessedConnectivityCorners(),
                                     &table) &&
           EncodeUvSeams(table, num_attribute_data_, draco_order_bits_, bytes);
  }

  int num_attribute_data_ = 0;
  std::vector<uint8_t> draco_order_bits_;
};

typedef MeshEdgebreakerTraversalUvSeamEncoder<MeshEdgebreakerTraversalEncoder>
    MeshEdgebreakerTraversalStandardUvSeamEncoder;
typedef MeshEdgebreakerTraversalUvSeamEncoder<
    MeshEdgebreakerTraversalValenceEncoder>
    MeshEdgebreakerTraversalValenceUvSeamEncoder;

}  // namespace draco

#endif  // DRACO_EXT_SEAMS_MESH_EDGEBREAKER_TRAVERSAL_UV_SEAM_ENCODER_H_
