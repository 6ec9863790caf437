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
#include "draco_ext/options/uv_encode_settings.h"

#include "draco/compression/encode.h"
#include "draco/compression/expert_encode.h"
#include "draco_ext/options/uv_configure.h"

namespace draco {

namespace {

// draco_encoder's defaults for the attributes it has no flag for here.
constexpr int kNormalQuantizationBits = 8;
constexpr int kGenericQuantizationBits = 8;

}  // namespace

Status EncodeMeshWithSettings(const Mesh &mesh,
                              const UvEncodeSettings &settings,
                              EncoderBuffer *out, std::string *summary) {
  Encoder encoder;
  encoder.SetAttributeQuantization(GeometryAttribute::POSITION, settings.qp);
  if (settings.qt > 0) {
    encoder.SetAttributeQuantization(GeometryAttribute::TEX_COORD,
                                     settings.qt);
  }
  encoder.SetAttributeQuantization(GeometryAttribute::NORMAL,
                                   kNormalQuantizationBits);
  encoder.SetAttributeQuantization(GeometryAttribute::GENERIC,
                                   kGenericQuantizationBits);
  const int speed = 10 - settings.cl;
  encoder.SetSpeedOptions(speed, speed);
  ExpertEncoder expert(mesh);
  expert.Reset(encoder.CreateExpertEncoderOptions(mesh));
  DRACO_ASSIGN_OR_RETURN(const std::string uv_summary,
                         ConfigureUvCompression(settings.uv, &mesh, &expert));
  if (summary != nullptr) {
    *summary = uv_summary;
  }
  return expert.EncodeToBuffer(out);
}

}  // namespace draco
