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
#include "draco_ext/seams/uv_seam_range_coder.h"

#include "draco/core/macros.h"

namespace draco {

namespace {

// The value in [low, low + range) with the most trailing zero bits: the
// shortest tail that identifies the final interval.
uint64_t TailValue(uint64_t low, uint32_t range) {
  const uint64_t end = low + range;
  for (int bits = 32; bits > 0; --bits) {
    const uint64_t mask = (uint64_t{1} << bits) - 1;
    const uint64_t value = (low + mask) & ~mask;
    if (value < end) {
      return value;
    }
  }
  return low;
}

}  // namespace

void UvSeamRangeEncoder::EncodeBit(bool bit, uint32_t probability_of_one) {
  const uint32_t bound = UvSeamSplitRange(range_, probability_of_one);
  if (bit) {
    low_ += bound;
    range_ -= bound;
  } else {
    range_ = bound;
  }
  while (range_ < kUvSeamRangeTop) {
    range_ <<= 8;
    ShiftLow();
  }
}

void UvSeamRangeEncoder::ShiftLow() {
  if (low_ < 0xFF000000u || low_ > 0xFFFFFFFFu) {
    const uint8_t carry = static_cast<uint8_t>(low_ >> 32);
    uint8_t byte = cache_;
    do {
      const uint8_t out = static_cast<uint8_t>(byte + carry);
      if (first_byte_) {
        DRACO_DCHECK_EQ(out, 0);
        first_byte_ = false;
      } else {
        bytes_.push_back(out);
      }
      byte = 0xFF;
    } while (--cache_size_ != 0);
    cache_ = static_cast<uint8_t>(low_ >> 24);
  }
  ++cache_size_;
  low_ = (low_ & 0x00FFFFFFu) << 8;
}

std::vector<uint8_t> UvSeamRangeEncoder::Finish() {
  low_ = TailValue(low_, range_);
  for (int i = 0; i < 5; ++i) {
    ShiftLow();
  }
  while (!bytes_.empty() && bytes_.back() == 0) {
    bytes_.pop_back();
  }
  return std::move(bytes_);
}

UvSeamRangeDecoder::UvSeamRangeDecoder(const uint8_t *data, size_t size)
    : data_(data), size_(size) {
  for (int i = 0; i < 4; ++i) {
    code_ = (code_ << 8) | NextByte();
  }
}

bool UvSeamRangeDecoder::Finish() const {
  const uint64_t tail = TailValue(low_, range_);
  if (code_ != tail - low_) {
    return false;
  }
  // Every stored byte was needed, and none of them is a trailing zero.
  return size_ <= position_ && (size_ == 0 || data_[size_ - 1] != 0);
}

}  // namespace draco
