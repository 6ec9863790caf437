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
// The context-modelled residual coder of the draco-uv schemes
// (uv_residual_coder.h): residual sequences of every context and magnitude
// round-trip with one table, one per context, mixes and the encoder's own
// choice of tables, and damaged streams are refused with false.
#include "draco_ext/common/uv_residual_coder.h"

#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "draco/compression/config/compression_shared.h"
#include "gtest/gtest.h"

namespace draco {
namespace {

// Residuals in the encoder's order with the context of each.
struct Residuals {
  std::vector<int> contexts;
  std::vector<int32_t> values;
  int size() const { return static_cast<int>(values.size()); }
  void Add(int context, int32_t value) {
    contexts.push_back(context);
    values.push_back(value);
  }
};

// A residual of random sign whose magnitude has a bit length drawn
// uniformly from 0 to 31, so that every token, direct or split, occurs.
int32_t RandomResidual(std::mt19937 *random) {
  const int bits = static_cast<int>((*random)() % 32);
  const uint32_t magnitude =
      bits == 0 ? 0
                : ((*random)() >> (32 - bits)) | (uint32_t{1} << (bits - 1));
  const int32_t value = static_cast<int32_t>(magnitude);  // Below 2^31.
  return (*random)() % 2 ? -value : value;
}

// |count| residuals of random contexts and magnitudes.
Residuals RandomResiduals(int count, uint32_t seed) {
  std::mt19937 random(seed);
  Residuals r;
  for (int i = 0; i < count; ++i) {
    r.Add(static_cast<int>(random() % kUvResidualNumContexts),
          RandomResidual(&random));
  }
  return r;
}

// Every residual at and next to the token boundaries of the zig-zag values
// (powers of two) and the int32 limits, in context |context|.
Residuals BoundaryResiduals(int context) {
  Residuals r;
  for (int k = 0; k <= 30; ++k) {
    const int32_t power = int32_t{1} << k;
    for (const int32_t value : {power - 1, power, power + 1}) {
      r.Add(context, value);
      r.Add(context, -value);
    }
  }
  for (const int32_t value : {std::numeric_limits<int32_t>::max(),
                              std::numeric_limits<int32_t>::max() - 1,
                              std::numeric_limits<int32_t>::min(),
                              std::numeric_limits<int32_t>::min() + 1}) {
    r.Add(context, value);
  }
  return r;
}

// Table starts the tests encode with: one table, every context in its own,
// a mix, and kChosen, the encoder's own choice.
constexpr uint16_t kChosen = 0xffff;
constexpr uint16_t kTableStarts[] = {0, kUvResidualAllTables, 0x254, kChosen};

std::vector<char> Encode(const Residuals &r, uint16_t table_starts) {
  UvResidualEncoder encoder;
  encoder.Reset(r.size());
  for (int i = 0; i < r.size(); ++i) {
    encoder.Add(r.contexts[i], r.values[i]);
  }
  EncoderBuffer buffer;
  EXPECT_TRUE(table_starts == kChosen ? encoder.Encode(&buffer)
                                      : encoder.Encode(table_starts, &buffer));
  return std::vector<char>(buffer.data(), buffer.data() + buffer.size());
}

// Decodes |count| residuals from |bytes| with |decoder|, asking for the
// contexts of |r| (context 0 past its end); false as soon as Decode() or
// Next() fails.
bool Decode(const std::vector<char> &bytes, int count, const Residuals &r,
            UvResidualDecoder *decoder, std::vector<int32_t> *values) {
  DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size(), kDracoMeshBitstreamVersion);
  if (!decoder->Decode(count, &buffer)) {
    return false;
  }
  values->resize(count);
  for (int i = 0; i < count; ++i) {
    const int context = i < r.size() ? r.contexts[i] : 0;
    if (!decoder->Next(context, &(*values)[i])) {
      return false;
    }
  }
  return true;
}

// True when |r| encoded with |table_starts| decodes to itself.
bool RoundTrips(const Residuals &r, uint16_t table_starts) {
  UvResidualDecoder decoder;
  std::vector<int32_t> values;
  return Decode(Encode(r, table_starts), r.size(), r, &decoder, &values) &&
         values == r.values;
}

TEST(UvResidualCoderTest, RoundTripsRandomSequencesWithEveryTableLayout) {
  for (uint32_t seed = 0; seed < 200; ++seed) {
    const Residuals r = RandomResiduals(1 + 37 * seed, seed);
    for (const uint16_t table_starts : kTableStarts) {
      EXPECT_TRUE(RoundTrips(r, table_starts))
          << "seed " << seed << " contexts " << table_starts;
    }
  }
}

TEST(UvResidualCoderTest,
     RoundTripsTokenBoundariesAndInt32LimitsInEveryContext) {
  for (int context = 0; context < kUvResidualNumContexts; ++context) {
    for (const uint16_t table_starts : kTableStarts) {
      EXPECT_TRUE(RoundTrips(BoundaryResiduals(context), table_starts))
          << "context " << context << " contexts " << table_starts;
    }
  }
}

// Small and huge residuals interleaved, and contexts used unevenly (some
// not at all), so that the raw bits of one context sit between the tokens
// of others.
TEST(UvResidualCoderTest, RoundTripsMixedMagnitudesAndUnusedContexts) {
  std::mt19937 random(5);
  for (int trial = 0; trial < 50; ++trial) {
    const int num_used = 1 + trial % kUvResidualNumContexts;
    Residuals r;
    for (int i = 0; i < 500; ++i) {
      const int context = static_cast<int>(random() % num_used);
      r.Add(context, i % 2 ? static_cast<int32_t>(random() % 7) - 3
                           : RandomResidual(&random));
    }
    for (const uint16_t table_starts : kTableStarts) {
      EXPECT_TRUE(RoundTrips(r, table_starts)) << "trial " << trial;
    }
  }
}

TEST(UvResidualCoderTest, EmptySequenceRoundTripsAndHasNoResidualToGive) {
  for (const uint16_t table_starts : kTableStarts) {
    const std::vector<char> bytes = Encode(Residuals(), table_starts);
    DecoderBuffer buffer;
    buffer.Init(bytes.data(), bytes.size(), kDracoMeshBitstreamVersion);
    UvResidualDecoder decoder;
    ASSERT_TRUE(decoder.Decode(0, &buffer)) << table_starts;
    EXPECT_EQ(buffer.remaining_size(), 0) << table_starts;
    int32_t value;
    for (int context = 0; context < kUvResidualNumContexts; ++context) {
      EXPECT_FALSE(decoder.Next(context, &value)) << context;
    }
  }
}

// Decode() reads exactly the encoder's bytes, so that the caller's data
// can follow them.
TEST(UvResidualCoderTest, DecodeConsumesExactlyTheEncodedBytes) {
  for (uint32_t seed = 0; seed < 20; ++seed) {
    const Residuals r = RandomResiduals(100 * seed, seed);
    for (const uint16_t table_starts : kTableStarts) {
      std::vector<char> bytes = Encode(r, table_starts);
      const size_t size = bytes.size();
      bytes.insert(bytes.end(), {'t', 'a', 'i', 'l'});
      DecoderBuffer buffer;
      buffer.Init(bytes.data(), bytes.size(), kDracoMeshBitstreamVersion);
      UvResidualDecoder decoder;
      ASSERT_TRUE(decoder.Decode(r.size(), &buffer));
      EXPECT_EQ(buffer.decoded_size(), static_cast<int64_t>(size))
          << "seed " << seed;
    }
  }
}

TEST(UvResidualCoderTest, NextFailsOnceAContextIsExhausted) {
  for (uint32_t seed = 0; seed < 30; ++seed) {
    const Residuals r = RandomResiduals(50 + seed, seed);
    for (const uint16_t table_starts : kTableStarts) {
      UvResidualDecoder decoder;
      std::vector<int32_t> values;
      ASSERT_TRUE(
          Decode(Encode(r, table_starts), r.size(), r, &decoder, &values));
      int32_t value;
      for (int context = 0; context < kUvResidualNumContexts; ++context) {
        EXPECT_FALSE(decoder.Next(context, &value))
            << "seed " << seed << " context " << context;
      }
    }
  }
}

TEST(UvResidualCoderTest, NextRejectsContextsOutsideTheTables) {
  const Residuals r = RandomResiduals(100, 1);
  const std::vector<char> bytes = Encode(r, kChosen);
  DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size(), kDracoMeshBitstreamVersion);
  UvResidualDecoder decoder;
  ASSERT_TRUE(decoder.Decode(r.size(), &buffer));
  int32_t value;
  for (const int context : {-1, kUvResidualNumContexts, 1000}) {
    EXPECT_FALSE(decoder.Next(context, &value)) << context;
  }
}

