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
// Context-modelled residual coding for the draco-uv texture coordinate
// schemes.
//
// Each residual component r is zig-zag mapped to z and split into a token of
// a small alphabet and raw low bits (the "hybrid integer" split of JPEG XL's
// entropy coder):
//   z < 16    token z, no raw bits;
//   z >= 16   n = bitlen(z) - 1, token = 16 + 2 (n - 4) + bit (n - 1) of z,
//             followed by the n - 1 lowest bits of z, raw.
// Tokens are grouped by a context the predictor derives from data the
// decoder already has; every group is coded with Draco's static rANS symbol
// coder (EncodeSymbols). A small alphabet keeps the per-context probability
// tables cheap, which is what makes contexts pay (full-alphabet tables eat
// the gain). Raw bits go through one DirectBitEncoder.
//
// Stream: uint8 use_contexts; per context (9, or 1 without contexts) a
// varint token count and, if non-zero, the EncodeSymbols() data; then the
// raw bits.
#ifndef DRACO_EXT_COMMON_UV_RESIDUAL_CODER_H_
#define DRACO_EXT_COMMON_UV_RESIDUAL_CODER_H_

#include <array>
#include <cstdint>
#include <vector>

#include "draco/compression/bit_coders/direct_bit_decoder.h"
#include "draco/core/bit_utils.h"
#include "draco/core/decoder_buffer.h"
#include "draco/core/encoder_buffer.h"

namespace draco {

constexpr int kUvResidualNumContexts = 9;
// Tokens below this are residuals' zig-zag values themselves.
constexpr uint32_t kUvResidualDirectTokens = 16;

class UvResidualEncoder {
 public:
  // Drops all residuals; |expected| residuals will be added.
  void Reset(int expected);
  // Appends a residual in decoding order; |context| < kUvResidualNumContexts.
  void Add(int context, int32_t residual);
  // Writes all residuals, with one table per context or a single table.
  bool Encode(bool use_contexts, EncoderBuffer *buffer) const;

 private:
  struct Symbol {
    uint8_t context;
    uint8_t token;
    uint8_t num_raw_bits;
    uint32_t raw_bits;
  };
  std::vector<Symbol> symbols_;
};

class UvResidualDecoder {
 public:
  // Reads the streams of |count| residuals. Fails on truncated or
  // inconsistent data.
  bool Decode(int count, DecoderBuffer *buffer);
  // The next residual of |context|, in the encoder's order. Fails when the
  // context's stream or the raw bits are exhausted or a token is invalid.
  // Inline: called twice per texture coordinate; the call alone cost
  // 0.4-0.6 % of a whole decode.
  bool Next(int context, int32_t *residual) {
    const int group = use_contexts_ ? context : 0;
    if (group < 0 || group >= kUvResidualNumContexts ||
        next_[group] >= tokens_[group].size()) {
      return false;
    }
    const uint32_t token = tokens_[group][next_[group]++];
    if (token >= kUvResidualDirectTokens) {
      return DecodeSplitToken(token, residual);
    }
    *residual = ConvertSymbolToSignedInt(token);
    return true;
  }

 private:
  // The residual of a token >= kUvResidualDirectTokens and its raw bits.
  bool DecodeSplitToken(uint32_t token, int32_t *residual);

  bool use_contexts_ = false;
  std::array<std::vector<uint32_t>, kUvResidualNumContexts> tokens_;
  std::array<size_t, kUvResidualNumContexts> next_ = {};
  DirectBitDecoder raw_bits_;
};

}  // namespace draco

#endif  // DRACO_EXT_COMMON_UV_RESIDUAL_CODER_H_
