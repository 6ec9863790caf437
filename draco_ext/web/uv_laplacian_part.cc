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
// The C interface of draco_decoder_laplacian.wasm, the web decoder's
// Laplacian part (loaded on demand by web/laplacian_on_demand.js): a
// standalone WebAssembly module with its own memory that exports malloc,
// free and draco_uv_laplacian_decode. The caller allocates the inputs and
// the output in this module's memory with malloc.
#include <emscripten/emscripten.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "prediction_schemes/laplacian/uv_laplacian_decode.h"

extern "C" {

// Decodes the Laplacian stream |stream| (|size| bytes, Draco bitstream
// version |bitstream_version|) of the texture mesh of |num_vertices| 3D
// positions (x, y, z each) and |num_faces| faces (three texture vertices
// each) into |uv| (u, v per texture vertex, frame units). Returns the
// frame's bits, or -1 for a stream the coder rejects, counts below zero or
// a face with a vertex out of range. The inputs are untrusted.
EMSCRIPTEN_KEEPALIVE int draco_uv_laplacian_decode(
    const double *positions, int num_vertices, const int *faces, int num_faces,
    const char *stream, int size, int bitstream_version, double *uv) {
  if (num_vertices < 0 || num_faces < 0 || size < 0 || bitstream_version < 0 ||
      bitstream_version > UINT16_MAX ||
      std::any_of(
          faces, faces + 3 * static_cast<int64_t>(num_faces),
          [num_vertices](int v) { return v < 0 || v >= num_vertices; })) {
    return -1;
  }
  draco::UvLaplacianMesh mesh;
  mesh.positions.resize(num_vertices);
  std::copy(positions, positions + 3 * static_cast<int64_t>(num_vertices),
            reinterpret_cast<double *>(mesh.positions.data()));
  mesh.faces.resize(num_faces);
  std::copy(faces, faces + 3 * static_cast<int64_t>(num_faces),
            reinterpret_cast<int *>(mesh.faces.data()));
  std::vector<double> values;
  int frame_bits;
  if (!draco::DecodeUvLaplacianValues(mesh, stream, size,
                                      static_cast<uint16_t>(bitstream_version),
                                      &values, &frame_bits)) {
    return -1;
  }
  std::copy(values.begin(), values.end(), uv);
  return frame_bits;
}

}  // extern "C"
