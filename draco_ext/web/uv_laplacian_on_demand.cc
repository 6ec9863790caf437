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
// DecodeUvLaplacianValues() of the web decoder whose Laplacian part loads on
// demand (CMake option DRACO_UV_LAPLACIAN_ON_DEMAND): the solver is not in
// this module; web/laplacian_on_demand.js loads draco_decoder_laplacian.wasm
// (built from uv_laplacian_part.cc), copies the mesh and the stream into its
// memory, runs it and copies the texture coordinates back.
#include <emscripten/emscripten.h>

#include "prediction_schemes/laplacian/uv_laplacian_decode.h"

// Returns the frame bits, or -1 when the part rejects the stream or cannot
// be loaded (it then keeps the reason for the decoder's status).
EM_JS(int, draco_uv_decode_laplacian,
      (const double *positions, int num_vertices, const int *faces,
       int num_faces, const char *stream, int size, int bitstream_version,
       double *uv),
      {
        return dracoUvDecodeLaplacian(positions, num_vertices, faces, num_faces,
                                      stream, size, bitstream_version, uv);
      });

namespace draco {

bool DecodeUvLaplacianValues(const UvLaplacianMesh &mesh, const char *data,
                             size_t size, uint16_t bitstream_version,
                             std::vector<double> *uv, int *frame_bits) {
  uv->resize(2 * mesh.positions.size());
  const int bits = draco_uv_decode_laplacian(
      reinterpret_cast<const double *>(mesh.positions.data()),
      mesh.num_vertices(), reinterpret_cast<const int *>(mesh.faces.data()),
      static_cast<int>(mesh.faces.size()), data, static_cast<int>(size),
      bitstream_version, uv->data());
  if (bits < 0) {
    return false;
  }
  *frame_bits = bits;
  return true;
}

}  // namespace draco
