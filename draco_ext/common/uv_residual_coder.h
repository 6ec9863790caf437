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
// decoder already has. The encoder merges runs of neighbouring contexts
// into one table where a table costs more than it saves (greedily, by an
// integer estimate of the tables' and tokens' bits), and codes each table's
// tokens with rANS (Draco's ans.h) at 12-bit precision
// (rans_token_table.h). On the corpus's meshes a table takes about 6 bits
// per distinct token; Draco's EncodeSymbols() took 15-18, 13-18 % of the UV
// bytes of small meshes with per-context tables. Raw bits go through one
// DirectBitEncoder.
//
// The texture coordinate schemes use kUvResidualNumContexts contexts; other
// users choose up to kMaxResidualContexts (the decoder must be told the
// same number).
//
// Stream: uint16 table starts (bit c set: context c starts a new table;
// bit 0 and bits from the number of contexts on are 0); per table a varint
// token count; a varint byte length and the bit-packed tables of the
// non-empty ones; per non-empty table a varint byte length and its rANS
// data; then the raw bits.
#ifndef DRACO_EXT_COMMON_UV_RESIDUAL_CODER_H_
#define DRACO_EXT_COMMON_UV_RESIDUAL_CODER_H_

#include <array>
#include <cstdint>
#include <vector>

#include "draco/compression/bit_coders/direct_bit_decoder.h"
#include "draco/compression/entropy/ans.h"
#include "draco/core/bit_utils.h"
#include "draco/core/decoder_buffer.h"
#include "draco/core/encoder_buffer.h"
#include "draco_ext/common/rans_token_table.h"

namespace draco {

// The most contexts a coder can have (the table starts are 16 bits).
constexpr int kMaxResidualContexts = 16;
// The texture coordinate schemes' contexts 0-7: the bit length of the
// neighbours' residuals (capped); kUvResidualNoNeighbourContext and
// kUvResidualNoStencilContext below.
constexpr int kUvResidualNumContexts = 10;
// A texture coordinate without decoded neighbours: the first of its chart.
constexpr int kUvResidualNoNeighbourContext = 8;
// A texture coordinate with decoded neighbours but no stencil to predict
// from: mostly the second of its chart, whose residual is a UV edge.
constexpr int kUvResidualNoStencilContext = 9;
// Every one of |num_contexts| contexts in its own table.
constexpr uint16_t ResidualAllTables(int num_contexts) {
  return static_cast<uint16_t>(((1u << num_contexts) - 1) & ~1u);
}
constexpr uint16_t kUvResidualAllTables =
    ResidualAllTables(kUvResidualNumContexts);
// Tokens below this are residuals' zig-zag values themselves.
constexpr uint32_t kUvResidualDirectTokens = 16;

class UvResidualEncoder {
 public:
  // A coder of |num_contexts| contexts, 1 to kMaxResidualContexts.
  explicit UvResidualEncoder(int num_contexts = kUvResidualNumContexts)
      : num_contexts_(num_contexts) {}
  // Drops all residuals; |expected| residuals will be added.
  void Reset(int expected);
  // Appends a residual in decoding order; |context| < the number of
  // contexts.
  void Add(int context, int32_t residual);
  // Writes all residuals with the table starts that make them smallest.
  bool Encode(EncoderBuffer *buffer) const;
  // Writes all residuals with the given table starts (see the stream).
  bool Encode(uint16_t table_starts, EncoderBuffer *buffer) const;

 private:
  struct Symbol {
    uint8_t context;
    uint8_t token;
    uint8_t num_raw_bits;
    uint32_t raw_bits;
  };
  // The table starts Encode() writes: greedy merges of neighbouring tables.
  uint16_t ChooseTableStarts() const;
  int num_contexts_;
  std::vector<Symbol> symbols_;
};

class UvResidualDecoder {
 public:
  // A decoder of |num_contexts| contexts, as the encoder had.
  explicit UvResidualDecoder(int num_contexts = kUvResidualNumContexts)
      : num_contexts_(num_contexts) {}
  // Reads the streams of |count| residuals. Fails on truncated or
  // inconsistent data.
  bool Decode(int count, DecoderBuffer *buffer);
  // The next residual of |context|, in the encoder's order. Fails when the
  // context's stream or the raw bits are exhausted or a token is invalid.
  // Inline: called twice per texture coordinate; the call alone cost
  // 0.4-0.6 % of a whole decode.
  // Tokens are rANS-decoded here, as they are asked for, rather than all
  // into arrays first (an array's store and load cost as much again).
  bool Next(int context, int32_t *residual) {
    if (static_cast<unsigned>(context) >=
        static_cast<unsigned>(num_contexts_)) {
      return false;
    }
    const int group = table_of_[context];
    if (remaining_[group] == 0) {
      return false;
    }
    --remaining_[group];
    const uint32_t token = static_cast<uint32_t>(decoders_[group].rans_read());
    if (token >= kUvResidualDirectTokens) {
      return DecodeSplitToken(token, residual);
    }
    *residual = ConvertSymbolToSignedInt(token);
    return true;
  }

 private:
  // The residual of a token >= kUvResidualDirectTokens and its raw bits.
  bool DecodeSplitToken(uint32_t token, int32_t *residual);

  // Reads the tables of the |counts| after the table starts and starts
  // their token decoders.
  bool DecodeTables(const std::array<uint32_t, kMaxResidualContexts> &counts,
                    int num_tables, DecoderBuffer *buffer);

  int num_contexts_;
  std::array<uint8_t, kMaxResidualContexts> table_of_ = {};
  // Per table: the tokens not yet read and their decoder.
  std::array<uint32_t, kMaxResidualContexts> remaining_ = {};
  std::array<RAnsDecoder<kRansTokenPrecisionBits>, kMaxResidualContexts>
      decoders_;
  DirectBitDecoder raw_bits_;
};

}  // namespace draco

#endif  // DRACO_EXT_COMMON_UV_RESIDUAL_CODER_H_
