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
#include <cstdlib>

#include "draco_ext/laplacian/uv_laplacian_coder.h"
#include "draco_ext/laplacian/mesh_prediction_scheme_tex_coords_laplacian_shared.h"

namespace draco {

namespace {

// The frame Draco quantises to is this many bits finer than the step.
constexpr int kFrameExtraBits = 8;

constexpr char kRandomPrefix[] = "random:";

struct LaplacianName {
  const char *name;
  UvLaplacianKind kind;
};

constexpr LaplacianName kLaplacianNames[] = {
    {"laplacian_tutte", UvLaplacianKind::kTutte},
    {"laplacian_cotan", UvLaplacianKind::kCotangent},
    {"laplacian_mv", UvLaplacianKind::kMeanValue},
};

constexpr int kMaxAnchors = 1 << 24;

bool ParseCount(const std::string &text, int *count) {
  char *end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || value < 0 || value > kMaxAnchors) {
    return false;
  }
  *count = static_cast<int>(value);
  return true;
}

// "P%" with 0 <= P <= 100 (decimals allowed).
bool ParsePercent(const std::string &text, double *percent) {
  if (text.size() < 2 || text.back() != '%') {
    return false;
  }
  const std::string number = text.substr(0, text.size() - 1);
  char *end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (*end != '\0' || !(value >= 0.0 && value <= 100.0)) {
    return false;
  }
  *percent = value;
  return true;
}

// K for an attribute of |num_values| texture coordinates; a percentage is
// rounded up, so that any positive one gives at least one anchor.
int AnchorCount(const UvAnchorSpec &spec, int64_t num_values) {
  if (!spec.is_percent) {
    return spec.count;
  }
  const double count = std::ceil(spec.percent / 100.0 * num_values);
  return static_cast<int>(std::min<double>(count, kMaxAnchors));
}

}  // namespace

StatusOr<UvAnchorSpec> ParseUvAnchorSpec(const std::string &spec) {
  UvAnchorSpec parsed;
  parsed.random = spec.rfind(kRandomPrefix, 0) == 0;
  const std::string amount =
      parsed.random ? spec.substr(sizeof(kRandomPrefix) - 1) : spec;
  parsed.is_percent = ParsePercent(amount, &parsed.percent);
  if (!parsed.is_percent && !ParseCount(amount, &parsed.count)) {
    return Status(Status::DRACO_ERROR,
                  "Bad -uv_anchors value '" + spec +
                      "': use K, P% or random:K, random:P% (K >= 0, "
                      "0 <= P <= 100).");
  }
  return parsed;
}

bool IsLossyUvPrediction(PredictionSchemeMethod method) {
  return method == MESH_PREDICTION_TEX_COORDS_LAPLACIAN;
}

bool IsUvLaplacianName(const std::string &name) {
  return std::any_of(
      std::begin(kLaplacianNames), std::end(kLaplacianNames),
      [&](const LaplacianName &entry) { return name == entry.name; });
}

Status ConfigureUvLaplacian(const std::string &name, int att_id,
                            ExpertEncoder *encoder) {
  const auto entry = std::find_if(
      std::begin(kLaplacianNames), std::end(kLaplacianNames),
      [&](const LaplacianName &entry) { return name == entry.name; });
  if (entry == std::end(kLaplacianNames)) {
    return Status(Status::DRACO_ERROR, "Not a Laplacian -uv_pred name.");
  }
  const int step_bits =
      encoder->options().GetAttributeInt(att_id, "quantization_bits", -1);
  if (step_bits < 1 || step_bits > kUvLaplacianMaxStepBits) {
    return Status(Status::DRACO_ERROR,
                  "-uv_pred " + name + " needs -qt 1 to " +
                      std::to_string(kUvLaplacianMaxStepBits) + ".");
  }
  const int frame_bits =
      std::min(step_bits + kFrameExtraBits, kUvLaplacianMaxFrameBits);
  encoder->SetAttributeQuantization(att_id, frame_bits);
  encoder->options().SetAttributeInt(att_id, kUvLaplacianKindOption,
                                     static_cast<int>(entry->kind));
  encoder->options().SetAttributeInt(att_id, kUvLaplacianStepBitsOption,
                                     step_bits);
  return OkStatus();
}

StatusOr<int> ApplyUvAnchors(const std::string &spec, const Mesh *mesh,
                             ExpertEncoder *encoder) {
  if (spec.empty()) {
    return 0;
  }
  DRACO_ASSIGN_OR_RETURN(const UvAnchorSpec parsed, ParseUvAnchorSpec(spec));
  int applied = 0;
  for (int i = 0; mesh != nullptr &&
                  i < mesh->NumNamedAttributes(GeometryAttribute::TEX_COORD);
       ++i) {
    const int att_id =
        mesh->GetNamedAttributeId(GeometryAttribute::TEX_COORD, i);
    if (encoder->options().GetAttributeInt(att_id, "prediction_scheme", -1) !=
        MESH_PREDICTION_TEX_COORDS_LAPLACIAN) {
      continue;
    }
    encoder->options().SetAttributeInt(
        att_id, kUvLaplacianAnchorsOption,
        AnchorCount(parsed, mesh->attribute(att_id)->size()));
    encoder->options().SetAttributeInt(att_id, kUvLaplacianRandomAnchorsOption,
                                       parsed.random ? 1 : 0);
    ++applied;
  }
  return applied;
}

Status ConfigureUvAnchors(const std::string &spec, const Mesh *mesh,
                          ExpertEncoder *encoder) {
  DRACO_ASSIGN_OR_RETURN(const int applied,
                         ApplyUvAnchors(spec, mesh, encoder));
  if (!spec.empty() && applied == 0) {
    return Status(Status::DRACO_ERROR,
                  "-uv_anchors needs -uv_pred laplacian_tutte, "
                  "laplacian_cotan or laplacian_mv.");
  }
  return OkStatus();
}

std::string UvAnchorsUsage() {
  return "  -uv_anchors <K>       extra anchors of -uv_pred laplacian_*, "
         "chosen\n"
         "                          greedily (default 50); <P>% scales them "
         "with the mesh\n"
         "                          (P percent of its texture coordinates, "
         "e.g. 2%);\n"
         "                          random:<K> or random:<P>% picks them at "
         "random\n";
}

}  // namespace draco
