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
// libFuzzer target: decodes arbitrary bytes as a Draco mesh with the patched
// decoder, like Draco's own draco_mesh_decoder_fuzzer, then touches every
// decoded value. scripts/fuzz.sh runs it once per row of
// testdata/golden/variants.tsv, seeded with that row's golden files, so
// each draco-uv scheme and variant gets its own corpus. Decoding may fail;
// it must not crash, overflow, leak or allocate without bound (ASan, UBSan
// and libFuzzer's -malloc_limit_mb watch that).
#include <cstddef>
#include <cstdint>

#include "draco/compression/decode.h"
#include "draco_ext/eval/uv_decoded_digest.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char *>(data), size);
  draco::Decoder decoder;
  const auto mesh = decoder.DecodeMeshFromBuffer(&buffer);
  // Reads every value at every corner, so that bad mappings show up; stock
  // Draco's sequential connectivity may leave face indices beyond the points
  // (benchmarks/hostile.md), which CheckMeshIndices() reports.
  if (mesh.ok() && draco::CheckMeshIndices(*mesh.value()).ok()) {
    draco::MeshDigest(*mesh.value());
  }
  return 0;
}