TEST(UvResidualCoderTest, DecodeRejectsAnyOtherCount) {
  for (uint32_t seed = 0; seed < 20; ++seed) {
    const Residuals r = RandomResiduals(10 * seed, seed);
    for (const uint16_t table_starts : kTableStarts) {
      const std::vector<char> bytes = Encode(r, table_starts);
      for (const int count : {r.size() - 1, r.size() + 1, -1}) {
        DecoderBuffer buffer;
        buffer.Init(bytes.data(), bytes.size(), kDracoMeshBitstreamVersion);
        UvResidualDecoder decoder;
        EXPECT_FALSE(decoder.Decode(count, &buffer))
            << "seed " << seed << " count " << count << " of " << r.size();
      }
    }
  }
}

TEST(UvResidualCoderTest, DecodeRejectsEveryTruncation) {
  for (uint32_t seed = 0; seed < 12; ++seed) {
    const Residuals r = RandomResiduals(20 * seed, seed);
    for (const uint16_t table_starts : kTableStarts) {
      const std::vector<char> bytes = Encode(r, table_starts);
      for (size_t size = 0; size < bytes.size(); ++size) {
        DecoderBuffer buffer;
        buffer.Init(bytes.data(), size, kDracoMeshBitstreamVersion);
        UvResidualDecoder decoder;
        EXPECT_FALSE(decoder.Decode(r.size(), &buffer))
            << "seed " << seed << ": " << size << " of " << bytes.size();
      }
    }
  }
}

