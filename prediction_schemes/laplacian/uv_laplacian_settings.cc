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
#include "prediction_schemes/laplacian/uv_laplacian_settings.h"

#include <algorithm>

namespace draco {

namespace {

// The attribute options that carry the settings; nothing else reads them.
constexpr char kKindOption[] = "draco_uv_laplacian_kind";
constexpr char kStepBitsOption[] = "draco_uv_laplacian_step_bits";
constexpr char kExtraAnchorsOption[] = "draco_uv_laplacian_anchors";
constexpr char kSelectionOption[] = "draco_uv_laplacian_selection";
constexpr char kQuantizationBitsOption[] = "quantization_bits";

}  // namespace

int UvDefaultExtraAnchors(int num_texture_vertices, int num_boundary_vertices) {
  // ceil((0.65 n + 6 b) / 100) in integers: (13 n + 120 b) / 2000.
  const int64_t weighted = 13 * int64_t{std::max(0, num_texture_vertices)} +
                           120 * int64_t{std::max(0, num_boundary_vertices)};
  return static_cast<int>(
      std::min<int64_t>((weighted + 1999) / 2000, kUvLaplacianMaxExtraAnchors));
}

void SetUvLaplacianSettings(const UvLaplacianEncoderOptions &settings,
                            int att_id, EncoderOptions *options) {
  options->SetAttributeInt(att_id, kQuantizationBitsOption,
                           settings.frame_bits);
  options->SetAttributeInt(att_id, kKindOption,
                           static_cast<int>(settings.kind));
  options->SetAttributeInt(att_id, kStepBitsOption, settings.step_bits);
  options->SetAttributeInt(att_id, kExtraAnchorsOption,
                           settings.extra_anchors);
  options->SetAttributeInt(att_id, kSelectionOption,
                           static_cast<int>(settings.selection));
}

UvLaplacianEncoderOptions GetUvLaplacianSettings(const EncoderOptions &options,
                                                 int att_id) {
  UvLaplacianEncoderOptions settings;
  // An attribute set to the scheme without these settings (plain
  // ExpertEncoder use) gets Tutte weights, the operator that needs no
  // geometry beyond the connectivity.
  settings.kind = static_cast<UvLaplacianKind>(options.GetAttributeInt(
      att_id, kKindOption, static_cast<int>(UvLaplacianKind::kTutte)));
  settings.frame_bits = options.GetAttributeInt(
      att_id, kQuantizationBitsOption, settings.frame_bits);
  settings.step_bits =
      options.GetAttributeInt(att_id, kStepBitsOption, settings.frame_bits);
  settings.extra_anchors = options.GetAttributeInt(
      att_id, kExtraAnchorsOption, settings.extra_anchors);
  settings.selection = static_cast<UvAnchorSelection>(options.GetAttributeInt(
      att_id, kSelectionOption, static_cast<int>(settings.selection)));
  return settings;
}

}  // namespace draco
