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
// The binary arithmetic coder of draco-uv's crease-bit seam coding: a
// carry-propagating range coder (G. N. N. Martin, "Range encoding: an
// algorithm for removing redundancy from a digitised message", 1979, in the
// byte-wise form of LZMA's rc) driven by 12-bit probabilities that change
// with every bit, so that adaptive context models can steer it. Draco's own
// RAnsBitEncoder codes a whole stream with one static 8-bit probability.
//
// The stream ends with the shortest tail that pins the final interval: the
// encoder emits the value in [low, low + range) with the most trailing zero
// bits and drops trailing zero bytes, which the decoder reads back as
// zeros. The decoder recomputes that value, so Finish() rejects streams
// with bytes missing or added at the end. Altered bytes only change the
// decoded bits; callers that must notice them code check bits.
#ifndef DRACO_EXT_SEAMS_UV_SEAM_RANGE_CODER_H_
#define DRACO_EXT_SEAMS_UV_SEAM_RANGE_CODER_H_

#include <cstddef>
#include <cstdint>
#include <vector>

#include "draco/core/macros.h"

namespace draco {

// Probabilities are P(bit == 1) in units of 1/4096, within [1, 4095].
constexpr int kUvSeamProbabilityBits = 12;
constexpr uint32_t kUvSeamProbabilityOne = 1u << kUvSeamProbabilityBits;
// Both sides renormalise when the range falls below this.
constexpr uint32_t kUvSeamRangeTop = 1u << 24;

class UvSeamRangeEncoder {
 public:
  UvSeamRangeEncoder() = default;

  void EncodeBit(bool bit, uint32_t probability_of_one);

  // Terminates the stream (see the file comment) and returns its bytes; the
  // encoder must not be used afterwards.
  std::vector<uint8_t> Finish();

 private:
  // Moves the top byte of |low_| out, resolving pending 0xFF bytes once a
  // carry is known.
  void ShiftLow();

  uint64_t low_ = 0;  // 32 bits plus a carry bit.
  uint32_t range_ = 0xFFFFFFFFu;
  uint8_t cache_ = 0;        // Last byte not yet known to be final.
  uint64_t cache_size_ = 1;  // |cache_| plus pending 0xFF bytes.
  bool first_byte_ = true;   // The first byte is always 0 and not stored.
  std::vector<uint8_t> bytes_;
};

// The part of |range| that codes a zero bit, for both coders.
inline uint32_t UvSeamSplitRange(uint32_t range, uint32_t probability_of_one) {
  DRACO_DCHECK(probability_of_one > 0 &&
               probability_of_one < kUvSeamProbabilityOne);
  return (range >> kUvSeamProbabilityBits) *
         (kUvSeamProbabilityOne - probability_of_one);
}

class UvSeamRangeDecoder {
 public:
  // Starts decoding |size| bytes at |data|, which must outlive the decoder.
  UvSeamRangeDecoder(const uint8_t *data, size_t size);

  // Inline: the seam decoder calls it once per interior edge.
  bool DecodeBit(uint32_t probability_of_one) {
    const uint32_t bound = UvSeamSplitRange(range_, probability_of_one);
    const bool bit = code_ >= bound;
    if (bit) {
      code_ -= bound;
      low_ += bound;
      range_ -= bound;
    } else {
      range_ = bound;
    }
    while (range_ < kUvSeamRangeTop) {
      range_ <<= 8;
      low_ <<= 8;
      code_ = (code_ << 8) | NextByte();
    }
    return bit;
  }

  // True if the stream ends exactly with the tail the encoder writes after
  // the bits decoded so far, and has no bytes beyond it.
  bool Finish() const;

 private:
  uint8_t NextByte() {
    const uint8_t byte = position_ < size_ ? data_[position_] : 0;
    ++position_;
    return byte;
  }

  const uint8_t *data_;
  size_t size_;
  size_t position_ = 0;  // Bytes consumed, including implicit trailing zeros.
  uint32_t range_ = 0xFFFFFFFFu;
  uint32_t code_ = 0;  // Stream value minus |low_| in the current window.
  uint32_t low_ = 0;   // The encoder's |low_| modulo 2^32.
};

}  // namespace draco

#endif  // DRACO_EXT_SEAMS_UV_SEAM_RANGE_CODER_H_
