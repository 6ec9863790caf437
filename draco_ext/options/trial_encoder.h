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
// TrialEncoder: the trial encodes of the auto choices (-uv_pred auto,
// -tangent_pred auto) on a mesh reduced to the attributes a choice can
// change.
#ifndef DRACO_EXT_OPTIONS_TRIAL_ENCODER_H_
#define DRACO_EXT_OPTIONS_TRIAL_ENCODER_H_

#include <memory>
#include <vector>

#include "draco/compression/config/compression_shared.h"
#include "draco/compression/expert_encode.h"
#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"

namespace draco {

// Encodes the faces of a mesh with a few of its attributes only, each under
// the options an ExpertEncoder of the whole mesh has for it (and that
// encoder's global options). Where no other attribute's coding depends on
// how one attribute is predicted, two predictions' trial sizes differ by
// exactly what the whole file's differ by, for a fraction of the encoding
// time: an attribute's prediction changes neither the connectivity nor the
// other attributes' values. That premise is the caller's to check (it holds
// for the lossless predictions, whose decoded values are all the same); a
// lossy prediction changes what the schemes that read its values predict.
class TrialEncoder {
 public:
  // Copies |att_ids| of |mesh| (trial attribute i is |att_ids|[i]) with
  // their options on |encoder|.
  TrialEncoder(const Mesh &mesh, const std::vector<int> &att_ids,
               const ExpertEncoder &encoder);
  // The options of the trial's attributes, as ExpertEncoder's.
  EncoderOptions &options() { return encoder_->options(); }
  // The trial's size with prediction |method| for trial attribute |index|.
  StatusOr<size_t> EncodedSizeWith(int index, PredictionSchemeMethod method);

 private:
  Mesh mesh_;
  std::unique_ptr<ExpertEncoder> encoder_;
};

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_TRIAL_ENCODER_H_
