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
// draco_uv_eval: how much each UV coder saves on a mesh or a folder of
// meshes, in the terms of [Váša & Brunnett 2014] section 6, and on meshes
// with tangents what each tangent coder saves.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "draco/io/mesh_io.h"
#include "draco_ext/eval/uv_eval.h"
#include "draco_ext/eval/uv_eval_report.h"
#include "draco_ext/options/uv_compression_options.h"
#include "draco_ext/tools/uv_tool_args.h"

namespace {

namespace fs = std::filesystem;

struct Args {
  std::string input;
  draco::UvEvalOptions options;
  std::string csv;
  std::string tangent_csv;
  std::string plot;
  bool progress = true;
  std::vector<double> texels;  // --texels, in texels of --texture_size.
  int texture_size = draco::UvCompressionOptions::kDefaultTextureSize;
};

void Usage() {
  // fputs: the text has percent signs.
  fputs(
      "Usage: draco_uv_eval <mesh or folder> [options]\n"
      "\n"
      "Encodes and decodes every mesh (OBJ, PLY, glTF, GLB) with each UV\n"
      "coder and reports UV bytes, bits per UV vertex, RMSE (eq. 9 of Vasa &\n"
      "Brunnett 2014), times and the ratio to stock Draco's best of -cl 7/10.\n"
      "\n"
      "  --qt LIST        texture coordinate quantization bits, default 10,12\n"
      "  --qp N           position quantization bits, default 14\n"
      "  --cl N           compression level, default 10\n"
      "  --schemes LIST   -uv_pred names, default "
      "draco,parallelogram,portable,multi_parallelogram,weighted,auto\n"
      "  --seams LIST     -uv_seams names (draco, context), each with every\n"
      "                   scheme, default draco; a scheme may name its own\n"
      "                   as <scheme>+<seams>, e.g. weighted+context\n"
      "  --uv_anchors K   -uv_anchors of the laplacian_* schemes (K, P%, "
      "random:K\n"
      "                   or random:P%), default: greedy, 0.65% of the\n"
      "                   texture coordinates + 6% of the boundary ones\n"
      "  --tangents LIST  -tangent_pred names measured with every scheme on\n"
      "                   meshes with tangents (glTF TANGENT), default\n"
      "                   draco,auto (draco: the scheme alone). Tangent bytes\n"
      "                   are size with minus without the tangents, same\n"
      "                   flags; bits per tangent value are 8 x those bytes /\n"
      "                   the mesh's points (one TANGENT value each, as glTF\n"
      "                   stores them per vertex); ratios are to stock Draco\n"
      "                   at the same qt and qtg; the round trip checks the\n"
      "                   decoded tangents against stock coding's\n"
      "  --qtg LIST       tangent quantization bits (-qtg), default 8\n"
      "  --rmse LIST      error targets (RMSE, UV units): one row each, "
      "scheme\n"
      "                   rmse, of what draco_encoder -uv_rmse R writes\n"
      "  --texels LIST    error targets in texels of a --texture_size texture\n"
      "  --texture_size N texels of that texture, default 4096\n"
      "  --repeat N       timing runs (minimum reported), default 3\n"
      "  --csv FILE       one row per (mesh, scheme, qt)\n"
      "  --tangent_csv FILE  one row per (mesh, scheme, tangents, qt, qtg)\n"
      "  --plot FILE      rate-distortion chart (PNG or SVG, needs python3 "
      "with matplotlib)\n"
      "  --quiet          no progress on stderr\n",
      stdout);
}

// A comma-separated list of quantization bits, 1 to 30.
bool ParseBitsList(const std::string &flag, const std::string &list,
                   std::vector<int> *values) {
  values->clear();
  for (const std::string &item : draco::SplitUvToolList(list)) {
    int bits;
    if (!draco::ParseUvToolInt(item, 1, 30, &bits)) {
      fprintf(stderr, "Error: bad %s value '%s'.\n", flag.c_str(),
              item.c_str());
      return false;
    }
    values->push_back(bits);
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
    } else if (!has_value && flag.rfind("--", 0) == 0) {
      fprintf(stderr, "Error: %s needs a value.\n", flag.c_str());
      return false;
    } else if (flag == "--qt" || flag == "--qtg") {
      if (!ParseBitsList(
              flag, argv[++i],
              flag == "--qt" ? &args->options.qt : &args->options.qtg)) {
        return false;
      }
    } else if (flag == "--qp" || flag == "--cl" || flag == "--repeat") {
      int *target = flag == "--qp"   ? &args->options.qp
                    : flag == "--cl" ? &args->options.cl
                                     : &args->options.repeat;
      if (!draco::ParseUvToolSetting(argv[++i], target)) {
        fprintf(stderr, "Error: bad %s value '%s'.\n", flag.c_str(), argv[i]);
        return false;
      }
    } else if (flag == "--schemes") {
      args->options.schemes = draco::SplitUvToolList(argv[++i]);
    } else if (flag == "--seams") {
      args->options.seams = draco::SplitUvToolList(argv[++i]);
    } else if (flag == "--tangents") {
      args->options.tangents = draco::SplitUvToolList(argv[++i]);
    } else if (flag == "--uv_anchors") {
      const auto anchors = draco::ParseUvAnchorSpec(argv[++i]);
      if (!anchors.ok()) {
        fprintf(stderr, "Error: %s\n", anchors.status().error_msg());
        return false;
      }
      args->options.uv_anchors = anchors.value();
    } else if (flag == "--rmse" || flag == "--texels") {
      for (const std::string &item : draco::SplitUvToolList(argv[++i])) {
        const auto target = draco::ParseUvErrorTarget(flag, item);
        if (!target.ok()) {
          fprintf(stderr, "Error: %s\n", target.status().error_msg());
          return false;
        }
        (flag == "--rmse" ? args->options.rmse_targets : args->texels)
            .push_back(target.value());
      }
    } else if (flag == "--texture_size") {
      if (!draco::ParseUvToolInt(argv[++i], 1, 1 << 24, &args->texture_size)) {
        fprintf(stderr, "Error: bad --texture_size value '%s'.\n", argv[i]);
        return false;
      }
    } else if (flag == "--csv") {
      args->csv = argv[++i];
    } else if (flag == "--tangent_csv") {
      args->tangent_csv = argv[++i];
    } else if (flag == "--plot") {
      args->plot = argv[++i];
    } else if (args->input.empty() && flag.rfind("-", 0) != 0) {
      args->input = flag;
    } else {
      fprintf(stderr, "Error: unknown argument '%s'.\n", flag.c_str());
      return false;
    }
  }
  for (const double texels : args->texels) {  // As -uv_texels computes it.
    draco::UvCompressionOptions target;
    target.texels = texels;
    target.texture_size = args->texture_size;
    args->options.rmse_targets.push_back(*target.MaxUvRmse());
  }
  return !args->input.empty() && !args->options.qt.empty() &&
         !args->options.schemes.empty() && !args->options.seams.empty() &&
         !args->options.tangents.empty() && !args->options.qtg.empty();
}

}  // namespace

