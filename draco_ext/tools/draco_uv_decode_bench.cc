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
// draco-uv's texture coordinate coders against stock Draco's, in time and,
// with --instructions, in executed instructions (the measure of the
// decode-speed targets).
//
// Each mesh is encoded in memory like draco_encoder, once without -uv_pred
// (stock Draco's bitstream) and once per scheme ("<uv_pred>[+<uv_seams>]");
// then all its files are decoded in interleaved rounds in this one process,
// so that slow phases of a shared machine hit every variant alike, and the
// minimum over the rounds is reported. The same library decodes both (stock
// files decode exactly as with stock Draco). Our files are decoded with each
// thread cap of --threads (SetMaxThreads()): by default as shipped (a second
// thread computes stencil frames ahead) and on one thread.
//
// --instructions counts the instructions executed inside
// Decoder::DecodeMeshFromBuffer for every file, on one thread: this tool
// decodes the file once more in a child process under valgrind's callgrind
// (--toggle-collect on that function) and reads the total from callgrind's
// profile. Instruction counts do not depend on the load of a shared machine,
// and this VM exposes no hardware counters (perf_event_open fails), so
// callgrind is the exact and portable way; in-process client requests would
// need the whole tool, encoders included, to run under valgrind.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

#include "draco/compression/decode.h"
#include "draco/io/file_utils.h"
#include "draco/io/mesh_io.h"
#include "draco/mesh/mesh_misc_functions.h"
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
  bool instructions = false;
  std::string profiles;     // Folder that keeps callgrind's profiles.
  std::string decode_file;  // Child mode: decode this file once.
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
      "  --rounds N       decodes of every file, default 30\n"
      "  --instructions   also instructions inside DecodeMeshFromBuffer on\n"
      "                   one thread (runs valgrind --tool=callgrind), and\n"
      "                   the mesh's interior edges\n"
      "  --profiles DIR   keep callgrind's profiles there, one per file\n"
      "                   (<mesh>.<scheme>.callgrind; implies --instructions)\n"
      "  --decode-file F  decode the Draco file F once on one thread and\n"
      "                   exit (what --instructions runs under callgrind)\n");
}

bool ParseFlag(const std::string &flag, const char *value, Args *args) {
  int *target = flag == "--qp"   ? &args->settings.qp
                : flag == "--qt" ? &args->settings.qt
                : flag == "--cl" ? &args->settings.cl
                                 : nullptr;
  if (target != nullptr) {
    return draco::ParseUvToolSetting(value, target);
  }
  if (flag == "--rounds") {
    return draco::ParseUvToolInt(value, 1, 100000, &args->rounds);
  }
  if (flag == "--schemes") {
    args->schemes = draco::SplitUvToolList(value);
    return true;
  }
  if (flag == "--profiles" || flag == "--decode-file") {
    (flag == "--profiles" ? args->profiles : args->decode_file) = value;
    args->instructions = args->instructions || flag == "--profiles";
    return *value != '\0';
  }
  if (flag == "--threads") {
    args->threads.clear();
    for (const std::string &item : draco::SplitUvToolList(value)) {
      int threads = 0;
      if (!draco::ParseUvToolInt(item, 1, 30, &threads)) {
        return false;
      }
      args->threads.push_back(threads);
    }
    return true;
  }
  return false;
}

