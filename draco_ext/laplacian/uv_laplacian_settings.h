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
#ifndef DRACO_EXT_LAPLACIAN_UV_LAPLACIAN_SETTINGS_H_
#define DRACO_EXT_LAPLACIAN_UV_LAPLACIAN_SETTINGS_H_

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
// Extra anchors without -uv_anchors, and the most -uv_anchors accepts.
constexpr int kUvLaplacianDefaultExtraAnchors = 50;
constexpr int kUvLaplacianMaxExtraAnchors = 1 << 24;

struct UvLaplacianEncoderOptions {
  UvLaplacianKind kind = UvLaplacianKind::kMeanValue;
  // Texture coordinates are given in units of a grid with 2^frame_bits - 1
  // steps over their range; residuals and anchors are quantised with
  // (2^frame_bits - 1) / (2^step_bits - 1) of those units.
  int step_bits = 12;
  int frame_bits = 20;
  int extra_anchors = kUvLaplacianDefaultExtraAnchors;
  UvAnchorSelection selection = UvAnchorSelection::kGreedy;
  // Off: plain rounding of the residuals, as in the paper.
  bool error_diffusion = true;
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

#endif  // DRACO_EXT_LAPLACIAN_UV_LAPLACIAN_SETTINGS_H_
