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
// Static rANS coding of tokens from a small alphabet (below 128) with a
// compact probability table, for streams where the table is a sizeable part
// of the data.
//
// Based on:
//   [Duda 2013] J. Duda: Asymmetric numeral systems: entropy coding
//     combining speed of Huffman coding with compression rate of arithmetic
//     coding. arXiv:1311.2540 (rANS; Draco's ans.h is the coder).
//   [Rice 1979] R. F. Rice: Some practical universal noiseless coding
//     techniques. JPL Publication 79-22 (the Rice code of the table).
//
// The table stores each token's count rounded to a quarter octave (its
// level, 0 for absent tokens); consecutive levels differ little, so their
// differences are Rice coded: about 5 bits per token of the alphabet, 6 per
// distinct token, on the texture coordinate residuals of the corpus, against
// 15-18 for Draco's EncodeSymbols() tables. Rounding the counts (each off
// by at most a factor 2^(1/8)) costs at most about 0.005 bits per token,
// plus the 12-bit precision's rounding of rare tokens. The
// probabilities follow from the levels with integer arithmetic only, so
// encoder and decoder agree on every platform.
//
// Weak where tables are cheap anyway (long streams over few tokens) and for
// alphabets with large gaps between used tokens: every token below the
// largest used one costs its level difference.
#ifndef DRACO_EXT_COMMON_RANS_TOKEN_TABLE_H_
#define DRACO_EXT_COMMON_RANS_TOKEN_TABLE_H_

#include <cstdint>
#include <vector>

#include "draco/compression/entropy/ans.h"
#include "draco/core/decoder_buffer.h"
#include "draco/core/encoder_buffer.h"

namespace draco {

// Tokens are below this.
constexpr int kMaxRansTokens = 128;
// The rANS precision: probabilities are multiples of 2^-12.
constexpr int kRansTokenPrecisionBits = 12;

// Bits appended least significant first; the last byte is zero-padded.
// (Draco's DirectBitEncoder pads to 32-bit words behind a 4-byte size, more
// than a few tables take.)
class BitWriter {
 public:
  void Put(uint32_t value, int num_bits);
  // |value| as a Rice code with parameter |k|: value >> k in unary (ones
  // ended by a zero), then its k low bits.
  void PutRice(uint32_t value, int k);
  const std::vector<uint8_t> &bytes() const { return bytes_; }

 private:
  std::vector<uint8_t> bytes_;
  int num_bits_ = 0;
};

// Reads what a BitWriter wrote; every Get fails past the end.
class BitReader {
 public:
  BitReader(const uint8_t *data, size_t size) : data_(data), size_(size) {}
  bool Get(int num_bits, uint32_t *value);
  // Fails also on unary parts longer than |max_quotient|.
  bool GetRice(int k, uint32_t max_quotient, uint32_t *value);

 private:
  const uint8_t *data_;
  size_t size_;
  uint64_t position_ = 0;  // In bits.
};

// A table: levels of the tokens 0 .. size() - 1; the last is non-zero.
class RansTokenTable {
 public:
  // The table of a histogram (counts of the tokens 0, 1, ...), with the
  // trailing zero counts left out. Fails when no count is non-zero.
  bool InitFromCounts(const std::vector<uint32_t> &counts);
  void Write(BitWriter *writer) const;
  // Fails on tables no encoder writes.
  bool Read(BitReader *reader);

  // The rANS probabilities (multiples of 2^-12, summing to 1) of the tokens.
  const std::vector<uint32_t> &probabilities() const { return probabilities_; }
  // The bits of Write() plus what coding |counts| with this table costs,
  // in 1/65536 bits; integer arithmetic only.
  uint64_t CostInBitUnits(const std::vector<uint32_t> &counts) const;

 private:
  // The bits of the levels Rice coded with parameter |k|.
  uint64_t LevelBits(int k) const;
  int BestRiceParameter() const;
  bool ComputeProbabilities();

  std::vector<uint8_t> levels_;
  std::vector<uint32_t> probabilities_;
};

// rANS-codes |tokens| (each below the table's size, with a non-zero
// probability) as a varint byte length and the coder's bytes.
bool EncodeRansTokens(const RansTokenTable &table,
                      const std::vector<uint32_t> &tokens,
                      EncoderBuffer *buffer);
// The rANS decoder of the tokens written by EncodeRansTokens(): reads the
// byte length, points |decoder| at the bytes (which must outlive it) and
// moves |buffer| past them; the tokens are then |decoder|->rans_read(), in
// order. Fails on an inconsistent table or length.
bool StartRansTokens(const RansTokenTable &table, DecoderBuffer *buffer,
                     RAnsDecoder<kRansTokenPrecisionBits> *decoder);
// Reads |count| tokens written by EncodeRansTokens().
bool DecodeRansTokens(const RansTokenTable &table, uint32_t count,
                      DecoderBuffer *buffer, std::vector<uint32_t> *tokens);

}  // namespace draco

#endif  // DRACO_EXT_COMMON_RANS_TOKEN_TABLE_H_
