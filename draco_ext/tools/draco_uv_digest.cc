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
// draco_uv_digest: prints what each Draco file decodes to as one line
// (uv_decoded_digest.h), "<file>\t<digest>", for pinning golden bitstreams
// and comparing builds. Exits 1 with a message on stderr if a file cannot be
// read or decoded.
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "draco/io/file_utils.h"
#include "draco_ext/eval/uv_decoded_digest.h"

int main(int argc, char **argv) {
  bool quantized = true;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    if (!strcmp(argv[i], "--dequantized")) {
      quantized = false;
    } else if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
      printf(
          "Usage: draco_uv_digest [--dequantized] FILE.drc...\n"
          "Prints \"FILE<TAB>faces=F points=P TYPE:DATATYPExN=HASH...\" per\n"
          "file: an FNV-1a hash of every attribute's values at every face\n"
          "corner. By default of the quantized integers the bitstream codes;\n"
          "with --dequantized of the values a normal decode returns.\n");
      return 0;
    } else {
      files.push_back(argv[i]);
    }
  }
  if (files.empty()) {
    fprintf(stderr, "draco_uv_digest: no input files (see -h)\n");
    return 1;
  }
  int status = 0;
  for (const std::string &file : files) {
    std::vector<char> data;
    if (!draco::ReadFileToBuffer(file, &data)) {
      fprintf(stderr, "draco_uv_digest: cannot read %s\n", file.c_str());
      status = 1;
      continue;
    }
    const draco::StatusOr<std::string> digest =
        draco::DecodedMeshDigest(data.data(), data.size(), quantized);
    if (!digest.ok()) {
      fprintf(stderr, "draco_uv_digest: %s: %s\n", file.c_str(),
              digest.status().error_msg());
      status = 1;
      continue;
    }
    printf("%s\t%s\n", file.c_str(), digest.value().c_str());
  }
  return status;
}
