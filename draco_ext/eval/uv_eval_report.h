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
// Tables, CSV and charts of draco_uv_eval's measurements.
#ifndef DRACO_EXT_EVAL_UV_EVAL_REPORT_H_
#define DRACO_EXT_EVAL_UV_EVAL_REPORT_H_

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "draco_ext/eval/uv_eval.h"

namespace draco {

// Mesh name -> kind, from a MANIFEST.tsv with "name" and "kind" columns in
// |input| (a folder) or in its parent; empty when there is none.
std::map<std::string, std::string> ReadMeshKinds(
    const std::filesystem::path &input);

// The per-mesh table printed after each mesh.
std::string FormatMeshTable(const std::vector<UvEvalRow> &rows);

// The CSV columns, in this spelling.
std::string CsvHeader();
std::string CsvLine(const UvEvalRow &row);

// The per-mesh tangent table printed after a mesh with tangents, and its
// CSV columns.
std::string FormatTangentTable(const std::vector<TangentEvalRow> &rows);
std::string TangentCsvHeader();
std::string TangentCsvLine(const TangentEvalRow &row);

class UvEvalReport {
 public:
  explicit UvEvalReport(std::map<std::string, std::string> kinds)
      : kinds_(std::move(kinds)) {}

  void Add(const std::vector<UvEvalRow> &rows);
  void AddTangents(const std::vector<TangentEvalRow> &rows);
  // Median / mean / max ratio to stock per scheme and qt, over all meshes
  // and per mesh kind; with tangent rows, the same of the tangent bytes per
  // qt, qtg, scheme and tangent name.
  std::string FormatSummary() const;
  bool WriteCsv(const std::string &path) const;
  bool WriteTangentCsv(const std::string &path) const;
  // Bits per UV vertex against RMSE, one curve per scheme and one panel per
  // mesh, drawn by draco_uv_plot.py with matplotlib.
  bool WritePlot(const std::string &path) const;
  bool AllRoundTripsOk() const;

 private:
  std::string FormatTangentSummary() const;

  std::map<std::string, std::string> kinds_;
  std::vector<UvEvalRow> rows_;
  std::vector<TangentEvalRow> tangent_rows_;
};

}  // namespace draco

#endif  // DRACO_EXT_EVAL_UV_EVAL_REPORT_H_
