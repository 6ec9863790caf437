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
// The error of decoded texture coordinates as [Váša & Brunnett 2014]
// measure it: RMSE over texture vertices, eq. (9), in UV units. Decoding
// reorders faces and points, so decoded faces are matched to the original
// ones by their quantized positions. draco_uv_eval's rmse column and the
// encoder's error target (-uv_rmse, options/uv_error_target.h) both use it.
#ifndef DRACO_EXT_COMMON_UV_RMSE_H_
#define DRACO_EXT_COMMON_UV_RMSE_H_

#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"

namespace draco {

// RMSE (eq. 9) of |decoded|'s texture coordinates against |original|'s,
// matching faces by their positions quantized with |qp| bits. With several
// UV sets, a texture vertex's squared error sums over all of them. Fails
// when a decoded face has no original counterpart (e.g. |qp| coarser than
// the positions were coded with).
StatusOr<double> UvRmse(const Mesh &original, const Mesh &decoded, int qp);

// The same for the one UV set |tex_coord_index| (the index among the
// TEX_COORD attributes, the same in both meshes).
StatusOr<double> UvRmseOf(const Mesh &original, const Mesh &decoded, int qp,
                          int tex_coord_index);

}  // namespace draco

#endif  // DRACO_EXT_COMMON_UV_RMSE_H_