bool ParseArgs(int argc, char **argv, Args *args) {
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--instructions") {
      args->instructions = true;
    } else if (flag.rfind("--", 0) == 0 && i + 1 < argc) {
      if (!ParseFlag(flag, argv[++i], args)) {
        return false;
      }
    } else if (args->input.empty() && flag.rfind("-", 0) != 0) {
      args->input = flag;
    } else {
      return false;
    }
  }
  if (!args->decode_file.empty()) {
    return args->input.empty();
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

// "draco" (stock Draco's file) and then every scheme.
std::vector<std::string> FileNames(const Args &args) {
  std::vector<std::string> names = {"draco"};
  names.insert(names.end(), args.schemes.begin(), args.schemes.end());
  return names;
}

// The files of |mesh|: stock Draco's first, then one per scheme.
bool EncodeVariants(const draco::Mesh &mesh, const Args &args,
                    std::vector<std::vector<char>> *files) {
  for (const std::string &name : FileNames(args)) {
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

// The child of --instructions: decodes the file once on one thread.
int DecodeFileOnce(const std::string &path) {
  std::vector<char> bytes;
  if (!draco::ReadFileToBuffer(path, &bytes)) {
    fprintf(stderr, "Error: cannot read %s\n", path.c_str());
    return 1;
  }
  draco::SetMaxThreads(1);
  if (DecodeMs(bytes) < 0) {
    fprintf(stderr, "Error: cannot decode %s\n", path.c_str());
    return 1;
  }
  return 0;
}

// The total of callgrind's profile |path| (its "summary:" or "totals:"
// line), or -1.
double ProfileTotal(const std::string &path) {
  std::ifstream profile(path);
  std::string line;
  double total = -1;
  while (std::getline(profile, line)) {
    if (line.rfind("summary: ", 0) == 0 || line.rfind("totals: ", 0) == 0) {
      total = std::strtod(line.c_str() + line.find(' '), nullptr);
    }
  }
  return total;
}

// The path of this tool's executable.
std::string SelfPath() {
  char path[4096];
  const ssize_t length = readlink("/proc/self/exe", path, sizeof(path) - 1);
  return std::string(path, length > 0 ? length : 0);
}

// "khr_dragon" for ".../khr_dragon.obj".
std::string MeshName(const std::string &path) {
  const std::string file = path.substr(path.rfind('/') + 1);
  return file.substr(0, file.rfind('.'));
}

// Instructions executed inside Decoder::DecodeMeshFromBuffer when this tool
// decodes |bytes| on one thread under callgrind, or -1 on failure. The file
// and the profile are written to |folder| as |stem| + ".drc" / ".callgrind".
double CountInstructions(const std::vector<char> &bytes,
                         const std::string &folder, const std::string &stem) {
  const std::string file = folder + "/" + stem + ".drc";
  const std::string profile = folder + "/" + stem + ".callgrind";
  if (!draco::WriteBufferToFile(bytes.data(), bytes.size(), file)) {
    return -1;
  }
  const std::string command =
      "valgrind --tool=callgrind --collect-atstart=no "
      "'--toggle-collect=draco::Decoder::DecodeMeshFromBuffer(*)' "
      "'--callgrind-out-file=" + profile + "' '" + SelfPath() +
      "' --decode-file '" + file +
      "' >/dev/null 2>'" + folder + "/" + stem + ".log'";
  const int status = std::system(command.c_str());
  std::remove(file.c_str());
  return status == 0 ? ProfileTotal(profile) : -1;
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

// Edges of |mesh| with a triangle on both sides in Draco's position
// connectivity: where Edgebreaker codes a seam bit per attribute.
int InteriorEdges(const draco::Mesh &mesh) {
  const auto table = draco::CreateCornerTableFromPositionAttribute(&mesh);
  int corners = 0;
  for (draco::CornerIndex c(0); c < table->num_corners(); ++c) {
    corners += table->Opposite(c) != draco::kInvalidCornerIndex;
  }
  return corners / 2;
}

// Instructions of every file (stock Draco's first), written to |folder| as
// <mesh>.<name>; empty when one cannot be counted.
std::vector<double> CountAll(const std::vector<std::vector<char>> &files,
                             const std::vector<std::string> &names,
                             const std::string &mesh,
                             const std::string &folder) {
  std::vector<double> counts;
  for (size_t i = 0; i < files.size(); ++i) {
    counts.push_back(
        CountInstructions(files[i], folder, mesh + "." + names[i]));
    if (counts.back() <= 0) {
      fprintf(stderr, "Error: callgrind failed on %s %s (see %s)\n",
              mesh.c_str(), names[i].c_str(), folder.c_str());
      return {};
    }
  }
  return counts;
}

// The table's header: times, then with --instructions the interior edges
// and the instructions of stock Draco's file and of every scheme.
void PrintHeader(const Args &args, const std::vector<std::string> &columns) {
  std::string header = "| mesh | stock ms |", rule = "| --- | ---: |";
  for (const std::string &column : columns) {
    header += " " + column + " ms | ratio |";
    rule += " ---: | ---: |";
  }
  if (args.instructions) {
    header += " interior edges | stock instr |";
    rule += " ---: | ---: |";
    for (const std::string &scheme : args.schemes) {
      header += " " + scheme + " instr | ratio |";
      rule += " ---: | ---: |";
    }
  }
  printf("%s\n%s\n", header.c_str(), rule.c_str());
}

// The folder of the profiles: --profiles, or a new temporary one.
std::string ProfileFolder(const Args &args) {
  if (!args.profiles.empty()) {
    std::filesystem::create_directories(args.profiles);
    return args.profiles;
  }
  char name[] = "/tmp/draco_uv_decode_bench.XXXXXX";
  return mkdtemp(name) != nullptr ? name : "";
}

}  // namespace

int main(int argc, char **argv) {
  Args args;
  if (!ParseArgs(argc, argv, &args)) {
    Usage();
    return draco::UvToolUsageExitCode(argc, argv);
  }
  if (!args.decode_file.empty()) {
    return DecodeFileOnce(args.decode_file);
  }
  const std::string folder = args.instructions ? ProfileFolder(args) : "";
  if (args.instructions && (folder.empty() || std::system(
          "valgrind --version >/dev/null 2>&1") != 0)) {
    fprintf(stderr, "Error: --instructions needs valgrind on the PATH and a "
                    "writable folder for its profiles.\n");
    return 1;
  }
  draco::SetMaxThreads(args.threads[0]);
  const std::vector<std::string> columns = ColumnNames(args);
  PrintHeader(args, columns);
  std::vector<std::vector<double>> ratios(columns.size());
  std::vector<std::vector<double>> instruction_ratios(args.schemes.size());
  int failures = 0;
  for (const std::string &path : draco::ListMeshFiles(args.input)) {
    const std::string name = MeshName(path);
    auto mesh = draco::ReadMeshFromFile(path);
    std::vector<std::vector<char>> files;
    if (!mesh.ok() || !EncodeVariants(*mesh.value(), args, &files)) {
      fprintf(stderr, "Error: cannot encode %s\n", path.c_str());
      ++failures;
      continue;
    }
    const std::vector<double> ms =
        MinDecodeMs(files, args.threads, args.rounds);
    const std::vector<double> instructions =
        args.instructions ? CountAll(files, FileNames(args), name, folder)
                          : std::vector<double>();
    if (ms.empty() || (args.instructions && instructions.empty())) {
      fprintf(stderr, "Error: cannot decode %s\n", path.c_str());
      ++failures;
      continue;
    }
    printf("| %s | %.3f |", path.substr(path.rfind('/') + 1).c_str(), ms[0]);
    for (size_t c = 0; c < columns.size(); ++c) {
      ratios[c].push_back(ms[c + 1] / ms[0]);
      printf(" %.3f | %.3f |", ms[c + 1], ratios[c].back());
    }
    if (args.instructions) {
      printf(" %d | %.0f |", InteriorEdges(*mesh.value()), instructions[0]);
      for (size_t s = 0; s < args.schemes.size(); ++s) {
        instruction_ratios[s].push_back(instructions[s + 1] / instructions[0]);
        printf(" %.0f | %.4f |", instructions[s + 1],
               instruction_ratios[s].back());
      }
    }
    printf("\n");
    fflush(stdout);
  }
  PrintSummary(columns, ratios);
  if (args.instructions) {
    std::vector<std::string> names;
    for (const std::string &scheme : args.schemes) {
      names.push_back(scheme + " instructions");
    }
    PrintSummary(names, instruction_ratios);
    if (args.profiles.empty()) {
      std::filesystem::remove_all(folder);
    }
  }
  return failures == 0 ? 0 : 1;
}