// The stream starts with the table starts, a uint16 in which only the bits
// of contexts 1 .. kUvResidualNumContexts - 1 may be set.
TEST(UvResidualCoderTest, DecodeRejectsInvalidTableStarts) {
  const Residuals r = RandomResiduals(200, 2);
  std::vector<char> bytes = Encode(r, kChosen);
  int rejected = 0;
  for (uint32_t starts = 0; starts < 0x10000; ++starts) {
    if ((starts & ~uint32_t{kUvResidualAllTables}) == 0) {
      continue;
    }
    bytes[0] = static_cast<char>(starts & 0xff);
    bytes[1] = static_cast<char>(starts >> 8);
    DecoderBuffer buffer;
    buffer.Init(bytes.data(), bytes.size(), kDracoMeshBitstreamVersion);
    UvResidualDecoder decoder;
    rejected += !decoder.Decode(r.size(), &buffer);
  }
  EXPECT_EQ(rejected, 0x10000 - (1 << (kUvResidualNumContexts - 1)));
}

// The encoder's choice of tables is never bigger than one table or one per
// context, and merges contexts whose residuals are alike.
TEST(UvResidualCoderTest, ChosenTablesAreNoBiggerThanOneOrAllTables) {
  for (uint32_t seed = 0; seed < 30; ++seed) {
    std::mt19937 random(seed);
    Residuals r;
    const int count = 100 + 1000 * (seed % 10);
    for (int i = 0; i < count; ++i) {
      // Contexts in pairs of alike residuals; the pairs differ.
      const int context = static_cast<int>(random() % kUvResidualNumContexts);
      const int32_t bound = int32_t{1} << (context / 2 * (seed % 3 + 1));
      r.Add(context, static_cast<int32_t>(random() % (2 * bound)) - bound);
    }
    const size_t chosen = Encode(r, kChosen).size();
    EXPECT_LE(chosen, Encode(r, 0).size()) << seed;
    EXPECT_LE(chosen, Encode(r, kUvResidualAllTables).size()) << seed;
    EXPECT_TRUE(RoundTrips(r, kChosen)) << seed;
  }
}

