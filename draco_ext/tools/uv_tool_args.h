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
// Command-line helpers shared by the evaluation tools (draco_uv_eval,
// draco_uv_gltf_eval, draco_uv_seam_stats).
#ifndef DRACO_EXT_TOOLS_UV_TOOL_ARGS_H_
#define DRACO_EXT_TOOLS_UV_TOOL_ARGS_H_

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace draco {

// The non-empty items of a comma-separated list.
inline std::vector<std::string> SplitUvToolList(const std::string &list) {
  std::vector<std::string> items;
  std::stringstream stream(list);
  std::string item;
  while (std::getline(stream, item, ',')) {
    if (!item.empty()) {
      items.push_back(item);
    }
  }
  return items;
}

// A decimal integer from |min| to |max|.
inline bool ParseUvToolInt(const std::string &text, int min, int max,
                           int *value) {
  char *end = nullptr;
  const long parsed = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || parsed < min || parsed > max) {
    return false;
  }
  *value = static_cast<int>(parsed);
  return true;
}

// A quantization or compression setting: an integer from 0 to 30.
inline bool ParseUvToolSetting(const std::string &text, int *value) {
  return ParseUvToolInt(text, 0, 30, value);
}

// The exit code after printing the usage: 0 when it was asked for (-h or
// --help first), 1 for bad arguments.
inline int UvToolUsageExitCode(int argc, char **argv) {
  const bool asked = argc > 1 && (std::string(argv[1]) == "-h" ||
                                  std::string(argv[1]) == "--help");
  return asked ? 0 : 1;
}

}  // namespace draco

#endif  // DRACO_EXT_TOOLS_UV_TOOL_ARGS_H_
