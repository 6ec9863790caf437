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
// The decoder's entry to the Laplacian texture coordinate coder
// (uv_laplacian_coder.h) in plain arrays, without Eigen. Two builds define
// it: uv_laplacian_coder.cc solves in the same module (native builds, the
// web encoder and the single-module web decoder); in the web decoder whose
// Laplacian part loads on demand, draco_ext/web/uv_laplacian_on_demand.cc
// hands the arrays to that part (draco_ext/web/uv_laplacian_part.cc)
// through JavaScript.
#ifndef PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_DECODE_H_
#define PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_DECODE_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "prediction_schemes/laplacian/uv_laplacian_mesh.h"

namespace draco {

// Decodes the coder's stream |data| (|size| bytes, written under Draco
// bitstream version |bitstream_version|) for |mesh|: |uv| receives u, v of
// every texture vertex in frame units (not rounded), |frame_bits| the
// frame's bits. False on anything DecodeUvLaplacian() rejects, and in the
// on-demand build also when the Laplacian part cannot be loaded or runs out
// of memory.
bool DecodeUvLaplacianValues(const UvLaplacianMesh &mesh, const char *data,
                             size_t size, uint16_t bitstream_version,
                             std::vector<double> *uv, int *frame_bits);

}  // namespace draco

#endif  // PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_DECODE_H_
