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
// The table of draco-uv's command-line flags, and what draco_encoder
// (patches/0004) and draco_transcoder (patches/0011) do with an argument
// that none of their flags took: CheckUnhandledToolArg(), called from the
// last branch of each tool's argument loop, where stock Draco skips the
// argument without a word.
//
//   * A flag that looks like one of draco-uv's is an error: its name starts
//     with a family prefix (-uv_, -tangent_), or it is a near miss of a flag
//     of the table (--uv_pred, -uvpred, -UV_PRED, -uv-pred, -uv_prde). The
//     message names the closest flag of the table: "unknown flag -uv_prd;
//     did you mean -uv_pred?". A typo must not quietly write a stock file.
//   * Any other flag (stock Draco's tools' own unknown flags, -foo) is
//     ignored, as in stock Draco, with a warning.
//   * Anything else (values, file names, negative numbers, "-") is ignored
//     silently, as in stock Draco: the value of an unknown flag must not be
//     reported as one more flag.
#ifndef DRACO_EXT_OPTIONS_DRACO_UV_FLAGS_H_
#define DRACO_EXT_OPTIONS_DRACO_UV_FLAGS_H_

#include <cstdio>
#include <string>
#include <vector>

namespace draco {

// Every flag of draco-uv's command-line tools, in the order -h lists them.
// A new flag is one entry of this table (draco_uv_flags.cc), next to its
// parser.
const std::vector<const char *> &DracoUvFlagNames();

// Name prefixes of draco-uv's flag families ("-uv_", "-tangent_"): a flag
// that starts with one is draco-uv's even when this build has no flag of
// that name, so that a flag of a newer or other build is an error here.
const std::vector<const char *> &DracoUvFlagFamilies();

// True for the flags of stock Draco's tools that take a value (-qp, -cl,
// ...). -qtg is one (draco_transcoder's own) and also draco-uv's in
// draco_encoder: the stock -q flags a letter from it are not its typos, and
// at the end of a command line it is skipped with a warning like them.
bool IsStockToolValueFlag(const std::string &arg);

// What a tool does with an argument that none of its flags took.
struct UnhandledToolArg {
  enum Kind {
    kIgnore,  // not a flag: ignored silently, as stock Draco does
    kWarn,    // a flag that is not draco-uv's: ignored with |message|
    kError,   // looks like a flag of draco-uv's: stop with |message|
  };
  Kind kind = kIgnore;
  // The warning or error without its "Warning: "/"Error: " prefix.
  std::string message;
  // For kError, the closest flag of the table, if one is close enough.
  std::string suggestion;
};

// Classifies |arg|, an argument that no flag of the tool |tool| took, given
// the table |known_flags| and the families |families| (the overload without
// them uses DracoUvFlagNames() and DracoUvFlagFamilies()). |is_last| tells
// that no argument follows: stock Draco's tools also skip a flag of theirs
// that needs a value there.
UnhandledToolArg ClassifyUnhandledToolArg(
    const std::string &tool, const std::string &arg, bool is_last,
    const std::vector<const char *> &known_flags,
    const std::vector<const char *> &families);
UnhandledToolArg ClassifyUnhandledToolArg(const std::string &tool,
                                          const std::string &arg, bool is_last);

// The tools' hook: classifies argv[index] (the tool named by argv[0]'s
// base name), prints a warning or an error line to |messages| and returns
// false when the tool must stop (exit non-zero before it writes anything).
bool CheckUnhandledToolArg(int argc, char **argv, int index,
                           FILE *messages = stderr);

// One help paragraph on unknown flags, for the tools' -h.
std::string UnknownToolFlagUsage();

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_DRACO_UV_FLAGS_H_
