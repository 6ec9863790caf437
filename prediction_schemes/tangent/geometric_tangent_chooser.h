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
// The encoder half of MESH_PREDICTION_GEOMETRIC_TANGENT that does not depend
// on Draco's connectivity type: given the tangents' connectivity, it tries
// the conventions and codings and keeps the smallest prediction data.
// MeshPredictionSchemeGeometricTangentEncoder (one class per corner table
// type) only checks its input and builds the TangentConnectivity.
#ifndef PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_CHOOSER_H_
#define PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_CHOOSER_H_

#include <array>
#include <cstdint>
#include <vector>

#include "draco/core/encoder_buffer.h"
#include "draco_ext/common/uv_residual_coder.h"
#include "prediction_schemes/tangent/mesh_prediction_scheme_geometric_tangent_shared.h"

namespace draco {

// What the encoder needs besides the data: the conventions to try, the
// normals' octahedral bits and where Draco's quantisation puts a tangent.
struct GeometricTangentEncoderSettings {
  uint8_t kinds = kAllGeometricTangentKinds;
  int normal_bits = 0;
  TangentGrid grid;
};

// Chooses how to code quantised tangents with the predictions of
// GeometricTangentPredictor: tries every convention of the settings' kinds,
// with per convention the handedness sign that most entries follow and the
// step-2 gain their first residuals call for (eq. (2)), neighbour class
// thresholds at the terciles of a first pass's neighbour sums, and the
// handedness and copies as tokens or as exceptions; keeps the smallest
// streams. Values must lie on the settings' grid (the caller checks).
class GeometricTangentChooser {
 public:
  // Runs the choice on |num_entries| tangents |values| (4 per entry);
  // false if coding fails or no kind was allowed.
  bool Choose(const TangentConnectivity &connectivity,
              const GeometricTangentEncoderSettings &settings,
              GeometricTangentPredictor *predictor, const int32_t *values,
              int num_entries);

  bool has_best() const { return has_best_; }
  // The chosen configuration and its prediction-data streams (after the
  // configuration), valid once Choose() returned true.
  const GeometricTangentConfig &best_config() const { return best_config_; }
  const std::vector<char> &best_streams() const { return best_streams_; }

 private:
  // The four ways of coding the handedness and the copies (bit 0 of the
  // index: the handedness as exceptions, bit 1: the copies as exceptions;
  // else as tokens). They differ only in the tokens they leave out, so one
  // pass over the entries codes all four.
  static constexpr int kNumExceptionChoices = 4;
  class Coder {
   public:
    explicit Coder(int expected_tokens) {
      for (Choice &choice : choices_) {
        choice.residuals.Reset(expected_tokens);
      }
    }
    bool Value(int context, int32_t predicted, int32_t sign,
               const int32_t *value) {
      for (Choice &choice : choices_) {
        choice.Add(context, sign * (*value - predicted));
      }
      return true;
    }
    bool Handedness(int entry, const std::array<int32_t, 2> &predicted,
                    const int32_t *w) {
      const int32_t symbol = HandednessSymbol(*w, predicted);
      if (symbol != 0) {
        handedness_exceptions_.Add(entry, symbol);
      }
      for (int i = 0; i < kNumExceptionChoices; ++i) {
        if ((i & 1) == 0) {
          choices_[i].Add(kTangentHandednessContext, symbol);
        }
      }
      return true;
    }
    bool Copy(int entry, const int32_t *source, const int32_t *v) {
      const bool exact = std::equal(v, v + kTangentNumComponents, source);
      if (!exact) {
        copy_exceptions_.Add(entry, 1);
      }
      for (int i = 0; i < kNumExceptionChoices; ++i) {
        if ((i & 2) != 0 && exact) {
          continue;
        }
        for (int c = 0; c < kTangentNumComponents; ++c) {
          choices_[i].Add(kTangentCopyContext, v[c] - source[c]);
        }
      }
      return true;
    }
    // The prediction-data streams of choice |i| (after the config).
    bool Encode(int i, EncoderBuffer *streams) const {
      if ((i & 1) != 0) {
        handedness_exceptions_.Encode(true, streams);
      }
      if ((i & 2) != 0) {
        copy_exceptions_.Encode(false, streams);
      }
      EncodeVarint<uint32_t>(choices_[i].num_tokens, streams);
      return choices_[i].residuals.Encode(streams);
    }

   private:
    struct Choice {
      void Add(int context, int32_t residual) {
        residuals.Add(context, residual);
        ++num_tokens;
      }
      UvResidualEncoder residuals{kTangentNumContexts};
      uint32_t num_tokens = 0;
    };
    std::array<Choice, kNumExceptionChoices> choices_;
    TangentExceptions handedness_exceptions_, copy_exceptions_;
  };
  // Records nothing: for the pass that only collects neighbour sums.
  struct NullCoder {
    bool Value(int, int32_t, int32_t, const int32_t *) { return true; }
    bool Handedness(int, const std::array<int32_t, 2> &, const int32_t *) {
      return true;
    }
    bool Copy(int, const int32_t *, const int32_t *) { return true; }
  };

  // The handedness sign and step-2 gain that suit |predictions| of |values|.
  static TangentCodingParameters FitParameters(
      const TangentGrid &grid,
      const std::vector<GeometricTangentPrediction> &predictions,
      const int32_t *values);
  // The neighbour class thresholds that split |sums| (-1: none) into
  // thirds.
  static std::array<uint8_t, 2> NeighbourThresholds(
      const std::vector<int8_t> &sums);
  // Codes |values| with |config| (and the neighbour thresholds its first
  // pass finds) and keeps the streams if they are the smallest so far.
  bool TryConfig(const TangentConnectivity &connectivity,
                 const GeometricTangentConfig &config,
                 const std::vector<GeometricTangentPrediction> &predictions,
                 const int32_t *values);

  GeometricTangentConfig best_config_;
  std::vector<char> best_streams_;
  bool has_best_ = false;
};

}  // namespace draco

#endif  // PREDICTION_SCHEMES_TANGENT_GEOMETRIC_TANGENT_CHOOSER_H_
