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
#include "draco_ext/options/trial_encoder.h"

#include "draco/core/encoder_buffer.h"

namespace draco {

TrialEncoder::TrialEncoder(const Mesh &mesh, const std::vector<int> &att_ids,
                           const ExpertEncoder &encoder) {
  mesh_.set_num_points(mesh.num_points());
  mesh_.SetNumFaces(mesh.num_faces());
  for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
    mesh_.SetFace(f, mesh.face(f));
  }
  encoder_ = std::make_unique<ExpertEncoder>(mesh_);
  encoder_->options().SetGlobalOptions(encoder.options().GetGlobalOptions());
  for (const int id : att_ids) {
    auto copy = std::make_unique<PointAttribute>();
    copy->CopyFrom(*mesh.attribute(id));
    const int trial_id = mesh_.AddAttribute(std::move(copy));
    if (const Options *options = encoder.options().FindAttributeOptions(id)) {
      encoder_->options().SetAttributeOptions(trial_id, *options);
    }
  }
}

StatusOr<size_t> TrialEncoder::EncodedSizeWith(int index,
                                               PredictionSchemeMethod method) {
  DRACO_RETURN_IF_ERROR(encoder_->SetAttributePredictionScheme(index, method));
  EncoderBuffer buffer;
  DRACO_RETURN_IF_ERROR(encoder_->EncodeToBuffer(&buffer));
  return buffer.size();
}

}  // namespace draco
