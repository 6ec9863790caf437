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
#include "draco_ext/eval/uv_eval_report.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numeric>
#include <sstream>
#include <tuple>

namespace draco {

namespace {

namespace fs = std::filesystem;

// 4096^2 texture: RMSE in texels is RMSE in UV units times 4096.
constexpr double kTexelsPerUvUnit = 4096.0;

std::string Format(const char *format, ...) __attribute__((format(printf, 1, 2)));
std::string Format(const char *format, ...) {
  char text[512];
  va_list args;
  va_start(args, format);
  vsnprintf(text, sizeof(text), format, args);
  va_end(args);
  return text;
}

std::vector<std::string> SplitTabs(const std::string &line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, '\t')) {
    fields.push_back(field);
  }
  return fields;
}

std::map<std::string, std::string> ReadManifest(const fs::path &path) {
  std::map<std::string, std::string> kinds;
  std::ifstream file(path);
  std::string line;
  if (!std::getline(file, line)) {
    return kinds;
  }
  const std::vector<std::string> header = SplitTabs(line);
  const auto name_it = std::find(header.begin(), header.end(), "name");
  const auto kind_it = std::find(header.begin(), header.end(), "kind");
  if (name_it == header.end() || kind_it == header.end()) {
    return kinds;
  }
  const size_t name_col = name_it - header.begin();
  const size_t kind_col = kind_it - header.begin();
  while (std::getline(file, line)) {
    const std::vector<std::string> fields = SplitTabs(line);
    if (fields.size() > std::max(name_col, kind_col)) {
      kinds[fields[name_col]] = fields[kind_col];
    }
  }
  return kinds;
}

double Median(std::vector<double> values) {
  if (values.empty()) {
    return 0;
  }
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

double Mean(const std::vector<double> &values) {
  return values.empty() ? 0
                        : std::accumulate(values.begin(), values.end(), 0.0) /
                              values.size();
}

std::string SummaryLine(const std::string &label,
                        const std::vector<double> &ratios,
                        const std::vector<double> &bpvs) {
  return Format("  %-42s %6zu %8.3f %8.3f %8.3f %9.2f\n", label.c_str(),
                ratios.size(), Median(ratios), Mean(ratios),
                ratios.empty() ? 0.0
                               : *std::max_element(ratios.begin(), ratios.end()),
                Median(bpvs));
}

}  // namespace

std::map<std::string, std::string> ReadMeshKinds(const fs::path &input) {
  if (!fs::is_directory(input)) {
    return {};
  }
  for (const fs::path &dir : {input, input.parent_path()}) {
    if (fs::exists(dir / "MANIFEST.tsv")) {
      return ReadManifest(dir / "MANIFEST.tsv");
    }
  }
  return {};
}

std::string FormatMeshTable(const std::vector<UvEvalRow> &rows) {
  if (rows.empty()) {
    return "";
  }
  std::string table = Format("%s: %lld UV vertices\n", rows[0].mesh.c_str(),
                             static_cast<long long>(rows[0].uv_vertices));
  table += Format("  %3s %-20s %10s %8s %7s %7s %10s %8s %8s %8s %s\n", "qt",
                  "scheme", "UV bytes", "seams", "bpv", "ratio", "RMSE",
                  "texels", "enc ms", "dec ms", "round trip");
  for (const UvEvalRow &row : rows) {
    table += Format(
        "  %3d %-20s %10lld %8.0f %7.3f %7.3f %10.3e %8.3f %8.2f %8.2f %s\n",
        row.qt, row.scheme.c_str(), static_cast<long long>(row.uv_bytes),
        row.seam_bytes, row.bpv, row.ratio_vs_draco, row.rmse,
        row.rmse * kTexelsPerUvUnit, row.enc_ms, row.dec_ms,
        !row.round_trip_ok ? "MISMATCH" : row.lossy ? "lossy" : "ok");
    if (row.target_rmse > 0) {
      table +=
          Format(
              "      lossless at the target: auto -qt %d, %lld UV "
              "bytes\n      ",
              row.lossless_qt, static_cast<long long>(row.lossless_uv_bytes)) +
          row.detail;
    }
  }
  return table;
}

std::string CsvHeader() {
  return "mesh,scheme,qt,uv_vertices,uv_bytes,seam_bytes,bpv,rmse,"
         "rmse_texels,enc_ms,dec_ms,ratio_vs_draco,round_trip,target_rmse,"
         "lossless_qt,lossless_uv_bytes,choice\n";
}

