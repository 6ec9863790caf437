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
#include "draco_ext/options/draco_uv_flags.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <limits>

namespace draco {

namespace {

// Up to this many edits (insertion, deletion, substitution or swap of two
// neighbours, after normalising: see Normalised()) from a flag of the table
// an unknown flag counts as a misspelling of it: "uv_pred" and "uvpred" are
// one edit apart, "uv_prde" one, "uv_pd" two. The flags of the table that
// carry stock Draco's names (-qtg) take no part: no flag of stock Draco's
// tools is within two edits of the others.
constexpr size_t kNearMiss = 2;
// Up to this many edits a flag of the family is suggested as the one meant.
constexpr size_t kSuggestion = 3;

// Stock Draco's flags that take a value (draco_encoder and
// draco_transcoder): as the last argument, the stock loops skip them.
constexpr const char *kStockValueFlags[] = {"-i",  "-o",  "-qp",   "-qt",
                                            "-qn", "-qg", "-qc",   "-qtg",
                                            "-qw", "-cl", "--skip"};

// |flag| as compared with the table: without leading dashes and any
// "=value", lower case, '-' as '_' ("--UV-Pred=auto" -> "uv_pred").
std::string Normalised(const std::string &flag) {
  const size_t begin = std::min(flag.find_first_not_of('-'), flag.size());
  std::string name = flag.substr(begin, flag.find('=', begin) - begin);
  for (char &c : name) {
    c = c == '-'
            ? '_'
            : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return name;
}

// Optimal string alignment distance: insertions, deletions, substitutions
// and swaps of neighbours.
size_t EditDistance(const std::string &a, const std::string &b) {
  const size_t n = a.size();
  const size_t m = b.size();
  std::vector<std::vector<size_t>> d(n + 1, std::vector<size_t>(m + 1));
  for (size_t i = 0; i <= n; ++i) {
    d[i][0] = i;
  }
  for (size_t j = 0; j <= m; ++j) {
    d[0][j] = j;
  }
  for (size_t i = 1; i <= n; ++i) {
    for (size_t j = 1; j <= m; ++j) {
      const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] =
          std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

bool StartsWith(const std::string &text, const std::string &prefix) {
  return text.compare(0, prefix.size(), prefix) == 0;
}

// A number ("-1", "-0.5"): the value of a flag, never a flag.
bool IsNumber(const std::string &arg) {
  char *end = nullptr;
  std::strtod(arg.c_str(), &end);
  return end != arg.c_str() && *end == '\0';
}

std::string FlagList(const std::vector<const char *> &flags) {
  std::string list;
  for (const char *flag : flags) {
    list += (list.empty() ? "" : ", ") + std::string(flag);
  }
  return list;
}

}  // namespace

const std::vector<const char *> &DracoUvFlagNames() {
  // One line per flag; uv_compression_options.h parses the -uv_ ones,
  // tangent_compression_options.h the tangent ones.
  static const std::vector<const char *> flags = {
      "-uv_pred",          // TEX_COORD prediction scheme
      "-uv_anchors",       // extra anchors of -uv_pred laplacian_*
      "-uv_rmse",          // error target in UV units
      "-uv_texels",        // error target in texels
      "-uv_texture_size",  // texels of -uv_texels' texture
      "-uv_decode_limit",  // decode cost limit of an error target's choice
      "-uv_seams",         // attribute seam coding
      "-tangent_pred",     // tangent prediction scheme
      "-qtg",              // tangent quantization (draco_encoder)
  };
  return flags;
}

const std::vector<const char *> &DracoUvFlagFamilies() {
  static const std::vector<const char *> families = {"-uv_", "-tangent_"};
  return families;
}

bool IsStockToolValueFlag(const std::string &arg) {
  return std::any_of(std::begin(kStockValueFlags), std::end(kStockValueFlags),
                     [&arg](const char *flag) { return arg == flag; });
}

UnhandledToolArg ClassifyUnhandledToolArg(
    const std::string &tool, const std::string &arg, bool is_last,
    const std::vector<const char *> &known_flags,
    const std::vector<const char *> &families) {
  UnhandledToolArg result;
  if (arg.size() < 2 || arg[0] != '-' || IsNumber(arg)) {
    return result;  // A value, a file name, "-": stock Draco skips it.
  }
  for (const char *flag : known_flags) {
    if (arg == flag && !IsStockToolValueFlag(arg)) {
      // The table has it, the tool has no branch for it.
      result.kind = UnhandledToolArg::kError;
      result.message = arg + " is not a flag of " +
                       (tool.empty() ? std::string("this tool") : tool);
      return result;
    }
  }
  const std::string name = Normalised(arg);
  size_t family_prefix = 0;
  for (const char *family : families) {
    if (StartsWith(name, Normalised(family))) {
      family_prefix = std::max(family_prefix, Normalised(family).size());
    }
  }
  size_t best_distance = std::numeric_limits<size_t>::max();
  const char *best = nullptr;
  const char *completion = nullptr;  // First flag that |name| begins.
  for (const char *flag : known_flags) {
    if (IsStockToolValueFlag(flag)) {
      continue;  // A stock name: its look-alikes are stock's flags.
    }
    const std::string known = Normalised(flag);
    // The distance is at least the difference in length: skip long args.
    const size_t length_gap = std::max(name.size(), known.size()) -
                              std::min(name.size(), known.size());
    if (length_gap <= kSuggestion) {
      const size_t distance = EditDistance(name, known);
      if (distance < best_distance) {
        best_distance = distance;
        best = flag;
      }
    }
    if (completion == nullptr && name.size() > family_prefix &&
        StartsWith(known, name)) {
      completion = flag;
    }
  }
  if (family_prefix == 0 && best_distance > kNearMiss) {
    result.kind = UnhandledToolArg::kWarn;
    result.message = is_last && IsStockToolValueFlag(arg)
                         ? "ignoring " + arg + ": no value follows it"
                         : "ignoring unknown flag " + arg;
    return result;
  }
  result.kind = UnhandledToolArg::kError;
  result.message = "unknown flag " + arg;
  if (best_distance <= kSuggestion) {
    result.suggestion = best;
  } else if (completion != nullptr) {
    result.suggestion = completion;
  }
  if (!result.suggestion.empty()) {
    // "-uv_pred=auto": suggest the flag and its value as two arguments.
    const size_t equals = arg.find('=');
    const std::string value =
        equals == std::string::npos ? "" : arg.substr(equals + 1);
    result.message += "; did you mean " + result.suggestion +
                      (value.empty() ? "" : " " + value) + "?";
  } else {
    result.message +=
        "; this build's draco-uv flags are " + FlagList(known_flags) + ".";
  }
  return result;
}

UnhandledToolArg ClassifyUnhandledToolArg(const std::string &tool,
                                          const std::string &arg,
                                          bool is_last) {
  return ClassifyUnhandledToolArg(tool, arg, is_last, DracoUvFlagNames(),
                                  DracoUvFlagFamilies());
}

bool CheckUnhandledToolArg(int argc, char **argv, int index, FILE *messages) {
  if (index <= 0 || index >= argc || argv[index] == nullptr) {
    return true;
  }
  std::string tool = argv[0] == nullptr ? "" : argv[0];
  tool = tool.substr(tool.find_last_of("/\\") + 1);
  const UnhandledToolArg verdict =
      ClassifyUnhandledToolArg(tool, argv[index], index + 1 == argc);
  switch (verdict.kind) {
    case UnhandledToolArg::kIgnore:
      return true;
    case UnhandledToolArg::kWarn:
      std::fprintf(messages, "Warning: %s\n", verdict.message.c_str());
      return true;
    case UnhandledToolArg::kError:
      std::fprintf(messages, "Error: %s\n", verdict.message.c_str());
      return false;
  }
  return true;
}

std::string UnknownToolFlagUsage() {
  const std::vector<const char *> &families = DracoUvFlagFamilies();
  std::string prefixes;
  for (size_t i = 0; i < families.size(); ++i) {
    prefixes += (i == 0                    ? ""
                 : i + 1 < families.size() ? ", "
                                           : " or ") +
                std::string(families[i]);
  }
  return "\nUnknown flags: one that looks like draco-uv's is an error (it "
         "starts\nwith " +
         prefixes +
         ", or is a near miss such as -uvpred); any other\n"
         "unknown flag is ignored with a warning.\n";
}

}  // namespace draco
