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
#include "draco_ext/seams/uv_seam_coder.h"

#include <utility>

namespace draco {

namespace {

// Bit I/O of the encoder: codes the bits it is given and hands out the
// lengths of the runs of quiet edges, plus one (0 after the last one).
class EncodingIo {
 public:
  explicit EncodingIo(std::vector<std::vector<uint32_t>> runs)
      : runs_(std::move(runs)), next_run_(runs_.size(), 0) {}
  bool Code(uint32_t probability_of_one, bool bit) {
    coder_.EncodeBit(bit, probability_of_one);
    return bit;
  }
  uint32_t NextRun(int quiet_class) {
    const std::vector<uint32_t> &runs = runs_[quiet_class];
    size_t &next = next_run_[quiet_class];
    return next < runs.size() ? runs[next++] + 1 : 0;
  }
  UvSeamRangeEncoder *coder() { return &coder_; }

 private:
  UvSeamRangeEncoder coder_;
  std::vector<std::vector<uint32_t>> runs_;
  std::vector<size_t> next_run_;
};

}  // namespace

bool EncodeUvSeams(const UvSeamCornerTable &table, int num_attributes,
                   const std::vector<uint8_t> &bits,
                   std::vector<uint8_t> *bytes) {
  UvSeamContextCoder<UvSeamCornerTable> coder;
  if (!coder.Init(table, num_attributes) ||
      bits.size() != coder.num_edges() * num_attributes) {
    return false;
  }
  std::vector<uint8_t> coded = bits;
  EncodingIo io(coder.QuietRuns(bits.data()));
  coder.Code(&io, coded.data());
  *bytes = io.coder()->Finish();
  return true;
}

}  // namespace draco