// What an error target's row chose: per summary line (one per UV set)
// the coding and the trial encodes, without commas, e.g.
// "laplacian_mv -qt 9 -uv_anchors default (8 trials)".
std::string TargetChoice(const UvEvalRow &row) {
  std::string choice;
  if (row.target_rmse <= 0) {
    return choice;
  }
  size_t line = 0;
  for (size_t at; (at = row.detail.find("-> ", line)) != std::string::npos;
       line = row.detail.find('\n', at)) {
    const size_t end = row.detail.find(", ", at);
    size_t digits = row.detail.find(" trial encodes)", at);
    const size_t trials_end = digits;
    while (digits > 0 && std::isdigit(row.detail[digits - 1])) {
      --digits;
    }
    choice += (choice.empty() ? "" : " / ") +
              row.detail.substr(at + 3, end - at - 3) + " (" +
              row.detail.substr(digits, trials_end - digits) + " trials)";
  }
  return choice;
}

std::string CsvLine(const UvEvalRow &row) {
  return Format("%s,%s,%d,%lld,%lld,%.0f,%.4f,%.6e,%.4f,%.3f,%.3f,%.4f,%s,",
                row.mesh.c_str(), row.scheme.c_str(), row.qt,
                static_cast<long long>(row.uv_vertices),
                static_cast<long long>(row.uv_bytes), row.seam_bytes, row.bpv,
                row.rmse, row.rmse * kTexelsPerUvUnit, row.enc_ms, row.dec_ms,
                row.ratio_vs_draco,
                !row.round_trip_ok ? "mismatch"
                : row.lossy        ? "lossy"
                                   : "ok") +
         Format("%.6e,%d,%lld,", row.target_rmse, row.lossless_qt,
                static_cast<long long>(row.lossless_uv_bytes)) +
         TargetChoice(row) + "\n";
}

namespace {

double TangentBits(int64_t bytes, int64_t values) {
  return values > 0 ? 8.0 * bytes / values : 0.0;
}

double RatioOf(int64_t bytes, int64_t stock_bytes) {
  return stock_bytes > 0 ? static_cast<double>(bytes) / stock_bytes : 0.0;
}

}  // namespace

std::string FormatTangentTable(const std::vector<TangentEvalRow> &rows) {
  if (rows.empty()) {
    return "";
  }
  std::string table =
      Format("%s: %lld tangent values (points)\n", rows[0].mesh.c_str(),
             static_cast<long long>(rows[0].tangent_values));
  table += Format("  %3s %4s %-20s %-10s %13s %8s %7s %10s %7s %s\n", "qt",
                  "qtg", "scheme", "tangents", "tangent bytes", "bits", "ratio",
                  "bytes", "ratio", "round trip");
  for (const TangentEvalRow &row : rows) {
    table += Format(
        "  %3d %4d %-20s %-10s %13lld %8.3f %7.3f %10lld %7.3f %s\n", row.qt,
        row.qtg, row.scheme.c_str(), row.tangents.c_str(),
        static_cast<long long>(row.tangent_bytes),
        TangentBits(row.tangent_bytes, row.tangent_values),
        RatioOf(row.tangent_bytes, row.stock_tangent_bytes),
        static_cast<long long>(row.bytes), RatioOf(row.bytes, row.stock_bytes),
        row.round_trip_ok ? "ok" : "MISMATCH");
  }
  return table;
}

std::string TangentCsvHeader() {
  return "mesh,scheme,tangents,qt,qtg,tangent_values,tangent_bytes,"
         "stock_tangent_bytes,bits_per_tangent,tangent_ratio,bytes,"
         "stock_bytes,file_ratio,round_trip\n";
}

std::string TangentCsvLine(const TangentEvalRow &row) {
  return Format("%s,%s,%s,%d,%d,%lld,%lld,%lld,%.4f,%.4f,%lld,%lld,%.4f,%s\n",
                row.mesh.c_str(), row.scheme.c_str(), row.tangents.c_str(),
                row.qt, row.qtg, static_cast<long long>(row.tangent_values),
                static_cast<long long>(row.tangent_bytes),
                static_cast<long long>(row.stock_tangent_bytes),
                TangentBits(row.tangent_bytes, row.tangent_values),
                RatioOf(row.tangent_bytes, row.stock_tangent_bytes),
                static_cast<long long>(row.bytes),
                static_cast<long long>(row.stock_bytes),
                RatioOf(row.bytes, row.stock_bytes),
                row.round_trip_ok ? "ok" : "mismatch");
}

void UvEvalReport::Add(const std::vector<UvEvalRow> &rows) {
  rows_.insert(rows_.end(), rows.begin(), rows.end());
}

