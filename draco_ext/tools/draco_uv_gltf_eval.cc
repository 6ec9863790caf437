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
// draco_uv_gltf_eval: what draco_transcoder's -uv_pred and -tangent_pred
// save on glTF and GLB assets, and whether every primitive reads back as
// with stock coding.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "draco_ext/eval/uv_eval.h"
#include "draco_ext/eval/uv_gltf_eval.h"
#include "draco_ext/options/tangent_compression_options.h"
#include "draco_ext/tools/uv_tool_args.h"

namespace {

namespace fs = std::filesystem;

struct Args {
  std::string input;
  draco::UvGltfEvalOptions options;
  std::vector<int> qtg = {8};
  std::string csv;
  bool progress = true;
};

void Usage() {
  printf(
      "Usage: draco_uv_gltf_eval <glTF/GLB file or folder> [options]\n"
      "\n"
      "Transcodes every asset like draco_transcoder, without draco-uv's\n"
      "options and with each -uv_pred and -tangent_pred pair, reads the\n"
      "results back and reports their sizes (glTF JSON + buffers; images\n"
      "are not counted) and whether every primitive decodes to the same\n"
      "values of every attribute as with stock coding. For assets with\n"
      "tangents it also transcodes them without TANGENT: a primitive's\n"
      "tangent bytes are its Draco buffer's bytes with minus without them,\n"
      "and bits per tangent are 8 x those bytes / the TANGENT values of the\n"
      "written glTF (its TANGENT accessor's count, one per vertex).\n"
      "\n"
      "  --schemes LIST   -uv_pred names (<name>+context for -uv_seams\n"
      "                   context), default auto\n"
      "  --tangents LIST  -tangent_pred names, each with every scheme,\n"
      "                   default draco,auto (draco: the scheme alone)\n"
      "  --qtg LIST       tangent quantization bits, default 8\n"
      "  --qp N           position quantization bits, default 11\n"
      "  --qt N           texture coordinate quantization bits, default 10\n"
      "  --qn N           normal quantization bits, default 8\n"
      "  --cl N           compression level, default 7\n"
      "  --glb            write GLB (images inside, counted) instead of glTF\n"
      "  --csv FILE       one row per (asset, scheme, tangents, qtg), and one\n"
      "                   per primitive with tangents\n"
      "  --quiet          no progress on stderr\n");
}

bool ParseList(const std::string &flag, const std::string &list,
               std::vector<int> *values) {
  values->clear();
  for (const std::string &item : draco::SplitUvToolList(list)) {
    int value = 0;
    if (!draco::ParseUvToolSetting(item, &value)) {
      fprintf(stderr, "Error: bad %s value '%s'.\n", flag.c_str(),
              item.c_str());
      return false;
    }
    values->push_back(value);
  }
  return !values->empty();
}

bool ParseSetting(const std::string &flag, const std::string &text,
                  draco::DracoCompressionOptions *compression) {
  int number = 0;
  if (!draco::ParseUvToolSetting(text, &number)) {
    fprintf(stderr, "Error: bad %s value '%s'.\n", flag.c_str(), text.c_str());
    return false;
  }
  if (flag == "--qp") {
    compression->quantization_position.SetQuantizationBits(number);
  } else if (flag == "--qt") {
    compression->quantization_bits_tex_coord = number;
  } else if (flag == "--qn") {
    compression->quantization_bits_normal = number;
  } else {
    compression->compression_level = number;
  }
  return true;
}

bool ParseArgs(int argc, char **argv, Args *args) {
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    const bool has_value = i + 1 < argc;
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
    } else if (flag == "--tangents") {
      args->options.tangents = draco::SplitUvToolList(argv[++i]);
    } else if (flag == "--csv") {
      args->csv = argv[++i];
    } else if (flag == "--qtg") {
      if (!ParseList(flag, argv[++i], &args->qtg)) {
        return false;
      }
    } else if (flag == "--qp" || flag == "--qt" || flag == "--qn" ||
               flag == "--cl") {
      if (!ParseSetting(flag, argv[++i], &args->options.compression)) {
        return false;
      }
    } else if (args->input.empty() && flag.rfind("-", 0) != 0) {
      args->input = flag;
    } else {
      fprintf(stderr, "Error: unexpected argument '%s'.\n", flag.c_str());
      return false;
    }
  }
  return !args->input.empty() && !args->options.schemes.empty() &&
         !args->options.tangents.empty();
}

