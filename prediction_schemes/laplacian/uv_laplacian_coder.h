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
// Lossy Laplacian coding of texture coordinates, [Váša & Brunnett 2014]
// L. Váša, G. Brunnett: Efficient encoding of texture coordinates guided by
// mesh geometry. CGF 33(5), section 5:
//  1. L: a Laplacian of the texture connectivity with weights from the 3D
//     mesh (uv_laplacian_operator.h), rows scaled to diagonal -1.
//  2. Anchors: one or two per chart (uv_laplacian_operator.h: UvCharts) so
//     that the system is regular, plus K chosen greedily by the largest
//     reconstruction error (or at random, for the paper's fig. 9); K is
//     given, or UvDefaultExtraAnchors() of the mesh.
//  3. r = L u is quantised uniformly with the step 2^frame / 2^step_bits;
//     residuals and anchors are entropy coded with Draco's rANS coder.
//  4. The decoder solves the least-squares system of L and the anchor rows
//     (uv_laplacian_system.h) once.
//
// Beyond the paper, the encoder quantises r with error diffusion: the
// rounding error of each row is added to the not yet quantised rows of its
// neighbours, so that the quantisation error has little low-frequency
// content, which the inverse Laplacian would amplify most (about 20% lower
// RMSE at the same rate on the corpus). The decoder is unaffected.
//
// Greedy anchors reuse one factorisation: each round adds the round's
// anchors by rank-one updates of the Cholesky factor and solves once. Rounds
// grow geometrically (1, 2, 4, ... anchors); a round takes the vertices
// with the largest errors that are local maxima of the error over their
// two-ring, so that one round does not spend two anchors on one bump of
// the error.
//
// Stream (after the caller's header): uint8 operator kind, uint8 step bits,
// uint8 frame bits; varint K and the K extra anchors as ascending texture
// vertex deltas (varints); the quantised anchor values as deltas from the
// previous anchor (UvResidualEncoder; contexts: a chart's first anchor, its
// second one, the extra anchors); the quantised residuals
// of every non-empty row, u before v per texture vertex (UvResidualEncoder,
// contexts from the boundary and the already decoded neighbours).
#ifndef PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_CODER_H_
#define PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_CODER_H_

#include <cstdint>

#include "draco/core/decoder_buffer.h"
#include "draco/core/encoder_buffer.h"
#include "prediction_schemes/laplacian/uv_laplacian_operator.h"
#include "prediction_schemes/laplacian/uv_laplacian_settings.h"

namespace draco {

// Caps the factor of the least-squares system of |num_vertices| texture
// vertices (entries, 8 bytes each): linear in the mesh, at most 2^28, so
// that hostile connectivity fails instead of exhausting memory. Mesh
// Laplacians under nested dissection need far less (O(n log n) with a small
// constant).
int64_t UvLaplacianMaxFactorEntries(int num_vertices);

// The decode work of |mesh|, from the ordering the decoder computes (the
// same code on the same texture graph; a graph whose vertices are numbered
// differently, e.g. before the encoder's traversal, may order a little
// differently). False when the decoder would refuse the system.
bool ComputeUvLaplacianDecodeWork(const UvLaplacianMesh &mesh,
                                  UvLaplacianDecodeWork *work);

// Encodes |uv| (one row per texture vertex of |mesh|, in frame units).
// |reconstruction|, if given, receives what the decoder will reconstruct
// (up to rounding). Falls back to the Tutte Laplacian, and says so in the
// stream, when the requested operator gives a singular system. False when
// the options are out of range or even the Tutte system cannot be solved.
bool EncodeUvLaplacian(const UvLaplacianMesh &mesh, const UvValues &uv,
                       const UvLaplacianEncoderOptions &options,
                       EncoderBuffer *buffer,
                       UvValues *reconstruction = nullptr);

// Decodes texture coordinates (frame units, not rounded) for |mesh| and the
// frame's bits. False on truncated, inconsistent or out-of-range data, or a
// singular system. |buffer| needs Draco's bitstream version (2.0 or later)
// for its symbol coding.
bool DecodeUvLaplacian(const UvLaplacianMesh &mesh, DecoderBuffer *buffer,
                       UvValues *uv, int *frame_bits);

}  // namespace draco

#endif  // PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_CODER_H_
