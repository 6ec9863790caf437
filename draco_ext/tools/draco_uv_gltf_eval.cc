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
// draco_uv_gltf_eval: what draco_transcoder's -uv_pred saves on glTF and
// GLB assets, and whether every primitive reads back as with stock coding.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "draco_ext/tools/uv_tool_args.h"
#include "draco_ext/eval/uv_gltf_eval.h"

namespace {

namespace fs = std::filesystem;

struct Args {
  std::string input;
  draco::UvGltfEvalOptions options;
  std::string csv;
  bool progress = true;
};

void Usage() {
  printf(
      "Usage: draco_uv_gltf_eval <glTF/GLB file or folder> [options]\n"
      "\n"
      "Transcodes every asset like draco_transcoder, without -uv_pred and\n"
      "with each scheme, reads the results back and reports their sizes\n"
      "(glTF JSON + buffers; images are not counted) and whether every\n"
      "primitive decodes to the same positions and UVs as with stock coding.\n"
      "\n"
      "  --schemes LIST   -uv_pred names, default auto\n"
      "  --qp N           position quantization bits, default 11\n"
      "  --qt N           texture coordinate quantization bits, default 10\n"
      "  --cl N           compression level, default 7\n"
      "  --glb            write GLB (images inside, counted) instead of glTF\n"
      "  --csv FILE       one row per (asset, scheme)\n"
      "  --quiet          no progress on stderr\n");
}

bool ParseArgs(int argc, char **argv, Args *args) {
  draco::DracoCompressionOptions &compression = args->options.compression;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    const bool has_value = i + 1 < argc;
    int number = 0;
    if (flag == "-h" || flag == "--help") {
      return false;
    } else if (flag == "--quiet") {
      args->progress = false;
    } else if (flag == "--glb") {
      args->options.glb = true;
    } else if (!has_value && flag.rfind("--", 0) == 0) {
      fprintf(stderr, "Error: %s needs a value.\n", flag.c_str());
      return false;
    } else if (flag == "--schemes") {
      args->options.schemes = draco::SplitUvToolList(argv[++i]);
    } else if (flag == "--csv") {
      args->csv = argv[++i];
    } else if (flag == "--qp" || flag == "--qt" || flag == "--cl") {
      if (!draco::ParseUvToolSetting(argv[++i], &number)) {
        fprintf(stderr, "Error: bad %s value '%s'.\n", flag.c_str(), argv[i]);
        return false;
      }
      if (flag == "--qp") {
        compression.quantization_position.SetQuantizationBits(number);
      } else if (flag == "--qt") {
        compression.quantization_bits_tex_coord = number;
      } else {
        compression.compression_level = number;
      }
    } else if (args->input.empty() && flag.rfind("-", 0) != 0) {
      args->input = flag;
    } else {
      fprintf(stderr, "Error: unexpected argument '%s'.\n", flag.c_str());
      return false;
    }
  }
  return !args->input.empty();
}

bool IsGltfFile(const fs::path &path) {
  const std::string extension = path.extension().string();
  return extension == ".gltf" || extension == ".glb";
}

// (path, name) of every asset; names are relative to a folder input.
std::vector<std::pair<std::string, std::string>> ListAssets(
    const std::string &input) {
  std::vector<std::pair<std::string, std::string>> assets;
  if (!fs::is_directory(input)) {
    assets.emplace_back(input, fs::path(input).filename().string());
    return assets;
  }
  for (const auto &entry : fs::recursive_directory_iterator(input)) {
    if (entry.is_regular_file() && IsGltfFile(entry.path())) {
      assets.emplace_back(entry.path().string(),
                          fs::relative(entry.path(), input).string());
    }
  }
  std::sort(assets.begin(), assets.end(),
            [](const auto &a, const auto &b) { return a.second < b.second; });
  return assets;
}

std::string Ratio(int64_t bytes, int64_t stock_bytes) {
  char text[32];
  snprintf(text, sizeof(text), "%.3f",
           stock_bytes > 0 ? static_cast<double>(bytes) / stock_bytes : 1.0);
  return text;
}

