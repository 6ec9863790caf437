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
// The decoder side of uv_seam_edgebreaker.h.
#include "draco/compression/config/compression_shared.h"
#include "draco/compression/mesh/mesh_edgebreaker_decoder_impl.h"
#include "draco_ext/seams/mesh_edgebreaker_traversal_uv_seam_decoder.h"
#include "draco_ext/seams/uv_seam_edgebreaker.h"

namespace draco {

std::unique_ptr<MeshEdgebreakerDecoderImplInterface>
CreateUvSeamEdgebreakerDecoderImpl(int method) {
  if (method == MESH_EDGEBREAKER_STANDARD_CONTEXT_SEAMS_ENCODING) {
    return std::unique_ptr<MeshEdgebreakerDecoderImplInterface>(
        new MeshEdgebreakerDecoderImpl<
            MeshEdgebreakerTraversalStandardUvSeamDecoder>());
  }
  if (method == MESH_EDGEBREAKER_VALENCE_CONTEXT_SEAMS_ENCODING) {
    return std::unique_ptr<MeshEdgebreakerDecoderImplInterface>(
        new MeshEdgebreakerDecoderImpl<
            MeshEdgebreakerTraversalValenceUvSeamDecoder>());
  }
  return nullptr;
}

}  // namespace draco
