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
#include "draco_ext/options/uv_laplacian_options.h"

#include <algorithm>
#include <cmath>

#include "prediction_schemes/laplacian/uv_laplacian_settings.h"

namespace draco {

namespace {

UvLaplacianKind KindOf(UvPrediction prediction) {
  switch (prediction) {
    case UvPrediction::kLaplacianTutte:
      return UvLaplacianKind::kTutte;
    case UvPrediction::kLaplacianCotan:
      return UvLaplacianKind::kCotangent;
    default:
      DRACO_DCHECK(prediction == UvPrediction::kLaplacianMeanValue);
      return UvLaplacianKind::kMeanValue;
  }
}

}  // namespace

int UvAnchorCount(const UvAnchorSpec &spec, int64_t num_values) {
  if (!spec.is_percent) {
    return spec.count;
  }
  const double count = std::ceil(spec.percent / 100.0 * num_values);
  return static_cast<int>(
      std::min<double>(count, kUvLaplacianMaxExtraAnchors));
}

Status ConfigureUvLaplacian(UvPrediction prediction,
                            const std::optional<UvAnchorSpec> &anchors,
                            const Mesh &mesh, int att_id,
                            ExpertEncoder *encoder) {
  if (!IsUvLaplacian(prediction)) {
    return ErrorStatus("Not a Laplacian -uv_pred name.");
  }
  UvLaplacianEncoderOptions settings;
  settings.kind = KindOf(prediction);
  settings.step_bits =
      encoder->options().GetAttributeInt(att_id, "quantization_bits", -1);
  if (settings.step_bits < 1 || settings.step_bits > kUvLaplacianMaxStepBits) {
    return ErrorStatus(std::string("-uv_pred ") +
                       UvPredictionNameOf(prediction) + " needs -qt 1 to " +
                       std::to_string(kUvLaplacianMaxStepBits) + ".");
  }
  settings.frame_bits = UvLaplacianFrameBits(settings.step_bits);
  if (anchors.has_value()) {
    settings.extra_anchors =
        UvAnchorCount(*anchors, mesh.attribute(att_id)->size());
    settings.selection = anchors->random ? UvAnchorSelection::kRandom
                                         : UvAnchorSelection::kGreedy;
  }
  SetUvLaplacianSettings(settings, att_id, &encoder->options());
  return OkStatus();
}

}  // namespace draco
