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

#include <cmath>
#include <random>

#include "gtest/gtest.h"

namespace draco {
namespace {

struct CodedBits {
  std::vector<bool> bits;
  std::vector<uint32_t> probabilities;
  std::vector<uint8_t> bytes;
};

// |count| bits drawn with random probabilities, coded with those
// probabilities.
CodedBits RandomCodedBits(int count, uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<uint32_t> probability(1, 4095);
  CodedBits coded;
  UvSeamRangeEncoder encoder;
  for (int i = 0; i < count; ++i) {
    const uint32_t p = probability(random);
    const bool bit = random() % 4096 < p;
    encoder.EncodeBit(bit, p);
    coded.bits.push_back(bit);
    coded.probabilities.push_back(p);
  }
  coded.bytes = encoder.Finish();
  return coded;
}

// Decodes |bytes| with the probabilities of |coded|; true if every bit
// and the tail match.
bool DecodesTo(const std::vector<uint8_t> &bytes, const CodedBits &coded) {
  UvSeamRangeDecoder decoder(bytes.data(), bytes.size());
  bool same = true;
  for (size_t i = 0; i < coded.bits.size(); ++i) {
    same = decoder.DecodeBit(coded.probabilities[i]) == coded.bits[i] && same;
  }
  return decoder.Finish() && same;
}

TEST(UvSeamRangeCoderTest, RoundTripsBitsWithChangingProbabilities) {
  for (uint32_t seed = 0; seed < 50; ++seed) {
    const CodedBits coded = RandomCodedBits(1 + 97 * seed, seed);
    EXPECT_TRUE(DecodesTo(coded.bytes, coded)) << "seed " << seed;
  }
}

TEST(UvSeamRangeCoderTest, SpendsWithinTwoBytesOfTheInformationContent) {
  for (uint32_t seed = 0; seed < 20; ++seed) {
    const CodedBits coded = RandomCodedBits(5000, seed);
    double bits = 0;
    for (size_t i = 0; i < coded.bits.size(); ++i) {
      const double p = coded.probabilities[i] / 4096.0;
      bits -= std::log2(coded.bits[i] ? p : 1 - p);
    }
    EXPECT_LE(coded.bytes.size(), std::ceil(bits / 8) + 2) << seed;
  }
}

TEST(UvSeamRangeCoderTest, CertainBitsCostNoBytes) {
  UvSeamRangeEncoder encoder;
  EXPECT_TRUE(encoder.Finish().empty());
  UvSeamRangeEncoder zeros;
  for (int i = 0; i < 1000; ++i) {
    zeros.EncodeBit(false, 1);
  }
  EXPECT_LE(zeros.Finish().size(), 1u);
}

// Every altered byte changes the decoded bits or fails Finish(); a
// shortened or lengthened stream fails Finish().
TEST(UvSeamRangeCoderTest, NoticesEveryAlteredOrShortenedStream) {
  for (uint32_t seed = 0; seed < 10; ++seed) {
    const CodedBits coded = RandomCodedBits(400, 100 + seed);
    ASSERT_FALSE(coded.bytes.empty());
    for (size_t i = 0; i < coded.bytes.size(); ++i) {
      std::vector<uint8_t> altered = coded.bytes;
      altered[i] ^= 1 + (seed % 255);
      EXPECT_FALSE(DecodesTo(altered, coded)) << "byte " << i;
      const std::vector<uint8_t> prefix(coded.bytes.begin(),
                                        coded.bytes.begin() + i);
      EXPECT_FALSE(DecodesTo(prefix, coded)) << "prefix " << i;
    }
    std::vector<uint8_t> longer = coded.bytes;
    longer.push_back(0);
    EXPECT_FALSE(DecodesTo(longer, coded));
  }
}

}  // namespace
}  // namespace draco
