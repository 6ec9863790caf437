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
#include "draco_ext/common/uv_rmse.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "draco/core/quantization_utils.h"

namespace draco {

namespace {

std::array<float, 2> UvAt(const PointAttribute &att, PointIndex point) {
  std::array<float, 2> uv = {0.f, 0.f};
  att.ConvertValue(att.mapped_index(point), 2, uv.data());
  return uv;
}

// The TEX_COORD attributes [first, last) of |mesh|.
std::vector<const PointAttribute *> UvSets(const Mesh &mesh, int first,
                                           int last) {
  std::vector<const PointAttribute *> atts;
  for (int i = first;
       i < last && i < mesh.NumNamedAttributes(GeometryAttribute::TEX_COORD);
       ++i) {
    atts.push_back(mesh.GetNamedAttribute(GeometryAttribute::TEX_COORD, i));
  }
  return atts;
}

// Quantizes positions like Draco's AttributeQuantizationTransform, with the
// parameters of the original mesh, so that decoded positions map back to the
// original's integers.
class PositionKeyer {
 public:
  PositionKeyer(const PointAttribute &position, int qp) {
    min_.fill(std::numeric_limits<float>::max());
    std::array<float, 3> max;
    max.fill(std::numeric_limits<float>::lowest());
    for (AttributeValueIndex i(0); i < position.size(); ++i) {
      std::array<float, 3> p;
      position.GetValue(i, p.data());
      for (int c = 0; c < 3; ++c) {
        min_[c] = std::min(min_[c], p[c]);
        max[c] = std::max(max[c], p[c]);
      }
    }
    float range = 0.f;
    for (int c = 0; c < 3; ++c) {
      range = std::max(range, max[c] - min_[c]);
    }
    quantizer_.Init(range > 0.f ? range : 1.f, (1 << qp) - 1);
  }

  // The face's quantized corner positions in a canonical rotation;
  // |rotation| receives the face corner it starts at.
  std::array<int32_t, 9> FaceKey(const Mesh &mesh, FaceIndex f,
                                 int *rotation) const {
    const PointAttribute &position =
        *mesh.GetNamedAttribute(GeometryAttribute::POSITION);
    std::array<std::array<int32_t, 3>, 3> corners;
    for (int k = 0; k < 3; ++k) {
      std::array<float, 3> p;
      position.ConvertValue(position.mapped_index(mesh.face(f)[k]), 3,
                            p.data());
      for (int c = 0; c < 3; ++c) {
        corners[k][c] = quantizer_.QuantizeFloat(p[c] - min_[c]);
      }
    }
    // The smallest of the three rotations, so that faces with repeated
    // corners get one key too.
    std::array<int32_t, 9> best_key;
    for (int start = 0; start < 3; ++start) {
      std::array<int32_t, 9> key;
      for (int k = 0; k < 3; ++k) {
        const auto &corner = corners[(start + k) % 3];
        std::copy(corner.begin(), corner.end(), key.begin() + 3 * k);
      }
      if (start == 0 || key < best_key) {
        best_key = key;
        *rotation = start;
      }
    }
    return best_key;
  }

 private:
  std::array<float, 3> min_;
  Quantizer quantizer_;
};

// Squared UV distance between corner k (canonical order) of two faces,
// summed over the UV sets |atts_a| of |a| and |atts_b| of |b|.
double FaceUvError2(const Mesh &a,
                    const std::vector<const PointAttribute *> &atts_a,
                    FaceIndex fa, int rot_a, const Mesh &b,
                    const std::vector<const PointAttribute *> &atts_b,
                    FaceIndex fb, int rot_b, int k) {
  double error2 = 0;
  for (size_t i = 0; i < atts_a.size() && i < atts_b.size(); ++i) {
    const auto ua = UvAt(*atts_a[i], a.face(fa)[(rot_a + k) % 3]);
    const auto ub = UvAt(*atts_b[i], b.face(fb)[(rot_b + k) % 3]);
    error2 += (ua[0] - ub[0]) * double(ua[0] - ub[0]) +
              (ua[1] - ub[1]) * double(ua[1] - ub[1]);
  }
  return error2;
}

// Original faces by position key, each with its rotation.
typedef std::map<std::array<int32_t, 9>, std::vector<std::pair<FaceIndex, int>>>
    FaceIndexByKey;

// Eq. (9) over the UV sets [first, last).
StatusOr<double> RmseOfSets(const Mesh &original, const Mesh &decoded, int qp,
                            int first, int last) {
  const PointAttribute *const position =
      original.GetNamedAttribute(GeometryAttribute::POSITION);
  if (position == nullptr ||
      decoded.GetNamedAttribute(GeometryAttribute::POSITION) == nullptr) {
    return Status(Status::DRACO_ERROR, "RMSE needs positions.");
  }
  const auto atts_a = UvSets(original, first, last);
  const auto atts_b = UvSets(decoded, first, last);
  const PositionKeyer keyer(*position, qp);
  FaceIndexByKey faces;
  for (FaceIndex f(0); f < original.num_faces(); ++f) {
    int rotation;
    faces[keyer.FaceKey(original, f, &rotation)].push_back({f, rotation});
  }
  // Eq. (9): one error per texture vertex, i.e. per original point (a
  // distinct combination of position and texture coordinates), taken the
  // first time a decoded corner maps to it.
  std::unordered_set<uint64_t> seen;
  double sum2 = 0;
  for (FaceIndex f(0); f < decoded.num_faces(); ++f) {
    int rotation;
    auto it = faces.find(keyer.FaceKey(decoded, f, &rotation));
    if (it == faces.end() || it->second.empty()) {
      return Status(Status::DRACO_ERROR,
                    "RMSE: a decoded face has no original counterpart.");
    }
    // Duplicate faces (same positions): take the closest unused one.
    auto &candidates = it->second;
    size_t best = 0;
    double best_error = std::numeric_limits<double>::max();
    for (size_t i = 0; i < candidates.size(); ++i) {
      double error = 0;
      for (int k = 0; k < 3; ++k) {
        error +=
            FaceUvError2(original, atts_a, candidates[i].first,
                         candidates[i].second, decoded, atts_b, f, rotation, k);
      }
      if (error < best_error) {
        best_error = error;
        best = i;
      }
    }
    const auto match = candidates[best];
    candidates.erase(candidates.begin() + best);
    for (int k = 0; k < 3; ++k) {
      const PointIndex point =
          original.face(match.first)[(match.second + k) % 3];
      if (seen.insert(point.value()).second) {
        sum2 += FaceUvError2(original, atts_a, match.first, match.second,
                             decoded, atts_b, f, rotation, k);
      }
    }
  }
  return seen.empty() ? 0.0
                      : std::sqrt(sum2 / static_cast<double>(seen.size()));
}

}  // namespace

StatusOr<double> UvRmse(const Mesh &original, const Mesh &decoded, int qp) {
  return RmseOfSets(original, decoded, qp, 0, std::numeric_limits<int>::max());
}

StatusOr<double> UvRmseOf(const Mesh &original, const Mesh &decoded, int qp,
                          int tex_coord_index) {
  return RmseOfSets(original, decoded, qp, tex_coord_index,
                    tex_coord_index + 1);
}

}  // namespace draco