void PrintTable(const std::string &scheme,
                const std::vector<draco::UvGltfEvalRow> &rows) {
  printf("\n-uv_pred %s\n\n", scheme.c_str());
  printf(
      "| asset | primitives (with UVs) | stock bytes | %s bytes | ratio "
      "| requires extension | round trip |\n",
      scheme.c_str());
  printf("| --- | ---: | ---: | ---: | ---: | --- | --- |\n");
  int64_t stock_total = 0, total = 0;
  int ok = 0, count = 0;
  for (const draco::UvGltfEvalRow &row : rows) {
    if (row.scheme != scheme) {
      continue;
    }
    ++count;
    ok += row.round_trip_ok;
    stock_total += row.stock_bytes;
    total += row.round_trip_ok ? row.bytes : row.stock_bytes;
    printf("| %s | %d (%d) | %lld | %lld | %s | %s | %s |\n", row.asset.c_str(),
           row.primitives, row.textured_primitives,
           static_cast<long long>(row.stock_bytes),
           static_cast<long long>(row.bytes),
           Ratio(row.bytes, row.stock_bytes).c_str(),
           row.requires_extension ? "yes" : "no",
           row.round_trip_ok ? "ok" : ("FAILED: " + row.detail).c_str());
  }
  printf(
      "| **total** (%d assets, %d round trips ok) | | %lld | %lld | %s | | |\n",
      count, ok, static_cast<long long>(stock_total),
      static_cast<long long>(total), Ratio(total, stock_total).c_str());
}

bool WriteCsv(const std::string &file,
              const std::vector<draco::UvGltfEvalRow> &rows) {
  std::ofstream out(file);
  out << "asset,scheme,primitives,textured_primitives,stock_bytes,bytes,"
         "requires_extension,round_trip_ok\n";
  for (const draco::UvGltfEvalRow &row : rows) {
    out << row.asset << ',' << row.scheme << ',' << row.primitives << ','
        << row.textured_primitives << ',' << row.stock_bytes << ',' << row.bytes
        << ',' << row.requires_extension << ',' << row.round_trip_ok << '\n';
  }
  return static_cast<bool>(out);
}

}  // namespace

int main(int argc, char **argv) {
  Args args;
  if (!ParseArgs(argc, argv, &args)) {
    Usage();
    return draco::UvToolUsageExitCode(argc, argv);
  }
  const fs::path work_dir =
      fs::temp_directory_path() /
      ("draco_uv_gltf_eval_" + std::to_string(static_cast<long>(getpid())));
  fs::create_directories(work_dir);

  std::vector<draco::UvGltfEvalRow> rows;
  std::vector<std::string> skipped;
  bool all_ok = true;
  for (const auto &[path, name] : ListAssets(args.input)) {
    if (args.progress) {
      fprintf(stderr, "%s\n", name.c_str());
    }
    const auto asset_rows =
        draco::EvaluateGltfAsset(path, name, args.options, work_dir.string());
    if (!asset_rows.ok()) {
      skipped.push_back(name + ": " + asset_rows.status().error_msg_string());
      continue;
    }
    for (const draco::UvGltfEvalRow &row : asset_rows.value()) {
      all_ok = all_ok && row.round_trip_ok;
      rows.push_back(row);
    }
  }
  fs::remove_all(work_dir);

  for (const std::string &scheme : args.options.schemes) {
    PrintTable(scheme, rows);
  }
  if (!skipped.empty()) {
    printf("\nSkipped (stock Draco fails on these too):\n");
    for (const std::string &line : skipped) {
      printf("  %s\n", line.c_str());
    }
  }
  if (!args.csv.empty() && !WriteCsv(args.csv, rows)) {
    fprintf(stderr, "Error: cannot write %s\n", args.csv.c_str());
    return 1;
  }
  return all_ok ? 0 : 1;
}
