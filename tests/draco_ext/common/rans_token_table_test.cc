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
// The compact rANS token tables (rans_token_table.h): tables of many
// histograms round-trip, give every present token a probability close to
// its share, and code tokens back to themselves at about their entropy;
// truncated or invalid tables and truncated token streams are refused with
// false.
#include "draco_ext/common/rans_token_table.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "draco/compression/config/compression_shared.h"
#include "gtest/gtest.h"

namespace draco {
namespace {

// Counts of |size| tokens: geometric-like decay with random gaps, as the
// residual tokens have, or flat.
std::vector<uint32_t> RandomCounts(uint32_t seed, int size) {
  std::mt19937 random(seed);
  std::vector<uint32_t> counts(size);
  const double scale = std::pow(10.0, 1 + random() % 6);
  for (int i = 0; i < size; ++i) {
    const bool gap = random() % 4 == 0;
    counts[i] = gap ? 0 : static_cast<uint32_t>(scale * std::exp(-0.3 * i)) +
                              random() % 3;
  }
  counts[random() % size] += 1;  // At least one token.
  return counts;
}

// Tokens in random order with the given counts.
std::vector<uint32_t> TokensOf(const std::vector<uint32_t> &counts,
                               uint32_t seed) {
  std::vector<uint32_t> tokens;
  for (size_t t = 0; t < counts.size(); ++t) {
    tokens.insert(tokens.end(), counts[t], static_cast<uint32_t>(t));
  }
  std::shuffle(tokens.begin(), tokens.end(), std::mt19937(seed));
  return tokens;
}

TEST(RansTokenTableTest, TablesRoundTripThroughTheirBits) {
  for (uint32_t seed = 0; seed < 300; ++seed) {
    RansTokenTable table;
    ASSERT_TRUE(
        table.InitFromCounts(RandomCounts(seed, 1 + seed % kMaxRansTokens)));
    BitWriter writer;
    table.Write(&writer);
    BitReader reader(writer.bytes().data(), writer.bytes().size());
    RansTokenTable read;
    ASSERT_TRUE(read.Read(&reader)) << seed;
    EXPECT_EQ(read.probabilities(), table.probabilities()) << seed;
  }
}

TEST(RansTokenTableTest, ProbabilitiesSumToOneAndFollowTheCounts) {
  for (uint32_t seed = 0; seed < 300; ++seed) {
    const std::vector<uint32_t> counts =
        RandomCounts(seed, 1 + seed % kMaxRansTokens);
    RansTokenTable table;
    ASSERT_TRUE(table.InitFromCounts(counts));
    const std::vector<uint32_t> &p = table.probabilities();
    uint64_t sum = 0, total = 0;
    for (const uint32_t count : counts) {
      total += count;
    }
    for (size_t t = 0; t < p.size(); ++t) {
      sum += p[t];
      EXPECT_EQ(p[t] > 0, counts[t] > 0) << seed << " token " << t;
    }
    EXPECT_EQ(sum, uint64_t{1} << kRansTokenPrecisionBits) << seed;
    // The coded size is within 1 % (plus the table) of the entropy.
    double entropy = 0;
    for (const uint32_t count : counts) {
      entropy += count == 0 ? 0 : -(count * std::log2(double(count) / total));
    }
    const double cost = table.CostInBitUnits(counts) / 65536.0;
    EXPECT_LE(cost, 1.01 * entropy + 8 * kMaxRansTokens + 0.02 * total)
        << seed;
  }
}

TEST(RansTokenTableTest, TokensRoundTripAtAboutTheEstimatedCost) {
  for (uint32_t seed = 0; seed < 100; ++seed) {
    const std::vector<uint32_t> counts = RandomCounts(seed, 1 + seed % 72);
    RansTokenTable table;
    ASSERT_TRUE(table.InitFromCounts(counts));
    const std::vector<uint32_t> tokens = TokensOf(counts, seed);
    EncoderBuffer out;
    ASSERT_TRUE(EncodeRansTokens(table, tokens, &out));
    out.Encode(uint32_t{0xdeadbeef});  // Data that follows.
    DecoderBuffer in;
    in.Init(out.data(), out.size(), kDracoMeshBitstreamVersion);
    std::vector<uint32_t> decoded;
    ASSERT_TRUE(DecodeRansTokens(table, static_cast<uint32_t>(tokens.size()),
                                 &in, &decoded))
        << seed;
    EXPECT_EQ(decoded, tokens) << seed;
    EXPECT_EQ(in.remaining_size(), 4) << seed;
    BitWriter table_bits;
    table.Write(&table_bits);
    const double estimate = table.CostInBitUnits(counts) / 65536.0 / 8 -
                            table_bits.bytes().size();
    EXPECT_LE(out.size() - 4, 1.001 * estimate + 8) << seed;
  }
}

TEST(RansTokenTableTest, EmptyHistogramsAndTooManyTokensHaveNoTable) {
  RansTokenTable table;
  EXPECT_FALSE(table.InitFromCounts({}));
  EXPECT_FALSE(table.InitFromCounts({0, 0, 0}));
  EXPECT_FALSE(
      table.InitFromCounts(std::vector<uint32_t>(kMaxRansTokens + 1, 1)));
  EXPECT_TRUE(table.InitFromCounts(std::vector<uint32_t>(kMaxRansTokens, 1)));
}

TEST(RansTokenTableTest, ReadRejectsTruncatedAndInvalidTables) {
  for (uint32_t seed = 0; seed < 50; ++seed) {
    RansTokenTable table;
    ASSERT_TRUE(table.InitFromCounts(RandomCounts(seed, 1 + seed % 40)));
    BitWriter writer;
    table.Write(&writer);
    for (size_t size = 0; size + 1 < writer.bytes().size(); ++size) {
      BitReader reader(writer.bytes().data(), size);
      RansTokenTable read;
      EXPECT_FALSE(read.Read(&reader)) << seed << ": " << size;
    }
  }
  // A table whose last level is zero, and one whose levels go negative.
  for (const uint32_t first_level_code : {0u, 1u}) {
    BitWriter writer;
    writer.Put(0, 7);  // One token.
    writer.Put(0, 2);  // Rice parameter 0.
    writer.PutRice(first_level_code, 0);  // Level 0, or -1.
    BitReader reader(writer.bytes().data(), writer.bytes().size());
    RansTokenTable read;
    EXPECT_FALSE(read.Read(&reader)) << first_level_code;
  }
}

TEST(RansTokenTableTest, DecodeRejectsTruncatedTokenStreams) {
  const std::vector<uint32_t> counts = RandomCounts(7, 30);
  RansTokenTable table;
  ASSERT_TRUE(table.InitFromCounts(counts));
  const std::vector<uint32_t> tokens = TokensOf(counts, 7);
  EncoderBuffer out;
  ASSERT_TRUE(EncodeRansTokens(table, tokens, &out));
  std::vector<uint32_t> decoded;
  for (size_t size = 0; size < out.size(); ++size) {
    DecoderBuffer in;
    in.Init(out.data(), size, kDracoMeshBitstreamVersion);
    EXPECT_FALSE(DecodeRansTokens(table, static_cast<uint32_t>(tokens.size()),
                                  &in, &decoded))
        << size;
  }
}

}  // namespace
}  // namespace draco