// Every (scheme, tangents, qtg) variant of |args| is valid for the
// transcoder; else prints why.
bool CheckVariants(const Args &args) {
  draco::DracoCompressionOptions options = args.options.compression;
  for (const int qtg : args.qtg) {
    options.quantization_bits_tangent = qtg;
    for (const std::string &scheme : args.options.schemes) {
      for (const std::string &tangents : args.options.tangents) {
        auto uv = draco::ParseUvSchemeName(scheme);
        auto prediction = draco::ParseTangentPredictionName(tangents);
        draco::Status status = !uv.ok() ? uv.status() : prediction.status();
        if (status.ok()) {
          options.uv = uv.value();
          options.uv.tangent.prediction = prediction.value();
          status = options.Check();
        }
        if (!status.ok()) {
          fprintf(stderr, "Error: %s\n", status.error_msg());
          return false;
        }
      }
    }
  }
  return true;
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

std::string Number(double value, const char *format = "%.3f") {
  char text[32];
  snprintf(text, sizeof(text), format, value);
  return text;
}

std::string Ratio(int64_t bytes, int64_t stock_bytes) {
  return stock_bytes > 0 ? Number(draco::UvGltfRatio(bytes, stock_bytes)) : "–";
}

// "bits (stock bits)" per TANGENT value.
std::string TangentBits(int64_t bytes, int64_t stock_bytes, int64_t values) {
  return Number(draco::TangentBitsPerValue(bytes, values), "%.2f") + " (" +
         Number(draco::TangentBitsPerValue(stock_bytes, values), "%.2f") + ")";
}

// A (scheme, tangents, qtg) variant: one table.
using Variant = std::tuple<std::string, std::string, int>;

Variant VariantOf(const draco::UvGltfEvalRow &row) {
  return {row.scheme, row.tangents, row.qtg};
}

std::string VariantLabel(const Variant &variant) {
  return "-uv_pred " + std::get<0>(variant) + " -tangent_pred " +
         std::get<1>(variant) + " -qtg " + std::to_string(std::get<2>(variant));
}

// The tangent columns of an asset or primitive: values, bytes (stock),
// ratio, bits (stock).
std::string TangentCells(int64_t values, int64_t bytes, int64_t stock_bytes) {
  if (values == 0) {
    return "| | | |";
  }
  return "| " + std::to_string(values) + " | " + std::to_string(bytes) + " (" +
         std::to_string(stock_bytes) + ") | " + Ratio(bytes, stock_bytes) +
         " | " + TangentBits(bytes, stock_bytes, values) + " |";
}

void PrintRow(const draco::UvGltfEvalRow &row) {
  printf("| %s | %d (%d, %zu) | %lld | %lld | %s | %s %s %s | %s |\n",
         row.asset.c_str(), row.primitives, row.textured_primitives,
         row.tangent_costs.size(), static_cast<long long>(row.stock_bytes),
         static_cast<long long>(row.bytes),
         Ratio(row.bytes, row.stock_bytes).c_str(),
         Ratio(row.draco_bytes, row.stock_draco_bytes).c_str(),
         TangentCells(row.tangent_values, row.tangent_bytes,
                      row.stock_tangent_bytes)
             .c_str(),
         row.requires_extension ? "yes" : "no",
         row.round_trip_ok ? "ok" : ("FAILED: " + row.detail).c_str());
  if (row.tangent_costs.size() < 2) {
    return;
  }
  for (const draco::UvGltfTangentCost &cost : row.tangent_costs) {
    printf("| %s #%s | | | | | %s | |\n", row.asset.c_str(),
           cost.primitive.c_str(),
           TangentCells(cost.values, cost.bytes, cost.stock_bytes).c_str());
  }
}

void PrintTable(const Variant &variant,
                const std::vector<draco::UvGltfEvalRow> &rows) {
  printf("\n%s\n\n", VariantLabel(variant).c_str());
  printf(
      "| asset | primitives (UVs, tangents) | stock bytes | bytes | ratio | "
      "Draco ratio | TANGENT values | tangent bytes (stock) | tangent ratio "
      "| bits/tangent (stock) | requires extension | round trip |\n");
  printf(
      "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: "
      "| --- | --- |\n");
  int64_t stock_total = 0, total = 0;
  int ok = 0, count = 0;
  for (const draco::UvGltfEvalRow &row : rows) {
    if (VariantOf(row) != variant) {
      continue;
    }
    ++count;
    ok += row.round_trip_ok;
    stock_total += row.stock_bytes;
    total += row.round_trip_ok ? row.bytes : row.stock_bytes;
    PrintRow(row);
  }
  printf(
      "| **total** (%d assets, %d round trips ok) | | %lld | %lld | %s | | | "
      "| | | | |\n",
      count, ok, static_cast<long long>(stock_total),
      static_cast<long long>(total), Ratio(total, stock_total).c_str());
}

double Median(std::vector<double> values) {
  if (values.empty()) {
    return 0;
  }
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

// One summary line per variant: medians over the assets (tangent columns
// over those with tangents) and the ratio of the totals.
void PrintSummary(const std::vector<Variant> &variants,
                  const std::vector<draco::UvGltfEvalRow> &rows) {
  printf(
      "\nSummary: medians over the assets that round-trip (tangent columns "
      "over those with tangents)\n\n"
      "| variant | assets | file ratio | Draco ratio | Draco ratio of the "
      "totals | assets with tangents | tangent ratio | min–max | "
      "bits/tangent (stock) |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: |\n");
  for (const Variant &variant : variants) {
    std::vector<double> file, draco, tangent, bits, stock_bits;
    int64_t draco_total = 0, stock_draco_total = 0;
    for (const draco::UvGltfEvalRow &row : rows) {
      if (VariantOf(row) != variant || !row.round_trip_ok) {
        continue;
      }
      file.push_back(draco::UvGltfRatio(row.bytes, row.stock_bytes));
      draco.push_back(
          draco::UvGltfRatio(row.draco_bytes, row.stock_draco_bytes));
      draco_total += row.draco_bytes;
      stock_draco_total += row.stock_draco_bytes;
      if (row.tangent_values > 0) {
        tangent.push_back(
            draco::UvGltfRatio(row.tangent_bytes, row.stock_tangent_bytes));
        bits.push_back(
            draco::TangentBitsPerValue(row.tangent_bytes, row.tangent_values));
        stock_bits.push_back(draco::TangentBitsPerValue(row.stock_tangent_bytes,
                                                        row.tangent_values));
      }
    }
    const auto range = std::minmax_element(tangent.begin(), tangent.end());
    printf("| %s | %zu | %s | %s | %s | %zu | %s | %s | %s (%s) |\n",
           VariantLabel(variant).c_str(), file.size(),
           Number(Median(file)).c_str(), Number(Median(draco)).c_str(),
           Ratio(draco_total, stock_draco_total).c_str(), tangent.size(),
           Number(Median(tangent)).c_str(),
           tangent.empty()
               ? "–"
               : (Number(*range.first) + "–" + Number(*range.second)).c_str(),
           Number(Median(bits), "%.2f").c_str(),
           Number(Median(stock_bits), "%.2f").c_str());
  }
}

void WriteCsvRow(std::ofstream &out, const draco::UvGltfEvalRow &row,
                 const std::string &primitive, int64_t values, int64_t bytes,
                 int64_t stock_bytes) {
  out << row.asset << ',' << primitive << ',' << row.scheme << ','
      << row.tangents << ',' << row.qtg << ',' << row.primitives << ','
      << row.textured_primitives << ',' << row.stock_bytes << ',' << row.bytes
      << ',' << row.stock_draco_bytes << ',' << row.draco_bytes << ',' << values
      << ',' << stock_bytes << ',' << bytes << ',' << row.requires_extension
      << ',' << row.round_trip_ok << '\n';
}

bool WriteCsv(const std::string &file,
              const std::vector<draco::UvGltfEvalRow> &rows) {
  std::ofstream out(file);
  out << "asset,primitive,scheme,tangents,qtg,primitives,textured_primitives,"
         "stock_bytes,bytes,stock_draco_bytes,draco_bytes,tangent_values,"
         "stock_tangent_bytes,tangent_bytes,requires_extension,round_trip_ok\n";
  for (const draco::UvGltfEvalRow &row : rows) {
    WriteCsvRow(out, row, "", row.tangent_values, row.tangent_bytes,
                row.stock_tangent_bytes);
    for (const draco::UvGltfTangentCost &cost : row.tangent_costs) {
      WriteCsvRow(out, row, cost.primitive, cost.values, cost.bytes,
                  cost.stock_bytes);
    }
  }
  return static_cast<bool>(out);
}

// Every asset at every -qtg; |skipped| gets the assets stock Draco fails on.
std::vector<draco::UvGltfEvalRow> Evaluate(const Args &args,
                                           const std::string &work_dir,
                                           std::vector<std::string> *skipped) {
  std::vector<draco::UvGltfEvalRow> rows;
  for (const auto &[path, name] : ListAssets(args.input)) {
    draco::UvGltfEvalOptions options = args.options;
    for (const int qtg : args.qtg) {
      if (args.progress) {
        fprintf(stderr, "%s -qtg %d\n", name.c_str(), qtg);
      }
      options.compression.quantization_bits_tangent = qtg;
      const auto asset_rows =
          draco::EvaluateGltfAsset(path, name, options, work_dir);
      if (!asset_rows.ok()) {
        skipped->push_back(name + " -qtg " + std::to_string(qtg) + ": " +
                           asset_rows.status().error_msg_string());
        continue;
      }
      rows.insert(rows.end(), asset_rows.value().begin(),
                  asset_rows.value().end());
    }
  }
  return rows;
}

}  // namespace

int main(int argc, char **argv) {
  Args args;
  if (!ParseArgs(argc, argv, &args)) {
    Usage();
    return draco::UvToolUsageExitCode(argc, argv);
  }
  if (!CheckVariants(args)) {
    return 1;
  }
  const fs::path work_dir =
      fs::temp_directory_path() /
      ("draco_uv_gltf_eval_" + std::to_string(static_cast<long>(getpid())));
  fs::create_directories(work_dir);
  std::vector<std::string> skipped;
  const std::vector<draco::UvGltfEvalRow> rows =
      Evaluate(args, work_dir.string(), &skipped);
  fs::remove_all(work_dir);

  std::vector<Variant> variants;
  for (const int qtg : args.qtg) {
    for (const std::string &scheme : args.options.schemes) {
      for (const std::string &tangents : args.options.tangents) {
        variants.emplace_back(scheme, tangents, qtg);
        PrintTable(variants.back(), rows);
      }
    }
  }
  PrintSummary(variants, rows);
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
  const bool all_ok = std::all_of(
      rows.begin(), rows.end(),
      [](const draco::UvGltfEvalRow &row) { return row.round_trip_ok; });
  return all_ok ? 0 : 1;
}
