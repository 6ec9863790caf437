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
// Measurements behind draco_uv_eval and the benchmarks: what each UV coder
// costs on a mesh, in the terms of [Váša & Brunnett 2014] section 6 (bits
// per UV vertex, RMSE of eq. 9) plus encode and decode times; on meshes with
// tangents also what each tangent coder costs.
#ifndef DRACO_EXT_EVAL_UV_EVAL_H_
#define DRACO_EXT_EVAL_UV_EVAL_H_

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"
#include "draco_ext/common/uv_rmse.h"  // IWYU pragma: export
#include "draco_ext/options/uv_compression_options.h"

namespace draco {

struct UvEvalOptions {
  std::vector<int> qt = {10, 12};
  int qp = 14;
  int cl = 10;
  // -uv_pred names; "draco" is always measured (it is the reference).
  std::vector<std::string> schemes = {"draco",    "parallelogram",
                                      "portable", "multi_parallelogram",
                                      "weighted", "auto"};
  int repeat = 3;  // Timings are the minimum over this many runs.
  // -uv_seams names: every scheme is measured with each. Rows of a coding
  // other than "draco" name their scheme "<scheme>+<coding>" (a scheme may
  // also be given so, e.g. "weighted+context"). The reference (stock
  // Draco's best of -cl 7 and 10) keeps stock seams.
  std::vector<std::string> seams = {"draco"};
  // -uv_anchors of the Laplacian schemes; unset means the default.
  std::optional<UvAnchorSpec> uv_anchors;
  // Error targets (-uv_rmse R, UV units): per target and -uv_seams name a
  // row of scheme "rmse" (with seams: "rmse+<coding>") with exactly what
  // draco_encoder -uv_rmse R writes, qt 0.
  std::vector<double> rmse_targets;
  // Meshes with tangents (glTF TANGENT): -tangent_pred names measured with
  // every scheme at every qt and qtg ("draco": stock tangent coding, the
  // scheme alone), and the -qtg values (draco_transcoder's default 8).
  std::vector<std::string> tangents = {"draco", "auto"};
  std::vector<int> qtg = {8};
};

// The options a measured scheme name stands for: "<uv_pred>[+<uv_seams>]",
// e.g. "weighted+context" (seams default to "draco"). Unknown names are
// errors that list the valid ones.
StatusOr<UvCompressionOptions> ParseUvSchemeName(const std::string &scheme);

// One (mesh, scheme, qt) measurement.
struct UvEvalRow {
  std::string mesh;
  std::string scheme;
  int qt = 0;
  int64_t uv_vertices = 0;  // Distinct (position, UV) pairs, all UV sets.
  int64_t uv_bytes = 0;     // size(with UVs) - size(without UVs).
  double seam_bytes = 0;    // Part of uv_bytes spent on seams: stock
                            // Draco's bit streams of the TEX_COORD
                            // attributes, or with -uv_seams context the
                            // exact stream, which codes the seams of all
                            // non-position attributes jointly.
  double bpv = 0;           // 8 * uv_bytes / uv_vertices.
  double rmse = 0;          // Eq. (9) in UV units, all UV sets.
  double enc_ms = 0;
  double dec_ms = 0;        // Decoding the whole mesh.
  double ratio_vs_draco = 0;  // uv_bytes / stock's best of -cl 7 and 10.
  bool lossy = false;          // A lossy scheme (the Laplacians).
  // Decoded UVs as expected: bit-exact for lossless schemes, decoded at all
  // for lossy ones (their error is |rmse|).
  bool round_trip_ok = false;
  std::string detail;          // E.g. what "auto" chose.
  // Rows of an error target: the target (else 0), the UV bytes of the
  // lossless coding that meets it (-uv_pred auto at the coarsest -qt whose
  // grid meets it) and that -qt. ratio_vs_draco compares with stock
  // Draco's best at that -qt; round_trip_ok says the target was met.
  double target_rmse = 0;
  int64_t lossless_uv_bytes = 0;
  int lossless_qt = 0;
};

// One (mesh, scheme, qt, tangents, qtg) measurement of a mesh with
// tangents, encoded like draco_encoder -qp -qt -cl -uv_pred -uv_seams
// -tangent_pred -qtg.
struct TangentEvalRow {
  std::string mesh;
  std::string scheme;    // As in UvEvalRow: "<uv_pred>[+<uv_seams>]".
  std::string tangents;  // The -tangent_pred name.
  int qt = 0;
  int qtg = 0;
  // The mesh's points: one TANGENT value each, as glTF stores a value per
  // vertex.
  int64_t tangent_values = 0;
  // size(with tangents) - size(without tangents), with these settings and
  // with stock Draco's at the same qt and qtg (-tangent_pred draco, stock
  // UV coding).
  int64_t tangent_bytes = 0;
  int64_t stock_tangent_bytes = 0;
  // Whole files: these settings and stock Draco's.
  int64_t bytes = 0;
  int64_t stock_bytes = 0;
  // Decoded tangents equal those of the stock-coded file at every corner.
  bool round_trip_ok = false;
  std::string detail;  // What the encoder chose (ConfigureUvCompression()).
};

// True when |mesh| has a tangent attribute (TangentAttributeIds()).
bool HasTangents(const Mesh &mesh);

// Distinct (position, texture coordinate) pairs over all TEX_COORD
// attributes: the texture vertices the paper counts.
int64_t CountUvVertices(const Mesh &mesh);

// The mesh files (.obj, .ply, .gltf, .glb in any case) of folder |input|,
// sorted, or |input| itself when it is not a folder: what the evaluation
// tools read.
std::vector<std::string> ListMeshFiles(const std::string &input);

// Bytes stock Draco's Edgebreaker spends on the seams of the TEX_COORD
// attributes: one static-probability rANS bit per interior edge each.
double StockSeamBytes(const Mesh &mesh);

// Measures every scheme of |options| at every qt on |mesh|.
StatusOr<std::vector<UvEvalRow>> EvaluateMesh(const std::string &name,
                                              const Mesh &mesh,
                                              const UvEvalOptions &options);

// Measures every scheme and tangent name of |options| at every qt and qtg
// on |mesh|, in that nesting (qt outermost); none without tangents.
StatusOr<std::vector<TangentEvalRow>> EvaluateMeshTangents(
    const std::string &name, const Mesh &mesh, const UvEvalOptions &options);

// A copy of |mesh| without its tangent attributes (points that then
// coincide merge, where Draco deduplicates point ids): what a tangent's
// bytes are measured against.
std::unique_ptr<Mesh> MeshWithoutTangents(const Mesh &mesh);

}  // namespace draco

#endif  // DRACO_EXT_EVAL_UV_EVAL_H_
