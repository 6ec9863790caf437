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
// Settings of the lossy Laplacian texture coordinate scheme
// (MESH_PREDICTION_TEX_COORDS_LAPLACIAN, section 5 of [Váša & Brunnett
// 2014]) and their limits, in one place: ConfigureUvCompression() writes
// them to Draco's encoder options with SetUvLaplacianSettings(), and the
// scheme's encoder, which Draco's factory hands only those options, reads
// them back with GetUvLaplacianSettings(). Light on purpose: the options
// layer includes it in lossless-only builds too.
#ifndef PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_SETTINGS_H_
#define PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_SETTINGS_H_

#include <cstdint>

#include "draco/compression/config/encoder_options.h"

namespace draco {

enum class UvLaplacianKind : uint8_t {
  kTutte = 0,
  kCotangent = 1,
  kMeanValue = 2,
};
constexpr int kNumUvLaplacianKinds = 3;

enum class UvAnchorSelection : uint8_t { kGreedy = 0, kRandom = 1 };

// Largest supported step bits (-qt).
constexpr int kUvLaplacianMaxStepBits = 20;
// Largest supported frame bits (Draco's quantisation limit).
constexpr int kUvLaplacianMaxFrameBits = 30;
// The frame Draco quantises to is this many bits finer than the step.
constexpr int kUvLaplacianFrameExtraBits = 8;
// The most extra anchors -uv_anchors accepts.
constexpr int kUvLaplacianMaxExtraAnchors = 1 << 24;
// UvLaplacianEncoderOptions::extra_anchors without -uv_anchors: the encoder
// places UvDefaultExtraAnchors() of the mesh.
constexpr int kUvLaplacianDefaultExtraAnchors = -1;

// The extra anchors placed without -uv_anchors on |num_texture_vertices|
// texture vertices of which |num_boundary_vertices| lie on the boundary of
// the texture connectivity (UvTextureGraph()): ceil(0.65 % of the vertices
// + 6 % of the boundary vertices), at most kUvLaplacianMaxExtraAnchors.
// The drift the anchors remove grows with the interior (the inverse
// Laplacian accumulates the residuals' quantisation error) and with the
// boundary, whose rows leave each chart's scale and rotation loose, so
// atlases of many small charts get 2.5-6 % of their vertices, one smooth
// chart about 0.8 %. Measured basis (laplacian_mv, bpv at RMSE = 1.5e-3 of
// the UV range on the corpus, benchmarks/laplacian.md section 3): within
// 5 % of the best of K = 50, 1, 2, 4 and 8 % on every mesh but one whose
// conformal chart drifts little and wants 0.3 % (stein_boat). Weak where
// the drift does not follow the boundary: the rule does not look at the
// coordinates.
int UvDefaultExtraAnchors(int num_texture_vertices, int num_boundary_vertices);

struct UvLaplacianEncoderOptions {
  UvLaplacianKind kind = UvLaplacianKind::kMeanValue;
  // Texture coordinates are given in units of a grid with 2^frame_bits - 1
  // steps over their range; residuals and anchors are quantised with
  // (2^frame_bits - 1) / (2^step_bits - 1) of those units.
  int step_bits = 12;
  int frame_bits = 20;
  // K, or kUvLaplacianDefaultExtraAnchors.
  int extra_anchors = kUvLaplacianDefaultExtraAnchors;
  UvAnchorSelection selection = UvAnchorSelection::kGreedy;
  // Off: plain rounding of the residuals, as in the paper.
  bool error_diffusion = true;
};

// What decoding a Laplacian coding costs beyond reading its stream: the
// size of the system and of the Cholesky factor of its normal equations,
// whose ordering and factorisation dominate (the flops grow like n^1.5 on
// mesh graphs under nested dissection). The anchors change the factor's
// values, not its work. ComputeUvLaplacianDecodeWork() (uv_laplacian_coder.h)
// computes it.
struct UvLaplacianDecodeWork {
  int num_vertices = 0;
  int64_t factor_entries = 0;
  double factor_flops = 0;
};

// The frame bits for step bits |step_bits|.
inline int UvLaplacianFrameBits(int step_bits) {
  const int frame_bits = step_bits + kUvLaplacianFrameExtraBits;
  return frame_bits < kUvLaplacianMaxFrameBits ? frame_bits
                                               : kUvLaplacianMaxFrameBits;
}

// Stores |settings| for attribute |att_id|. Draco quantises the attribute to
// the frame, so its "quantization_bits" become settings.frame_bits.
void SetUvLaplacianSettings(const UvLaplacianEncoderOptions &settings,
                            int att_id, EncoderOptions *options);

// The settings stored for |att_id| (defaults where none are).
UvLaplacianEncoderOptions GetUvLaplacianSettings(const EncoderOptions &options,
                                                 int att_id);

}  // namespace draco

#endif  // PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_SETTINGS_H_