void UvEvalReport::AddTangents(const std::vector<TangentEvalRow> &rows) {
  tangent_rows_.insert(tangent_rows_.end(), rows.begin(), rows.end());
}

std::string UvEvalReport::FormatTangentSummary() const {
  if (tangent_rows_.empty()) {
    return "";
  }
  // (qt, qtg, scheme, tangents) -> ratios, bits, file ratios.
  using Key = std::tuple<int, int, std::string, std::string>;
  std::map<Key, std::array<std::vector<double>, 3>> values;
  for (const TangentEvalRow &row : tangent_rows_) {
    auto &entry = values[Key(row.qt, row.qtg, row.scheme, row.tangents)];
    entry[0].push_back(RatioOf(row.tangent_bytes, row.stock_tangent_bytes));
    entry[1].push_back(TangentBits(row.tangent_bytes, row.tangent_values));
    entry[2].push_back(RatioOf(row.bytes, row.stock_bytes));
  }
  std::string summary = Format(
      "Summary: tangent bytes / stock Draco's at the same qt and qtg (meshes "
      "with tangents)\n"
      "  %-48s %6s %8s %8s %8s %9s %10s\n",
      "qt, qtg, scheme, -tangent_pred", "n", "median", "mean", "max",
      "med bits", "med file");
  for (const auto &[key, entry] : values) {
    const std::string label =
        Format("qt %d qtg %d %s %s", std::get<0>(key), std::get<1>(key),
               std::get<2>(key).c_str(), std::get<3>(key).c_str());
    summary +=
        Format("  %-48s %6zu %8.3f %8.3f %8.3f %9.2f %10.3f\n", label.c_str(),
               entry[0].size(), Median(entry[0]), Mean(entry[0]),
               *std::max_element(entry[0].begin(), entry[0].end()),
               Median(entry[1]), Median(entry[2]));
  }
  return summary;
}

std::string UvEvalReport::FormatSummary() const {
  std::map<std::pair<int, std::string>,
           std::map<std::string, std::vector<double>>>
      ratios, bpvs;
  for (const UvEvalRow &row : rows_) {
    const auto key = std::make_pair(
        row.qt, row.target_rmse > 0
                    ? row.scheme + " " + Format("%g", row.target_rmse)
                    : row.scheme);
    const auto kind = kinds_.find(row.mesh);
    for (const std::string &group :
         {std::string("all meshes"),
          kind == kinds_.end() ? std::string() : "kind " + kind->second}) {
      if (!group.empty()) {
        ratios[key][group].push_back(row.ratio_vs_draco);
        bpvs[key][group].push_back(row.bpv);
      }
    }
  }
  std::string summary = Format(
      "Summary: UV bytes / stock Draco's best of -cl 7 and -cl 10\n"
      "  %-42s %6s %8s %8s %8s %9s\n",
      "qt, scheme, meshes", "n", "median", "mean", "max", "med bpv");
  for (const auto &entry : ratios) {
    for (const auto &group : entry.second) {
      summary +=
          SummaryLine(Format("qt %d %s (%s)", entry.first.first,
                             entry.first.second.c_str(), group.first.c_str()),
                      group.second, bpvs.at(entry.first).at(group.first));
    }
  }
  return summary + FormatTangentSummary();
}

bool UvEvalReport::WriteCsv(const std::string &path) const {
  std::ofstream file(path);
  file << CsvHeader();
  for (const UvEvalRow &row : rows_) {
    file << CsvLine(row);
  }
  return static_cast<bool>(file);
}

bool UvEvalReport::WritePlot(const std::string &path) const {
  const std::string csv = path + ".csv";
  if (!WriteCsv(csv)) {
    return false;
  }
  const std::string python =
      fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command =
      python + " \"" DRACO_UV_PLOT_SCRIPT "\" \"" + csv + "\" \"" + path + "\"";
  const bool ok = std::system(command.c_str()) == 0;
  fs::remove(csv);
  return ok;
}

bool UvEvalReport::WriteTangentCsv(const std::string &path) const {
  std::ofstream file(path);
  file << TangentCsvHeader();
  for (const TangentEvalRow &row : tangent_rows_) {
    file << TangentCsvLine(row);
  }
  return static_cast<bool>(file);
}

bool UvEvalReport::AllRoundTripsOk() const {
  return std::all_of(rows_.begin(), rows_.end(),
                     [](const UvEvalRow &row) { return row.round_trip_ok; }) &&
         std::all_of(
             tangent_rows_.begin(), tangent_rows_.end(),
             [](const TangentEvalRow &row) { return row.round_trip_ok; });
}

}  // namespace draco
