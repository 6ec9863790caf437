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
// draco-uv's part of DracoCompressionOptions, the per-mesh compression
// settings of Draco's scene and glTF pipeline (draco_transcoder). Draco's
// compression options header includes this one (patches/0014), so it
// depends on nothing but Draco's Status.
//
// Extension point: a new per-mesh draco-uv option (such as -uv_seams) is a
// field of UvCompressionOptions, a branch of ParseUvCompressionFlag(), a
// check in CheckUvCompressionOptions() and its application in
// ConfigureUvCompressionForGltf() (uv_gltf.h); no patch changes.
#ifndef DRACO_EXT_OPTIONS_UV_COMPRESSION_OPTIONS_H_
#define DRACO_EXT_OPTIONS_UV_COMPRESSION_OPTIONS_H_

#include "draco/draco_features.h"

#ifdef DRACO_TRANSCODER_SUPPORTED
#include <string>

#include "draco/core/status.h"

namespace draco {

struct DracoCompressionOptions;

// How the texture coordinates of a mesh are compressed beyond stock Draco.
// Default-constructed, it changes nothing: output stays byte-identical to
// stock Draco.
struct UvCompressionOptions {
  // A -uv_pred name (uv_prediction_options.h); empty or "draco" keeps stock
  // Draco's choice.
  std::string prediction;
  // A -uv_seams name (uv_seam_options.h); empty or "draco" keeps stock
  // Draco's seam coding.
  std::string seams;
  // A -uv_anchors value (uv_laplacian_options.h) for the Laplacian
  // -uv_pred names; empty keeps the default 50 greedy anchors.
  std::string anchors;

  // True when no draco-uv feature is requested.
  bool IsStock() const;

  bool operator==(const UvCompressionOptions &other) const {
    return prediction == other.prediction && seams == other.seams &&
           anchors == other.anchors;
  }
  bool operator!=(const UvCompressionOptions &other) const {
    return !(*this == other);
  }
};

// Checks |options.uv| against the rest of |options|: a known -uv_pred name,
// and for anything but stock Draco Edgebreaker encoding (compression level
// 1 or more), quantized texture coordinates and, for the methods that need
// them, quantized positions; a known -uv_seams name, and for context
// Edgebreaker encoding; a valid -uv_anchors value, only with a Laplacian
// -uv_pred name. Called by DracoCompressionOptions::Check().
Status CheckUvCompressionOptions(const DracoCompressionOptions &options);

// Command-line flags of draco-uv for tools built on DracoCompressionOptions
// (draco_transcoder): true when |arg| is one of them.
bool IsUvCompressionFlag(const char *arg);

// Parses the flag argv[*index] and its value argv[*index + 1] into
// |options| and leaves *index on the value. Fails when the value is missing
// or invalid (the message lists the valid names).
Status ParseUvCompressionFlag(int argc, char **argv, int *index,
                              UvCompressionOptions *options);

// Help text of the flags, one line per flag and value.
std::string UvCompressionUsage();

}  // namespace draco

#endif  // DRACO_TRANSCODER_SUPPORTED
#endif  // DRACO_EXT_OPTIONS_UV_COMPRESSION_OPTIONS_H_
