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
// draco_uv_seam_stats: [Váša & Brunnett 2014] section 3 with measured
// numbers. For every mesh, the bytes and bits per vertex that texture
// connectivity (the seams of every non-position attribute) costs as
// per-edge bits, per-vertex flags, stock Draco and draco-uv's
// -uv_seams context (see draco_ext/eval/uv_seam_stats.h).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "draco/io/mesh_io.h"
#include "draco_ext/tools/uv_tool_args.h"
#include "draco_ext/eval/uv_eval.h"
#include "draco_ext/eval/uv_seam_stats.h"

namespace {

namespace fs = std::filesystem;

struct Args {
  std::string input;
  draco::UvEncodeSettings settings;
  std::string csv;
};

void Usage() {
  printf(
      "Usage: draco_uv_seam_stats <mesh or folder> [options]\n"
      "\n"
      "Texture connectivity cost per mesh: eqs. 1-2 of Vasa & Brunnett 2014\n"
      "and measured bytes of per-edge bits, per-vertex flags (Isenburg &\n"
      "Snoeyink 2000), stock Draco and -uv_seams context, on Draco's seam\n"
      "bits of every non-position attribute.\n"
      "\n"
      "  --cl N      compression level (5..10), default 10\n"
      "  --qp N      position quantization bits, default 14\n"
      "  --qt N      texture coordinate quantization bits, default 12\n"
      "  --csv FILE  one row per mesh\n");
}

bool ParseArgs(int argc, char **argv, Args *args) {
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "-h" || flag == "--help") {
      return false;
    }
    const bool has_value = i + 1 < argc;
    if ((flag == "--cl" || flag == "--qp" || flag == "--qt") && has_value) {
      int *target = flag == "--cl"   ? &args->settings.cl
                    : flag == "--qp" ? &args->settings.qp
                                     : &args->settings.qt;
      if (!draco::ParseUvToolSetting(argv[++i], target)) {
        fprintf(stderr, "Error: bad %s value '%s'.\n", flag.c_str(), argv[i]);
        return false;
      }
    } else if (flag == "--csv" && has_value) {
      args->csv = argv[++i];
    } else if (args->input.empty() && flag.rfind("-", 0) != 0) {
      args->input = flag;
    } else {
      fprintf(stderr, "Error: bad argument '%s'.\n", flag.c_str());
      return false;
    }
  }
  return !args->input.empty();
}

double Bpv(int64_t bytes, int64_t vertices) {
  return vertices > 0 ? 8.0 * bytes / vertices : 0.0;
}

void PrintRow(const draco::UvSeamStats &s) {
  printf(
      "%-28s %7lld %6lld %6.2f %6.2f %6.3f %9lld %6.3f %9lld %6.3f %9lld "
      "%6.3f %9lld %6.3f %6.3f %s\n",
      s.mesh.c_str(), static_cast<long long>(s.vertices),
      static_cast<long long>(s.seam_edges), s.eq1_bpv, s.eq2_bpv,
      s.vertices > 0 ? 8.0 * s.per_edge_entropy_bytes / s.vertices : 0.0,
      static_cast<long long>(s.per_edge_bytes),
      Bpv(s.per_edge_bytes, s.vertices),
      static_cast<long long>(s.per_vertex_bytes),
      Bpv(s.per_vertex_bytes, s.vertices),
      static_cast<long long>(s.stock_bytes), Bpv(s.stock_bytes, s.vertices),
      static_cast<long long>(s.context_bytes), Bpv(s.context_bytes, s.vertices),
      s.stock_bytes > 0 ? static_cast<double>(s.context_bytes) / s.stock_bytes
                        : 0.0,
      s.sizes_match_files ? "yes" : "NO");
}

// Opens |path| for writing and writes the CSV header; null on failure.
FILE *OpenCsv(const std::string &path) {
  FILE *csv = fopen(path.c_str(), "w");
  if (csv != nullptr) {
    fprintf(csv,
            "mesh,attributes,vertices,interior_edges,seam_edges,eq1_bpv,"
            "eq2_bpv,per_edge_entropy_bytes,per_edge_bytes,per_vertex_bytes,"
            "stock_bytes,"
            "context_bytes,sizes_match_files\n");
  }
  return csv;
}

void WriteCsvRow(const draco::UvSeamStats &s, FILE *csv) {
  fprintf(csv, "%s,%d,%lld,%lld,%lld,%.4f,%.4f,%.1f,%lld,%lld,%lld,%lld,%d\n",
          s.mesh.c_str(), s.attributes, static_cast<long long>(s.vertices),
          static_cast<long long>(s.interior_edges),
          static_cast<long long>(s.seam_edges), s.eq1_bpv, s.eq2_bpv,
          s.per_edge_entropy_bytes, static_cast<long long>(s.per_edge_bytes),
          static_cast<long long>(s.per_vertex_bytes),
          static_cast<long long>(s.stock_bytes),
          static_cast<long long>(s.context_bytes), s.sizes_match_files);
}

// Adds the byte and edge counts of |s| to |total| (the TOTAL row).
void AddToTotal(const draco::UvSeamStats &s, draco::UvSeamStats *total) {
  total->vertices += s.vertices;
  total->seam_edges += s.seam_edges;
  total->per_edge_entropy_bytes += s.per_edge_entropy_bytes;
  total->per_edge_bytes += s.per_edge_bytes;
  total->per_vertex_bytes += s.per_vertex_bytes;
  total->stock_bytes += s.stock_bytes;
  total->context_bytes += s.context_bytes;
  total->sizes_match_files = total->sizes_match_files && s.sizes_match_files;
}

}  // namespace

int main(int argc, char **argv) {
  Args args;
  if (!ParseArgs(argc, argv, &args)) {
    Usage();
    return draco::UvToolUsageExitCode(argc, argv);
  }
  const std::vector<std::string> files = draco::ListMeshFiles(args.input);
  const std::vector<fs::path> meshes(files.begin(), files.end());
  FILE *csv = nullptr;
  if (!args.csv.empty() && (csv = OpenCsv(args.csv)) == nullptr) {
    fprintf(stderr, "Error: cannot write %s.\n", args.csv.c_str());
    return 1;
  }
  printf("%-28s %7s %6s %6s %6s %6s %9s %6s %9s %6s %9s %6s %9s %6s %6s %s\n",
         "mesh", "V", "seams", "eq1", "eq2", "H", "per-edge", "bpv", "per-vert",
         "bpv", "stock", "bpv", "context", "bpv", "ratio", "exact");
  draco::UvSeamStats total;
  total.mesh = "TOTAL";
  total.sizes_match_files = true;
  int failures = 0;
  for (const fs::path &path : meshes) {
    auto mesh = draco::ReadMeshFromFile(path.string());
    if (!mesh.ok()) {
      fprintf(stderr, "Error: cannot read %s: %s\n", path.c_str(),
              mesh.status().error_msg());
      ++failures;
      continue;
    }
    const auto stats = draco::MeasureUvSeams(path.stem().string(),
                                             *mesh.value(), args.settings);
    if (!stats.ok()) {
      fprintf(stderr, "Error: %s: %s\n", path.c_str(),
              stats.status().error_msg());
      ++failures;
      continue;
    }
    const draco::UvSeamStats &s = stats.value();
    PrintRow(s);
    fflush(stdout);
    if (csv != nullptr) {
      WriteCsvRow(s, csv);
    }
    AddToTotal(s, &total);
  }
  if (meshes.size() > 1) {
    PrintRow(total);
  }
  if (csv != nullptr) {
    fclose(csv);
  }
  return failures == 0 ? 0 : 1;
}
