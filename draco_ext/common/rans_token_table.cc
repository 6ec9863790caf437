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
#include "draco_ext/common/rans_token_table.h"

#include <algorithm>
#include <limits>

#include "draco/compression/entropy/ans.h"
#include "draco/core/bit_utils.h"
#include "draco/core/varint_decoding.h"
#include "draco/core/varint_encoding.h"

namespace draco {

namespace {

constexpr uint32_t kPrecision = uint32_t{1} << kRansTokenPrecisionBits;
// Counts below 2^32: levels up to 1 + 4 * 31 + 4.
constexpr uint32_t kMaxLevel = 129;
// 256 * 2^(j / 4), the weights of the levels 1 + 4 e + j before the shift.
constexpr uint64_t kLevelMantissa[4] = {256, 304, 362, 431};
// Where a count's mantissa (256 .. 511) rounds up to the next level:
// 256 * 2^((2 j + 1) / 8).
constexpr uint64_t kLevelThresholds[4] = {280, 332, 395, 470};
constexpr int kTableSizeBits = 7;
constexpr int kRiceParameterBits = 2;
constexpr int kMaxRiceParameter = 3;
// Zig-zag level differences are at most 2 * kMaxLevel.
constexpr uint32_t kMaxLevelDifference = 2 * kMaxLevel;
constexpr uint64_t kBitUnit = 65536;

// The level of a count >= 1: 1 + round(4 log2(count)).
uint8_t LevelOfCount(uint32_t count) {
  const int e = MostSignificantBit(count);
  const uint64_t mantissa = (uint64_t{count} << 8) >> e;  // 256 .. 511.
  int j = 0;
  while (j < 4 && mantissa >= kLevelThresholds[j]) {
    ++j;
  }
  return static_cast<uint8_t>(1 + 4 * e + j);
}

// The relative weight of a level >= 1, below 2^41.
uint64_t WeightOfLevel(uint32_t level) {
  return kLevelMantissa[(level - 1) & 3] << ((level - 1) >> 2);
}

// log2(p) in 1/65536, rounded down, for 1 <= p < 2^32.
uint64_t FixedLog2(uint32_t p) {
  const int e = MostSignificantBit(p);
  uint64_t x = (uint64_t{p} << 31) >> e;  // 1.f in Q31: [2^31, 2^32).
  uint64_t result = static_cast<uint64_t>(e) << 16;
  for (int bit = 15; bit >= 0; --bit) {
    x = (x * x) >> 31;
    if (x >= (uint64_t{1} << 32)) {
      x >>= 1;
      result |= uint64_t{1} << bit;
    }
  }
  return result;
}

uint32_t ZigZag(int32_t value) { return ConvertSignedIntToSymbol(value); }

}  // namespace

void BitWriter::Put(uint32_t value, int num_bits) {
  for (int i = 0; i < num_bits; ++i, ++num_bits_) {
    if (num_bits_ % 8 == 0) {
      bytes_.push_back(0);
    }
    bytes_.back() |= static_cast<uint8_t>(((value >> i) & 1) << (num_bits_ % 8));
  }
}

void BitWriter::PutRice(uint32_t value, int k) {
  for (uint32_t q = value >> k; q > 0; --q) {
    Put(1, 1);
  }
  Put(0, 1);
  Put(value, k);
}

bool BitReader::Get(int num_bits, uint32_t *value) {
  if (position_ + num_bits > 8 * uint64_t{size_}) {
    return false;
  }
  *value = 0;
  for (int i = 0; i < num_bits; ++i, ++position_) {
    *value |= static_cast<uint32_t>((data_[position_ / 8] >> (position_ % 8)) & 1)
              << i;
  }
  return true;
}

bool BitReader::GetRice(int k, uint32_t max_quotient, uint32_t *value) {
  uint32_t quotient = 0, bit = 1, low = 0;
  while (true) {
    if (!Get(1, &bit)) {
      return false;
    }
    if (bit == 0) {
      break;
    }
    if (++quotient > max_quotient) {
      return false;
    }
  }
  if (!Get(k, &low)) {
    return false;
  }
  *value = (quotient << k) | low;
  return true;
}

bool RansTokenTable::InitFromCounts(const std::vector<uint32_t> &counts) {
  size_t size = counts.size();
  while (size > 0 && counts[size - 1] == 0) {
    --size;
  }
  if (size == 0 || size > kMaxRansTokens) {
    return false;
  }
  levels_.resize(size);
  for (size_t i = 0; i < size; ++i) {
    levels_[i] = counts[i] == 0 ? 0 : LevelOfCount(counts[i]);
  }
  return ComputeProbabilities();
}

uint64_t RansTokenTable::LevelBits(int k) const {
  uint64_t bits = 0;
  int previous = 0;
  for (const uint8_t level : levels_) {
    bits += (ZigZag(level - previous) >> k) + 1 + k;
    previous = level;
  }
  return bits;
}

int RansTokenTable::BestRiceParameter() const {
  int best = 0;
  for (int k = 1; k <= kMaxRiceParameter; ++k) {
    best = LevelBits(k) < LevelBits(best) ? k : best;
  }
  return best;
}

void RansTokenTable::Write(BitWriter *writer) const {
  DRACO_DCHECK(!levels_.empty());
  writer->Put(static_cast<uint32_t>(levels_.size() - 1), kTableSizeBits);
  const int k = BestRiceParameter();
  writer->Put(k, kRiceParameterBits);
  int previous = 0;
  for (const uint8_t level : levels_) {
    writer->PutRice(ZigZag(level - previous), k);
    previous = level;
  }
}

bool RansTokenTable::Read(BitReader *reader) {
  uint32_t size_minus_one, k;
  if (!reader->Get(kTableSizeBits, &size_minus_one) ||
      !reader->Get(kRiceParameterBits, &k)) {
    return false;
  }
  levels_.resize(size_minus_one + 1);
  int previous = 0;
  for (uint8_t &level : levels_) {
    uint32_t difference;
    if (!reader->GetRice(k, kMaxLevelDifference >> k, &difference)) {
      return false;
    }
    const int value = previous + ConvertSymbolToSignedInt(difference);
    if (value < 0 || value > static_cast<int>(kMaxLevel)) {
      return false;
    }
    level = static_cast<uint8_t>(value);
    previous = value;
  }
  return levels_.back() != 0 && ComputeProbabilities();
}

bool RansTokenTable::ComputeProbabilities() {
  uint64_t total = 0;
  for (const uint8_t level : levels_) {
    total += level == 0 ? 0 : WeightOfLevel(level);
  }
  if (total == 0) {
    return false;
  }
  // Each present token's share of 2^12, at least 1; the rounding error goes
  // to the most probable token, or, if it cannot take it, is taken one by
  // one from the tokens above 1 (at most 128 tokens share 4096).
  probabilities_.assign(levels_.size(), 0);
  int64_t sum = 0;
  size_t largest = 0;
  for (size_t i = 0; i < levels_.size(); ++i) {
    if (levels_[i] != 0) {
      probabilities_[i] = static_cast<uint32_t>(std::max<uint64_t>(
          1, (WeightOfLevel(levels_[i]) * kPrecision + total / 2) / total));
      sum += probabilities_[i];
      largest = probabilities_[i] > probabilities_[largest] ? i : largest;
    }
  }
  int64_t excess = sum - kPrecision;
  if (static_cast<int64_t>(probabilities_[largest]) - excess >= 1) {
    probabilities_[largest] -= static_cast<uint32_t>(excess);
    return true;
  }
  while (excess > 0) {
    for (uint32_t &p : probabilities_) {
      if (p > 1 && excess > 0) {
        --p;
        --excess;
      }
    }
  }
  return true;
}

uint64_t RansTokenTable::CostInBitUnits(
    const std::vector<uint32_t> &counts) const {
  uint64_t cost = kBitUnit * (kTableSizeBits + kRiceParameterBits +
                              LevelBits(BestRiceParameter()));
  const uint64_t full = FixedLog2(kPrecision);
  for (size_t i = 0; i < counts.size(); ++i) {
    if (counts[i] != 0) {
      DRACO_DCHECK(i < probabilities_.size() && probabilities_[i] > 0);
      cost += counts[i] * (full - FixedLog2(probabilities_[i]));
    }
  }
  return cost;
}

bool EncodeRansTokens(const RansTokenTable &table,
                      const std::vector<uint32_t> &tokens,
                      EncoderBuffer *buffer) {
  const std::vector<uint32_t> &probabilities = table.probabilities();
  std::vector<rans_sym> symbols(probabilities.size());
  uint32_t cumulative = 0;
  for (size_t i = 0; i < symbols.size(); ++i) {
    symbols[i] = {probabilities[i], cumulative};
    cumulative += probabilities[i];
  }
  // At most two bytes per token and four for the final state.
  std::vector<uint8_t> data(2 * tokens.size() + 4);
  RAnsEncoder<kRansTokenPrecisionBits> encoder;
  encoder.write_init(data.data());
  for (auto it = tokens.rbegin(); it != tokens.rend(); ++it) {
    if (*it >= symbols.size() || symbols[*it].prob == 0) {
      return false;
    }
    encoder.rans_write(&symbols[*it]);
  }
  const int size = encoder.write_end();
  EncodeVarint(static_cast<uint32_t>(size), buffer);
  return buffer->Encode(data.data(), size);
}

bool StartRansTokens(const RansTokenTable &table, DecoderBuffer *buffer,
                     RAnsDecoder<kRansTokenPrecisionBits> *decoder) {
  uint32_t size;
  if (!DecodeVarint(&size, buffer) || size == 0 ||
      size > static_cast<uint64_t>(buffer->remaining_size()) ||
      size > static_cast<uint32_t>(std::numeric_limits<int>::max())) {
    return false;
  }
  const std::vector<uint32_t> &probabilities = table.probabilities();
  if (!decoder->rans_build_look_up_table(
          probabilities.data(), static_cast<uint32_t>(probabilities.size())) ||
      decoder->read_init(reinterpret_cast<const uint8_t *>(buffer->data_head()),
                         static_cast<int>(size)) != 0) {
    return false;
  }
  buffer->Advance(size);
  return true;
}

bool DecodeRansTokens(const RansTokenTable &table, uint32_t count,
                      DecoderBuffer *buffer, std::vector<uint32_t> *tokens) {
  RAnsDecoder<kRansTokenPrecisionBits> decoder;
  if (!StartRansTokens(table, buffer, &decoder)) {
    return false;
  }
  tokens->resize(count);
  for (uint32_t &token : *tokens) {
    token = static_cast<uint32_t>(decoder.rans_read());
  }
  return true;
}

}  // namespace draco