int main(int argc, char **argv) {
  Args args;
  if (!ParseArgs(argc, argv, &args)) {
    Usage();
    return draco::UvToolUsageExitCode(argc, argv);
  }
  const fs::path input(args.input);
  if (!fs::exists(input)) {
    fprintf(stderr, "Error: %s does not exist.\n", args.input.c_str());
    return 1;
  }
  const std::vector<std::string> files = draco::ListMeshFiles(args.input);
  const std::vector<fs::path> meshes(files.begin(), files.end());
  if (meshes.empty()) {
    fprintf(stderr, "Error: no OBJ, PLY, glTF or GLB files in %s.\n",
            args.input.c_str());
    return 1;
  }
  draco::UvEvalReport report(draco::ReadMeshKinds(input));
  int failures = 0;
  for (size_t i = 0; i < meshes.size(); ++i) {
    const std::string name = meshes[i].stem().string();
    if (args.progress) {
      fprintf(stderr, "[%zu/%zu] %s\n", i + 1, meshes.size(), name.c_str());
    }
    auto mesh = draco::ReadMeshFromFile(meshes[i].string());
    if (!mesh.ok()) {
      fprintf(stderr, "Error: cannot read %s: %s\n", meshes[i].c_str(),
              mesh.status().error_msg());
      ++failures;
      continue;
    }
    auto rows = draco::EvaluateMesh(name, *mesh.value(), args.options);
    auto tangent_rows =
        rows.ok()
            ? draco::EvaluateMeshTangents(name, *mesh.value(), args.options)
            : draco::StatusOr<std::vector<draco::TangentEvalRow>>(
                  rows.status());
    if (!tangent_rows.ok()) {
      fprintf(stderr, "Error: %s\n", tangent_rows.status().error_msg());
      ++failures;
      continue;
    }
    report.Add(rows.value());
    report.AddTangents(tangent_rows.value());
    printf("%s\n", draco::FormatMeshTable(rows.value()).c_str());
    if (!tangent_rows.value().empty()) {
      printf("%s\n", draco::FormatTangentTable(tangent_rows.value()).c_str());
    }
  }
  printf("%s", report.FormatSummary().c_str());
  if (!args.csv.empty() && !report.WriteCsv(args.csv)) {
    fprintf(stderr, "Error: cannot write %s\n", args.csv.c_str());
    return 1;
  }
  if (!args.tangent_csv.empty() && !report.WriteTangentCsv(args.tangent_csv)) {
    fprintf(stderr, "Error: cannot write %s\n", args.tangent_csv.c_str());
    return 1;
  }
  if (!args.plot.empty() && !report.WritePlot(args.plot)) {
    fprintf(stderr, "Error: cannot write the chart %s\n", args.plot.c_str());
    return 1;
  }
  if (!report.AllRoundTripsOk()) {
    fprintf(stderr,
            "Error: a round trip did not reproduce the UVs or tangents.\n");
    return 2;
  }
  return failures == 0 ? 0 : 1;
}