// Altered bytes may still form a valid stream (nothing checks the raw bits
// or the rANS data), but decoding them returns false or values and never
// crashes; where the counts, tables or tokens no longer fit, it returns
// false (about a third of these alterations; the test asks for a tenth).
TEST(UvResidualCoderTest, CorruptStreamsFailOrDecodeWithoutCrashing) {
  std::mt19937 random(9);
  int rejected = 0, trials = 0;
  for (uint32_t seed = 0; seed < 20; ++seed) {
    const Residuals r = RandomResiduals(300, 1000 + seed);
    for (const uint16_t table_starts : kTableStarts) {
      const std::vector<char> bytes = Encode(r, table_starts);
      for (int trial = 0; trial < 100; ++trial, ++trials) {
        std::vector<char> corrupt = bytes;
        for (int flips = 1 + trial % 3; flips > 0; --flips) {
          corrupt[random() % corrupt.size()] ^=
              static_cast<char>(1 + random() % 255);
        }
        UvResidualDecoder decoder;
        std::vector<int32_t> values;
        rejected += !Decode(corrupt, r.size(), r, &decoder, &values);
      }
    }
  }
  EXPECT_GT(rejected, trials / 10);
}

// Per-context tables are what the contexts are for: when the contexts'
// distributions differ, they code smaller than one table.
TEST(UvResidualCoderTest, ContextsCodeSmallerWhenTheirDistributionsDiffer) {
  for (uint32_t seed = 0; seed < 10; ++seed) {
    std::mt19937 random(seed);
    Residuals r;
    for (int i = 0; i < 20000; ++i) {
      // Context c: residuals of magnitude below 2^c, most of them tokens.
      const int context = static_cast<int>(random() % kUvResidualNumContexts);
      const int32_t bound = int32_t{1} << context;
      r.Add(context, static_cast<int32_t>(random() % (2 * bound)) - bound);
    }
    EXPECT_LT(Encode(r, kUvResidualAllTables).size(), Encode(r, 0).size()) << seed;
    EXPECT_TRUE(RoundTrips(r, kUvResidualAllTables)) << seed;
  }
}

TEST(UvResidualCoderTest, ResetDropsEarlierResiduals) {
  for (uint32_t seed = 0; seed < 10; ++seed) {
    const Residuals earlier = RandomResiduals(100, seed);
    const Residuals r = RandomResiduals(100, 100 + seed);
    UvResidualEncoder encoder;
    for (int i = 0; i < earlier.size(); ++i) {
      encoder.Add(earlier.contexts[i], earlier.values[i]);
    }
    encoder.Reset(r.size());
    for (int i = 0; i < r.size(); ++i) {
      encoder.Add(r.contexts[i], r.values[i]);
    }
    for (const uint16_t table_starts : kTableStarts) {
      EncoderBuffer buffer;
      ASSERT_TRUE(table_starts == kChosen ? encoder.Encode(&buffer)
                                         : encoder.Encode(table_starts, &buffer));
      EXPECT_EQ(std::vector<char>(buffer.data(), buffer.data() + buffer.size()),
                Encode(r, table_starts))
          << seed;
    }
  }
}

// One decoder for stream after stream (as a scheme decodes attribute after
// attribute), including after a failed Decode().
TEST(UvResidualCoderTest, DecoderStartsAfreshOnEveryStream) {
  UvResidualDecoder decoder;
  std::vector<int32_t> values;
  for (uint32_t seed = 0; seed < 40; ++seed) {
    const Residuals r = RandomResiduals(1 + 13 * seed, seed);
    const uint16_t table_starts = kTableStarts[seed % 4];
    const std::vector<char> bytes = Encode(r, table_starts);
    if (seed % 5 == 0) {
      EXPECT_FALSE(Decode(bytes, r.size() + 1, r, &decoder, &values));
    }
    ASSERT_TRUE(Decode(bytes, r.size(), r, &decoder, &values)) << seed;
    EXPECT_EQ(values, r.values) << seed;
  }
}

}  // namespace
}  // namespace draco
