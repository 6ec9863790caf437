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
// libFuzzer target: encode -> decode round trips of small generated meshes
// with every -uv_pred name (UvPredictionNames(), so new schemes are covered
// without editing this file) and every -uv_seams coding at fuzzed -qp, -qt
// and -cl.
//
// The meshes are indexed triangle soups over small value tables, so
// duplicate vertices, zero-area 3D and UV triangles, repeated corners,
// non-manifold edges, isolated triangles, far-away UVs, NaN and infinities
// and meshes without positions or texture coordinates all come up often.
//
// Oracle (aborts otherwise):
//  * an encoding either succeeds or fails with a message; on finite meshes
//    the draco-uv schemes only refuse with a "-uv_pred ..." message that
//    names the reason, never with a generic encoder failure where stock
//    Draco succeeds; meshes with NaN or infinities never encode;
//  * what encodes, decodes, and (except with the lossy Laplacian coders)
//    decodes to exactly the bits that stock Draco's encoding at the same
//    settings decodes to.
// Meshes with NaN or infinite values are only given to draco-uv schemes,
// which must refuse them: stock Draco's quantizer converts such values to
// integers (undefined behaviour), which is stock behaviour, not ours.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdio>
#include <cstdlib>
#include <iterator>

#include "draco_ext/hooks/prediction_scheme_ids.h"
#include "draco_ext/options/uv_compression_options.h"
#include "tests/uv_soup_mesh.h"

namespace {

using draco::SoupMesh;

float ConsumeCoordinate(FuzzedDataProvider *provider) {
  const uint8_t kind = provider->ConsumeIntegral<uint8_t>();
  switch (kind) {
    case 250:
      return std::nanf("");
    case 251:
      return INFINITY;
    case 252:
      return -INFINITY;
    case 253:
      return 1e30f;
    case 254:
      return -1e7f;
    case 255:
      return provider->ConsumeFloatingPoint<float>();
    default:
      // A coarse grid: coincident and collinear values are common.
      return (static_cast<int>(kind % 17) - 8) * 0.25f;
  }
}

SoupMesh ConsumeSoup(FuzzedDataProvider *provider) {
  SoupMesh soup;
  const uint8_t flags = provider->ConsumeIntegral<uint8_t>();
  const int num_positions =
      flags % 29 == 0 ? 0 : provider->ConsumeIntegralInRange(1, 24);
  const int num_uvs =
      flags % 31 == 1 ? 0 : provider->ConsumeIntegralInRange(1, 24);
  const int num_faces = provider->ConsumeIntegralInRange(1, 40);
  for (int i = 0; i < num_positions; ++i) {
    soup.positions.push_back({ConsumeCoordinate(provider),
                              ConsumeCoordinate(provider),
                              ConsumeCoordinate(provider)});
  }
  for (int i = 0; i < num_uvs; ++i) {
    soup.uvs.push_back(
        {ConsumeCoordinate(provider), ConsumeCoordinate(provider)});
  }
  for (int f = 0; f < num_faces; ++f) {
    SoupMesh::Face face;
    for (int i = 0; i < 3; ++i) {
      face.position[i] = provider->ConsumeIntegralInRange(0, 23);
      // Mostly the UV of the same index (a seamless chart), sometimes
      // another (seams).
      face.uv[i] = provider->ConsumeBool()
                       ? face.position[i]
                       : provider->ConsumeIntegralInRange(0, 23);
    }
    soup.faces.push_back(face);
  }
  return soup;
}

[[noreturn]] void Fail(const char *what, const draco::UvEncodeSettings &s,
                       const std::string &detail) {
  fprintf(stderr,
          "draco_uv_roundtrip_fuzzer: %s (-qp %d -qt %d -cl %d -uv_pred %s "
          "-uv_seams %s): %s\n",
          what, s.qp, s.qt, s.cl, draco::UvPredictionNameOf(s.uv.prediction),
          draco::UvSeamCodingNameOf(s.uv.seams), detail.c_str());
  abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  FuzzedDataProvider provider(data, size);
  const auto &names = draco::UvPredictionNames();
  draco::UvEncodeSettings settings;
  settings.uv.prediction =
      names[provider.ConsumeIntegralInRange<size_t>(0, names.size() - 1)]
          .prediction;
  settings.qp = provider.ConsumeIntegralInRange(1, 24);
  settings.qt = provider.ConsumeIntegralInRange(1, 22);
  settings.cl = provider.ConsumeIntegralInRange(0, 10);
  constexpr draco::UvSeamCoding kSeamCodings[] = {
      draco::UvSeamCoding::kDraco, draco::UvSeamCoding::kContext};
  settings.uv.seams = kSeamCodings[provider.ConsumeIntegralInRange<size_t>(
      0, std::size(kSeamCodings) - 1)];
  const std::unique_ptr<draco::Mesh> mesh =
      draco::BuildSoupMesh(ConsumeSoup(&provider));
  if (mesh == nullptr) {
    return 0;
  }
  const draco::PredictionSchemeMethod method =
      draco::UvPredictionMethod(settings.uv.prediction);
  // Without texture coordinates a draco-uv name changes nothing: the mesh
  // is stock Draco's to encode.
  const bool draco_uv_scheme =
      draco::IsDracoUvPredictionMethod(method) &&
      mesh->NumNamedAttributes(draco::GeometryAttribute::TEX_COORD) > 0;
  const bool non_finite =
      draco::HasNonFiniteValue(*mesh, draco::GeometryAttribute::POSITION) ||
      draco::HasNonFiniteValue(*mesh, draco::GeometryAttribute::TEX_COORD);
  if (non_finite && !draco_uv_scheme) {
    return 0;  // Stock Draco's own undefined behaviour; not exercised.
  }
  const draco::UvRoundTrip result =
      draco::RoundTripAgainstStock(*mesh, settings, !non_finite);
  if (!result.encoded.ok()) {
    const std::string message = result.encoded.error_msg_string();
    if (message.empty()) {
      Fail("encoding failed without a message", settings, "");
    }
    // A mesh with NaN or infinities may also fail before the schemes are
    // configured (e.g. "All triangles are degenerate."); only encoding it
    // would be wrong.
    const bool named_reason = message.find("-uv_pred") != std::string::npos ||
                              message.find("-uv_seams") != std::string::npos;
    if (draco_uv_scheme && !non_finite && !named_reason) {
      draco::UvEncodeSettings stock = settings;
      stock.uv = draco::UvCompressionOptions();
      draco::EncoderBuffer buffer;
      if (draco::EncodeMeshWithSettings(*mesh, stock, &buffer).ok()) {
        Fail("failed where stock Draco encodes", settings, message);
      }
    }
    return 0;
  }
  if (non_finite) {
    Fail("encoded NaN or infinity", settings, "");
  }
  if (!result.decoded.ok()) {
    Fail("cannot decode own output", settings,
         result.decoded.error_msg_string());
  }
  // The Laplacian coders are lossy: their output is not stock Draco's.
  const bool lossy = draco::IsLossyUvPrediction(method);
  if (result.stock_encoded && !result.identical && !lossy) {
    Fail("decoded values differ from stock Draco's", settings, "");
  }
  return 0;
}
