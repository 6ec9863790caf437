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
#include "draco/core/bit_utils.h"
#include "draco/core/varint_decoding.h"
#include "draco/core/varint_encoding.h"
#include "draco_ext/common/rans_token_table.h"

namespace draco {

namespace {

constexpr int kFirstSplitBits = 4;  // bitlen(z) - 1 of the first split token.
// z < 2^32: n <= 31, so tokens stay below 16 + 2 * 28.
constexpr uint32_t kNumTokens =
    kUvResidualDirectTokens + 2 * (32 - kFirstSplitBits);
static_assert(kNumTokens <= kMaxRansTokens, "tokens fit the table");

// The fixed cost of a table in 1/65536 bits: its token count, rANS length
// and rANS final state, about 6 bytes; an empty table costs its count.
constexpr uint64_t kTableOverheadInBitUnits = uint64_t{48} << 16;
constexpr uint64_t kEmptyTableInBitUnits = uint64_t{8} << 16;

typedef std::vector<uint32_t> Histogram;

Histogram Merged(const Histogram &a, const Histogram &b) {
  Histogram sum(a);
  for (size_t i = 0; i < b.size(); ++i) {
    sum[i] += b[i];
  }
  return sum;
}

// What one table of |histogram| costs, in 1/65536 bits.
uint64_t CostOfTable(const Histogram &histogram) {
  RansTokenTable table;
  if (!table.InitFromCounts(histogram)) {
    return kEmptyTableInBitUnits;
  }
  return kTableOverheadInBitUnits + table.CostInBitUnits(histogram);
}

// The table of each of |num_contexts| contexts under |table_starts|.
std::array<uint8_t, kMaxResidualContexts> TablesOfContexts(
    uint16_t table_starts, int num_contexts) {
  std::array<uint8_t, kMaxResidualContexts> table_of = {};
  int table = 0;
  for (int c = 0; c < num_contexts; ++c) {
    table += (table_starts >> c) & 1;
    table_of[c] = static_cast<uint8_t>(table);
  }
  return table_of;
}

}  // namespace

void UvResidualEncoder::Reset(int expected) {
  symbols_.clear();
  symbols_.reserve(expected);
}

void UvResidualEncoder::Add(int context, int32_t residual) {
  DRACO_DCHECK_LT(context, num_contexts_);
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

uint16_t UvResidualEncoder::ChooseTableStarts() const {
  // Runs of neighbouring contexts: first context, histogram, cost.
  struct Run {
    int first;
    Histogram histogram;
    uint64_t cost;
  };
  std::vector<Run> runs(num_contexts_);
  for (int c = 0; c < num_contexts_; ++c) {
    runs[c] = {c, Histogram(kNumTokens, 0), 0};
  }
  for (const Symbol &symbol : symbols_) {
    ++runs[symbol.context].histogram[symbol.token];
  }
  for (Run &run : runs) {
    run.cost = CostOfTable(run.histogram);
  }
  // Merge the neighbours whose merge saves most until none saves.
  while (runs.size() > 1) {
    size_t best = 0;
    uint64_t best_saving = 0, best_cost = 0;
    Histogram best_histogram;
    for (size_t i = 0; i + 1 < runs.size(); ++i) {
      Histogram merged = Merged(runs[i].histogram, runs[i + 1].histogram);
      const uint64_t cost = CostOfTable(merged);
      const uint64_t separate = runs[i].cost + runs[i + 1].cost;
      if (cost < separate && separate - cost > best_saving) {
        best_saving = separate - cost;
        best_cost = cost;
        best = i;
        best_histogram.swap(merged);
      }
    }
    if (best_saving == 0) {
      break;
    }
    runs[best].histogram.swap(best_histogram);
    runs[best].cost = best_cost;
    runs.erase(runs.begin() + best + 1);
  }
  uint16_t table_starts = 0;
  for (size_t i = 1; i < runs.size(); ++i) {
    table_starts |= static_cast<uint16_t>(1u << runs[i].first);
  }
  return table_starts;
}

bool UvResidualEncoder::Encode(EncoderBuffer *buffer) const {
  return Encode(ChooseTableStarts(), buffer);
}

bool UvResidualEncoder::Encode(uint16_t table_starts,
                               EncoderBuffer *buffer) const {
  if (num_contexts_ < 1 || num_contexts_ > kMaxResidualContexts ||
      (table_starts & ~ResidualAllTables(num_contexts_)) != 0) {
    return false;
  }
  const std::array<uint8_t, kMaxResidualContexts> table_of =
      TablesOfContexts(table_starts, num_contexts_);
  const int num_tables = table_of[num_contexts_ - 1] + 1;
  std::vector<std::vector<uint32_t>> tokens(num_tables);
  std::vector<Histogram> histograms(num_tables, Histogram(kNumTokens, 0));
  DirectBitEncoder raw_bits;
  raw_bits.StartEncoding();
  for (const Symbol &symbol : symbols_) {
    const int table = table_of[symbol.context];
    tokens[table].push_back(symbol.token);
    ++histograms[table][symbol.token];
    if (symbol.num_raw_bits > 0) {
      raw_bits.EncodeLeastSignificantBits32(symbol.num_raw_bits,
                                            symbol.raw_bits);
    }
  }
  buffer->Encode(table_starts);
  std::vector<RansTokenTable> tables(num_tables);
  BitWriter table_bits;
  for (int t = 0; t < num_tables; ++t) {
    EncodeVarint(static_cast<uint32_t>(tokens[t].size()), buffer);
    if (!tokens[t].empty()) {
      if (!tables[t].InitFromCounts(histograms[t])) {
        return false;
      }
      tables[t].Write(&table_bits);
    }
  }
  EncodeVarint(static_cast<uint32_t>(table_bits.bytes().size()), buffer);
  buffer->Encode(table_bits.bytes().data(), table_bits.bytes().size());
  for (int t = 0; t < num_tables; ++t) {
    if (!tokens[t].empty() && !EncodeRansTokens(tables[t], tokens[t], buffer)) {
      return false;
    }
  }
  raw_bits.EndEncoding(buffer);
  return true;
}

bool UvResidualDecoder::Decode(int count, DecoderBuffer *buffer) {
  uint16_t table_starts;
  if (count < 0 || num_contexts_ < 1 || num_contexts_ > kMaxResidualContexts ||
      !buffer->Decode(&table_starts) ||
      (table_starts & ~ResidualAllTables(num_contexts_)) != 0) {
    return false;
  }
  table_of_ = TablesOfContexts(table_starts, num_contexts_);
  const int num_tables = table_of_[num_contexts_ - 1] + 1;
  std::array<uint32_t, kMaxResidualContexts> counts = {};
  int64_t total = 0;
  for (int t = 0; t < num_tables; ++t) {
    if (!DecodeVarint(&counts[t], buffer) || counts[t] > count - total) {
      return false;
    }
    total += counts[t];
  }
  return total == count && DecodeTables(counts, num_tables, buffer) &&
         raw_bits_.StartDecoding(buffer);
}

bool UvResidualDecoder::DecodeTables(
    const std::array<uint32_t, kMaxResidualContexts> &counts, int num_tables,
    DecoderBuffer *buffer) {
  uint32_t table_bytes;
  if (!DecodeVarint(&table_bytes, buffer) ||
      table_bytes > static_cast<uint64_t>(buffer->remaining_size())) {
    return false;
  }
  BitReader reader(reinterpret_cast<const uint8_t *>(buffer->data_head()),
                   table_bytes);
  std::array<RansTokenTable, kMaxResidualContexts> tables;
  for (int t = 0; t < num_tables; ++t) {
    if (counts[t] > 0 && !tables[t].Read(&reader)) {
      return false;
    }
  }
  buffer->Advance(table_bytes);
  for (int t = 0; t < kMaxResidualContexts; ++t) {
    remaining_[t] = 0;
    if (t < num_tables && counts[t] > 0) {
      if (!StartRansTokens(tables[t], buffer, &decoders_[t])) {
        return false;
      }
      remaining_[t] = counts[t];
    }
  }
  return true;
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
