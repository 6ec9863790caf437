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
#include "draco_ext/common/uv_residual_coder.h"

#include "draco/compression/bit_coders/direct_bit_encoder.h"
#include "draco/compression/entropy/symbol_decoding.h"
#include "draco/compression/entropy/symbol_encoding.h"
#include "draco/core/bit_utils.h"
#include "draco/core/varint_decoding.h"
#include "draco/core/varint_encoding.h"

namespace draco {

namespace {

constexpr int kFirstSplitBits = 4;  // bitlen(z) - 1 of the first split token.
// z < 2^32: n <= 31, so tokens stay below 16 + 2 * 28.
constexpr uint32_t kNumTokens =
    kUvResidualDirectTokens + 2 * (32 - kFirstSplitBits);

}  // namespace

void UvResidualEncoder::Reset(int expected) {
  symbols_.clear();
  symbols_.reserve(expected);
}

void UvResidualEncoder::Add(int context, int32_t residual) {
  DRACO_DCHECK_LT(context, kUvResidualNumContexts);
  const uint32_t z = ConvertSignedIntToSymbol(residual);
  Symbol symbol{static_cast<uint8_t>(context), static_cast<uint8_t>(z), 0, 0};
  if (z >= kUvResidualDirectTokens) {
    const int n = MostSignificantBit(z);  // bitlen(z) - 1, >= 4.
    const uint32_t next_bit = (z >> (n - 1)) & 1;
    symbol.token = static_cast<uint8_t>(kUvResidualDirectTokens +
                                        2 * (n - kFirstSplitBits) + next_bit);
    symbol.num_raw_bits = static_cast<uint8_t>(n - 1);
    symbol.raw_bits = z & ((uint32_t{1} << (n - 1)) - 1);
  }
  symbols_.push_back(symbol);
}

bool UvResidualEncoder::Encode(bool use_contexts, EncoderBuffer *buffer) const {
  const int num_contexts = use_contexts ? kUvResidualNumContexts : 1;
  std::vector<std::vector<uint32_t>> tokens(num_contexts);
  DirectBitEncoder raw_bits;
  raw_bits.StartEncoding();
  for (const Symbol &symbol : symbols_) {
    tokens[use_contexts ? symbol.context : 0].push_back(symbol.token);
    if (symbol.num_raw_bits > 0) {
      raw_bits.EncodeLeastSignificantBits32(symbol.num_raw_bits,
                                            symbol.raw_bits);
    }
  }
  buffer->Encode(static_cast<uint8_t>(use_contexts));
  for (const std::vector<uint32_t> &group : tokens) {
    EncodeVarint(static_cast<uint32_t>(group.size()), buffer);
    if (!group.empty() &&
        !EncodeSymbols(group.data(), static_cast<int>(group.size()), 1,
                       nullptr, buffer)) {
      return false;
    }
  }
  raw_bits.EndEncoding(buffer);
  return true;
}

bool UvResidualDecoder::Decode(int count, DecoderBuffer *buffer) {
  uint8_t use_contexts;
  if (count < 0 || !buffer->Decode(&use_contexts) || use_contexts > 1) {
    return false;
  }
  use_contexts_ = use_contexts == 1;
  const int num_contexts = use_contexts_ ? kUvResidualNumContexts : 1;
  int64_t total = 0;
  for (int i = 0; i < kUvResidualNumContexts; ++i) {
    tokens_[i].clear();
    next_[i] = 0;
  }
  for (int i = 0; i < num_contexts; ++i) {
    uint32_t group_size;
    if (!DecodeVarint(&group_size, buffer) || group_size > count - total) {
      return false;
    }
    total += group_size;
    tokens_[i].resize(group_size);
    if (!DecodeSymbols(group_size, 1, buffer, tokens_[i].data())) {
      return false;
    }
  }
  return total == count && raw_bits_.StartDecoding(buffer);
}

bool UvResidualDecoder::DecodeSplitToken(uint32_t token, int32_t *residual) {
  if (token >= kNumTokens) {
    return false;
  }
  const int n =
      static_cast<int>(token - kUvResidualDirectTokens) / 2 + kFirstSplitBits;
  uint32_t low = 0;
  if (!raw_bits_.DecodeLeastSignificantBits32(n - 1, &low)) {
    return false;
  }
  *residual = ConvertSymbolToSignedInt(
      (uint32_t{1} << n) |
      (((token - kUvResidualDirectTokens) & 1) << (n - 1)) | low);
  return true;
}

}  // namespace draco
