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
// draco_uv_decode_bench: how long decoding a whole mesh takes with
// draco-uv's texture coordinate coders against stock Draco's, the
// decode-time target of the weighted prediction (at most 1.1x stock).
//
// Each mesh is encoded in memory like draco_encoder, once without -uv_pred
// (stock Draco's bitstream) and once per scheme; then all its files are
// decoded in interleaved rounds in this one process, so that slow phases
// of a shared machine hit every variant alike, and the minimum over the
// rounds is reported. The same library decodes both (stock files decode
// exactly as with stock Draco). Our files are decoded with each thread cap
// of --threads (SetMaxThreads()): by default as shipped (a second thread
// computes stencil frames ahead) and on one thread.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "draco/compression/decode.h"
#include "draco/io/mesh_io.h"
#include "draco_ext/tools/uv_tool_args.h"
#include "draco_ext/options/uv_encode_settings.h"
#include "draco_ext/eval/uv_eval.h"
#include "draco_ext/common/threads.h"

namespace {

struct Args {
  std::string input;
  draco::UvEncodeSettings settings;
  std::vector<std::string> schemes = {"auto"};
  std::vector<int> threads = {2, 1};
  int rounds = 30;
};

void Usage() {
  printf(
      "Usage: draco_uv_decode_bench <mesh or folder> [options]\n"
      "Decoding time of each -uv_pred scheme against stock Draco, whole\n"
      "mesh from memory, minimum of interleaved rounds.\n"
      "\n"
      "  --schemes LIST   <uv_pred>[+<uv_seams>] names, default auto\n"
      "  --qp N --qt N --cl N   default 14, 12, 10\n"
      "  --threads LIST   thread caps for our files, default 2,1\n"
      "  --rounds N       decodes of every file, default 30\n");
}

bool ParseArgs(int argc, char **argv, Args *args) {
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    const bool has_value = i + 1 < argc;
    int *target = flag == "--qp"   ? &args->settings.qp
                  : flag == "--qt" ? &args->settings.qt
                  : flag == "--cl" ? &args->settings.cl
                                   : nullptr;
    if (target != nullptr && has_value) {
      if (!draco::ParseUvToolSetting(argv[++i], target)) {
        return false;
      }
    } else if (flag == "--rounds" && has_value) {
      if (!draco::ParseUvToolInt(argv[++i], 1, 100000, &args->rounds)) {
        return false;
      }
    } else if (flag == "--schemes" && has_value) {
      args->schemes = draco::SplitUvToolList(argv[++i]);
    } else if (flag == "--threads" && has_value) {
      args->threads.clear();
      for (const std::string &item : draco::SplitUvToolList(argv[++i])) {
        int threads = 0;
        if (!draco::ParseUvToolInt(item, 1, 30, &threads)) {
          return false;
        }
        args->threads.push_back(threads);
      }
    } else if (args->input.empty() && flag.rfind("-", 0) != 0) {
      args->input = flag;
    } else {
      return false;
    }
  }
  return !args->input.empty() && !args->schemes.empty() &&
         !args->threads.empty() && args->rounds > 0;
}

// Milliseconds to decode |bytes|, or a negative value when decoding fails.
double DecodeMs(const std::vector<char> &bytes) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  draco::Decoder decoder;
  const auto start = std::chrono::steady_clock::now();
  const auto mesh = decoder.DecodeMeshFromBuffer(&buffer);
  const auto end = std::chrono::steady_clock::now();
  return mesh.ok() ? std::chrono::duration<double, std::milli>(end - start)
                         .count()
                   : -1.0;
}

// Encodes |mesh| with |settings| and the scheme |name| ("<uv_pred>[+<seams>]").
draco::Status EncodeScheme(const draco::Mesh &mesh,
                           draco::UvEncodeSettings settings,
                           const std::string &name,
                           draco::EncoderBuffer *buffer) {
  DRACO_ASSIGN_OR_RETURN(settings.uv, draco::ParseUvSchemeName(name));
  return draco::EncodeMeshWithSettings(mesh, settings, buffer);
}

// The files of |mesh|: stock Draco's first, then one per scheme.
bool EncodeVariants(const draco::Mesh &mesh, const Args &args,
                    std::vector<std::vector<char>> *files) {
  std::vector<std::string> names = {"draco"};
  names.insert(names.end(), args.schemes.begin(), args.schemes.end());
  for (const std::string &name : names) {
    draco::EncoderBuffer buffer;
    const draco::Status status =
        EncodeScheme(mesh, args.settings, name, &buffer);
    if (!status.ok()) {
      fprintf(stderr, "Error: scheme '%s': %s\n", name.c_str(),
              status.error_msg());
      return false;
    }
    files->emplace_back(buffer.data(), buffer.data() + buffer.size());
  }
  return true;
}

// Minimum decoding time over interleaved rounds of stock Draco's file (first)
// and of every other file under every thread cap (file-major); empty when a
// file fails to decode.
std::vector<double> MinDecodeMs(const std::vector<std::vector<char>> &files,
                                const std::vector<int> &threads, int rounds) {
  std::vector<double> best(1 + (files.size() - 1) * threads.size(), 1e30);
  for (int round = 0; round < rounds; ++round) {
    for (size_t i = 0, k = 0; i < files.size(); ++i) {
      for (size_t t = 0; t < (i == 0 ? 1 : threads.size()); ++t, ++k) {
        draco::SetMaxThreads(threads[t]);
        const double ms = DecodeMs(files[i]);
        if (ms < 0) {
          return {};
        }
        best[k] = std::min(best[k], ms);
      }
    }
  }
  draco::SetMaxThreads(threads[0]);
  return best;
}

// "auto" for the first thread cap, "auto 1 thread" and so on for others.
std::vector<std::string> ColumnNames(const Args &args) {
  std::vector<std::string> names;
  for (const std::string &scheme : args.schemes) {
    for (size_t t = 0; t < args.threads.size(); ++t) {
      names.push_back(
          t == 0 ? scheme
                 : scheme + " " + std::to_string(args.threads[t]) +
                       (args.threads[t] == 1 ? " thread" : " threads"));
    }
  }
  return names;
}

void PrintSummary(const std::vector<std::string> &schemes,
                  const std::vector<std::vector<double>> &ratios) {
  for (size_t s = 0; s < schemes.size(); ++s) {
    std::vector<double> r = ratios[s];
    if (r.empty()) {
      continue;
    }
    std::sort(r.begin(), r.end());
    const size_t within = std::count_if(r.begin(), r.end(),
                                        [](double x) { return x <= 1.1; });
    printf("%s: median %.3f, max %.3f, %zu of %zu meshes within 1.1x\n",
           schemes[s].c_str(), r[r.size() / 2], r.back(), within, r.size());
  }
}

}  // namespace

int main(int argc, char **argv) {
  Args args;
  if (!ParseArgs(argc, argv, &args)) {
    Usage();
    return draco::UvToolUsageExitCode(argc, argv);
  }
  draco::SetMaxThreads(args.threads[0]);
  const std::vector<std::string> columns = ColumnNames(args);
  std::string header = "| mesh | stock ms |", rule = "| --- | ---: |";
  for (const std::string &column : columns) {
    header += " " + column + " ms | ratio |";
    rule += " ---: | ---: |";
  }
  printf("%s\n%s\n", header.c_str(), rule.c_str());
  std::vector<std::vector<double>> ratios(columns.size());
  int failures = 0;
  for (const std::string &path : draco::ListMeshFiles(args.input)) {
    auto mesh = draco::ReadMeshFromFile(path);
    std::vector<std::vector<char>> files;
    if (!mesh.ok() || !EncodeVariants(*mesh.value(), args, &files)) {
      fprintf(stderr, "Error: cannot encode %s\n", path.c_str());
      ++failures;
      continue;
    }
    const std::vector<double> ms =
        MinDecodeMs(files, args.threads, args.rounds);
    if (ms.empty()) {
      fprintf(stderr, "Error: cannot decode %s\n", path.c_str());
      ++failures;
      continue;
    }
    printf("| %s | %.3f |", path.substr(path.rfind('/') + 1).c_str(), ms[0]);
    for (size_t c = 0; c < columns.size(); ++c) {
      ratios[c].push_back(ms[c + 1] / ms[0]);
      printf(" %.3f | %.3f |", ms[c + 1], ratios[c].back());
    }
    printf("\n");
    fflush(stdout);
  }
  PrintSummary(columns, ratios);
  return failures == 0 ? 0 : 1;
}
