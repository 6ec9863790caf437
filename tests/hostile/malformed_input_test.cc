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
// The decoder treats its input as hostile: every golden file
// (testdata/golden/, one per mesh and row of variants.tsv, so new schemes
// are covered by adding a row; the lossy Laplacian schemes by theirs,
// testdata/golden/lossy/) truncated at every byte, with bits
// flipped, with the draco-uv header fields and the prediction scheme id
// replaced by unknown values and with huge counts either decodes or fails with
// a message; it never crashes, hangs or allocates without bound. So do the
// tangent golden files (testdata/golden/tangent_variants.tsv), with every
// field of MESH_PREDICTION_GEOMETRIC_TANGENT's header set out of range. The
// sanitizer builds of scripts/fuzz.sh go further on the same seeds.
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_data.h"
#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_tex_coords_decoder.h"
#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_tex_coords_portable_decoder.h"
#include "draco/compression/attributes/prediction_schemes/prediction_scheme_wrap_decoding_transform.h"
#include "draco/compression/bit_coders/rans_bit_encoder.h"
#include "draco/compression/decode.h"
#include "draco/core/varint_encoding.h"
#include "draco/io/file_utils.h"
#include "draco_ext/common/uv_bitstream_guard.h"
#include "draco_ext/common/uv_prediction_ids.h"
#include "draco_ext/common/uv_residual_coder.h"
#include "gtest/gtest.h"
#include "prediction_schemes/tangent/mesh_prediction_scheme_geometric_tangent_shared.h"
#include "prediction_schemes/weighted/mesh_prediction_scheme_tex_coords_weighted_shared.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

namespace fs = std::filesystem;

// Peak resident memory a test in this file may reach: decoding the small
// golden files needs a few MB; a count taken from corrupt data and
// allocated as such would go far beyond.
constexpr long kMaxPeakRssKb = 512 * 1024;

struct GoldenFile {
  std::string name;
  std::vector<char> data;
};

// The .drc files of testdata/|folder|, sorted by name.
std::vector<GoldenFile> DrcFilesIn(const std::string &folder) {
  std::vector<GoldenFile> files;
  for (const auto &entry : fs::directory_iterator(UvTestdataPath(folder))) {
    if (entry.path().extension() == ".drc") {
      GoldenFile file{entry.path().filename().string(), {}};
      EXPECT_TRUE(ReadFileToBuffer(entry.path().string(), &file.data));
      files.push_back(std::move(file));
    }
  }
  std::sort(
      files.begin(), files.end(),
      [](const GoldenFile &a, const GoldenFile &b) { return a.name < b.name; });
  return files;
}

std::vector<GoldenFile> GoldenFiles() { return DrcFilesIn("golden"); }

// The golden files of the exact and of the lossy (Laplacian) schemes, for
// the layout-free tests.
std::vector<GoldenFile> GoldenAndLaplacianFiles() {
  std::vector<GoldenFile> files = GoldenFiles();
  for (GoldenFile &file : DrcFilesIn("golden/lossy")) {
    files.push_back(std::move(file));
  }
  return files;
}

// Decodes |size| bytes of |data|; an error must carry a message.
Status Decode(const char *data, size_t size) {
  DecoderBuffer buffer;
  buffer.Init(data, size);
  Decoder decoder;
  const Status status = decoder.DecodeMeshFromBuffer(&buffer).status();
  EXPECT_TRUE(status.ok() || !status.error_msg_string().empty());
  return status;
}

Status Decode(const std::vector<char> &data) {
  return Decode(data.data(), data.size());
}

long PeakRssKb() {
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// Offset of the draco-uv bitstream guard in |data|, or -1 (stock files).
int GuardOffset(const std::vector<char> &data) {
  char guard[8];
  const int32_t words[2] = {kUvGuardFirst, kUvGuardSecond};
  std::memcpy(guard, words, sizeof(guard));
  const auto it = std::search(data.begin(), data.end(), guard, guard + 8);
  return it == data.end() ? -1 : static_cast<int>(it - data.begin());
}

// The golden files of the weighted schemes (variants named weighted*),
// whose header layout UnknownHeaderValuesAreRejected knows. Other schemes'
// golden files get the layout-free tests (truncation, bit flips) by just
// being in testdata/golden/.
std::vector<GoldenFile> WeightedGoldenFiles() {
  std::vector<GoldenFile> files = GoldenFiles();
  files.erase(std::remove_if(files.begin(), files.end(),
                             [](const GoldenFile &f) {
                               return GuardOffset(f.data) < 0 ||
                                      f.name.find(".weighted") ==
                                          std::string::npos;
                             }),
              files.end());
  return files;
}

TEST(MalformedInputTest, GoldenFilesDecode) {
  const std::vector<GoldenFile> files = GoldenFiles();
  ASSERT_FALSE(files.empty()) << "run scripts/make-golden.sh";
  ASSERT_FALSE(WeightedGoldenFiles().empty());
  for (const GoldenFile &file : files) {
    EXPECT_TRUE(Decode(file.data).ok()) << file.name;
  }
}

TEST(MalformedInputTest, EveryTruncationFailsWithAMessage) {
  int tried = 0;
  for (const GoldenFile &file : GoldenAndLaplacianFiles()) {
    for (size_t size = 0; size < file.data.size(); ++size) {
      // A copy of exactly |size| bytes, so that ASan-free builds still
      // read nothing past the end unnoticed by the decoder's checks.
      const std::vector<char> prefix(file.data.begin(),
                                     file.data.begin() + size);
      EXPECT_FALSE(Decode(prefix).ok()) << file.name << " cut at " << size;
      ++tried;
    }
  }
  EXPECT_LT(PeakRssKb(), kMaxPeakRssKb);
  RecordProperty("truncations", tried);
}

// Every bit of the draco-uv header and the first residual bytes, and random
// bits anywhere; a flipped residual may decode to other values, which is
// fine, as long as nothing crashes.
TEST(MalformedInputTest, BitFlipsDecodeOrFailWithAMessage) {
  constexpr int kHeaderBytes = 48;
  constexpr int kRandomFlipsPerFile = 600;
  std::mt19937 rng(5);
  int tried = 0, failed = 0;
  for (const GoldenFile &file : GoldenAndLaplacianFiles()) {
    std::vector<size_t> bits;
    const int guard = GuardOffset(file.data);
    if (guard >= 0) {
      const size_t end =
          std::min(file.data.size(), static_cast<size_t>(guard + kHeaderBytes));
      for (size_t bit = 8 * guard; bit < 8 * end; ++bit) {
        bits.push_back(bit);
      }
    }
    std::uniform_int_distribution<size_t> any_bit(0, 8 * file.data.size() - 1);
    for (int i = 0; i < kRandomFlipsPerFile; ++i) {
      bits.push_back(any_bit(rng));
    }
    std::vector<char> data = file.data;
    for (const size_t bit : bits) {
      data[bit / 8] ^= static_cast<char>(1 << (bit % 8));
      failed += !Decode(data).ok();
      data[bit / 8] ^= static_cast<char>(1 << (bit % 8));
      ++tried;
    }
  }
  EXPECT_GT(failed, 0);
  EXPECT_LT(PeakRssKb(), kMaxPeakRssKb);
  RecordProperty("bit_flips", tried);
  RecordProperty("bit_flips_rejected", failed);
}

// The fields after the guard: format version, configuration byte and the
// residual coder's table starts (uint16, little-endian); then the first
// token count (varint).
TEST(MalformedInputTest, UnknownHeaderValuesAreRejected) {
  const std::vector<GoldenFile> files = WeightedGoldenFiles();
  ASSERT_FALSE(files.empty());
  int tried = 0;
  for (const GoldenFile &file : files) {
    const int guard = GuardOffset(file.data);
    const int version = guard + 8, config = guard + 9, starts = guard + 10;
    const auto expect_rejected = [&](int offset, int value) {
      std::vector<char> data = file.data;
      data[offset] = static_cast<char>(value);
      EXPECT_FALSE(Decode(data).ok())
          << file.name << ": byte " << offset << " = " << value;
      ++tried;
    };
    for (int byte = 0; byte < 8; ++byte) {
      expect_rejected(guard + byte, file.data[guard + byte] ^ 0x10);
    }
    for (const int value : {0, 1, 2, 255}) {
      expect_rejected(version, value);
    }
    for (int value = 7; value < 256; ++value) {
      expect_rejected(config, value);
    }
    // Context 0 never starts a table; there are no contexts from 10 on.
    expect_rejected(starts, file.data[starts] | 1);
    for (int value = 1 << (kUvResidualNumContexts - 8); value < 256;
         value <<= 1) {
      expect_rejected(starts + 1, file.data[starts + 1] | value);
    }
    // A token count of 2^32 - 1, far above the number of residuals.
    std::vector<char> huge(file.data.begin(), file.data.begin() + starts + 2);
    huge.insert(huge.end(), {'\xff', '\xff', '\xff', '\xff', '\x0f'});
    huge.insert(huge.end(), file.data.begin() + starts + 3, file.data.end());
    EXPECT_FALSE(Decode(huge).ok()) << file.name << ": huge token count";
    ++tried;
  }
  EXPECT_LT(PeakRssKb(), kMaxPeakRssKb);
  RecordProperty("header_values", tried);
}

// The prediction scheme id of the texture coordinates: the first byte at
// which a draco-uv golden file differs from the stock one of the same mesh
// and settings (positions and connectivity come first and are identical).
int PredictionIdOffset(const std::vector<char> &ours,
                       const std::vector<char> &stock) {
  const auto mismatch =
      std::mismatch(ours.begin(), ours.end(), stock.begin(), stock.end());
  return static_cast<int>(mismatch.first - ours.begin());
}

TEST(MalformedInputTest, UnknownOrMismatchedPredictionIdsAreRejected) {
  int tried = 0;
  for (const std::string mesh : {"torus_uv", "bumpy_cube_sphere", "cube_att"}) {
    std::vector<char> stock, weighted, multi;
    ASSERT_TRUE(ReadFileToBuffer(
        UvTestdataPath("golden/" + mesh + ".stock.drc"), &stock));
    ASSERT_TRUE(ReadFileToBuffer(
        UvTestdataPath("golden/" + mesh + ".weighted.drc"), &weighted));
    ASSERT_TRUE(ReadFileToBuffer(
        UvTestdataPath("golden/" + mesh + ".weighted_multi.drc"), &multi));
    const int id = PredictionIdOffset(weighted, stock);
    ASSERT_EQ(id, PredictionIdOffset(multi, stock)) << mesh;
    ASSERT_EQ(weighted[id], MESH_PREDICTION_TEX_COORDS_WEIGHTED) << mesh;
    ASSERT_EQ(multi[id], MESH_PREDICTION_TEX_COORDS_WEIGHTED_MULTI) << mesh;
    // Ids no decoder knows (beyond the enum, so that schemes added to it
    // later do not turn them into valid ids).
    const int num_ids = NUM_PREDICTION_SCHEMES;
    for (const int value :
         {num_ids, num_ids + 1, 42, 127, PREDICTION_NONE - 1, -128}) {
      for (std::vector<char> data : {weighted, multi}) {
        data[id] = static_cast<char>(value);
        EXPECT_FALSE(Decode(data).ok()) << mesh << ": id " << value;
        ++tried;
      }
    }
    // Every transform type byte (it follows the id).
    for (int value = -128; value < 128; ++value) {
      std::vector<char> data = weighted;
      data[id + 1] = static_cast<char>(value);
      Decode(data);
      ++tried;
    }
    // The multi-stencil id accepts the single-stencil configuration (it may
    // use every configuration); the single-stencil id promises stock speed
    // and rejects multi-stencil data.
    std::vector<char> relabelled = weighted;
    relabelled[id] = MESH_PREDICTION_TEX_COORDS_WEIGHTED_MULTI;
    const auto as_multi = DecodeDracoMesh(relabelled);
    const auto original = DecodeDracoMesh(weighted);
    ASSERT_TRUE(as_multi.ok() && original.ok()) << mesh;
    EXPECT_EQ(CornerValues(*as_multi.value(), GeometryAttribute::TEX_COORD),
              CornerValues(*original.value(), GeometryAttribute::TEX_COORD));
    UvPredictionConfig config;
    ASSERT_TRUE(config.FromByte(multi[GuardOffset(multi) + 9]));
    relabelled = multi;
    relabelled[id] = MESH_PREDICTION_TEX_COORDS_WEIGHTED;
    EXPECT_EQ(Decode(relabelled).ok(), UsesReachStencil(config.kind)) << mesh;
    tried += 2;
  }
  RecordProperty("prediction_ids", tried);
}

// Where MESH_PREDICTION_GEOMETRIC_TANGENT's header lies in a file: the
// bitstream guard, the format version after it, GeometricTangentConfig from
// |config|, the TangentExceptions its flags ask for, the token count (a
// varint) from |tokens| and the residual streams from |streams|.
struct TangentHeader {
  int guard = -1;
  int config = -1;
  int config_end = -1;
  int tokens = -1;
  int streams = -1;
  GeometricTangentConfig value;
};

// The last bitstream guard in |data| followed by the tangent format version
// and a configuration the decoder accepts (the tangents are the texture
// coordinates' child, so their header comes after a UV scheme's); guard -1
// where there is none.
TangentHeader FindTangentHeader(const std::vector<char> &data) {
  char guard[8];
  const int32_t words[2] = {kUvGuardFirst, kUvGuardSecond};
  std::memcpy(guard, words, sizeof(guard));
  TangentHeader found;
  for (auto it = std::search(data.begin(), data.end(), guard, guard + 8);
       it != data.end(); it = std::search(it + 1, data.end(), guard, guard + 8)) {
    const int offset = static_cast<int>(it - data.begin());
    if (offset + 9 >= static_cast<int>(data.size()) ||
        data[offset + 8] != kGeometricTangentFormatVersion) {
      continue;
    }
    DecoderBuffer buffer;
    buffer.Init(data.data() + offset + 9, data.size() - offset - 9);
    GeometricTangentConfig config;
    if (!config.Decode(&buffer)) {
      continue;
    }
    const int config_size = static_cast<int>(buffer.decoded_size());
    TangentExceptions exceptions;
    uint32_t num_tokens;
    if ((config.handedness_exceptions &&
         !exceptions.Decode(true, std::numeric_limits<int>::max(), &buffer)) ||
        (config.copy_exceptions &&
         !exceptions.Decode(false, std::numeric_limits<int>::max(),
                            &buffer))) {
      continue;
    }
    const int tokens = offset + 9 + static_cast<int>(buffer.decoded_size());
    if (!DecodeVarint(&num_tokens, &buffer)) {
      continue;
    }
    found.guard = offset;
    found.config = offset + 9;
    found.config_end = found.config + config_size;
    found.tokens = tokens;
    found.streams = offset + 9 + static_cast<int>(buffer.decoded_size());
    found.value = config;
  }
  return found;
}

// |data| with the configuration of |header| replaced by |bytes|.
std::vector<char> WithConfigBytes(const std::vector<char> &data,
                                  const TangentHeader &header,
                                  const std::vector<char> &bytes) {
  std::vector<char> result(data.begin(), data.begin() + header.config);
  result.insert(result.end(), bytes.begin(), bytes.end());
  result.insert(result.end(), data.begin() + header.config_end, data.end());
  return result;
}

std::vector<char> ConfigBytes(const GeometricTangentConfig &config) {
  EncoderBuffer buffer;
  config.Encode(&buffer);
  return std::vector<char>(buffer.data(), buffer.data() + buffer.size());
}

// The golden files of the tangent settings (rows of tangent_variants.tsv,
// named tangent_*), split into those of the geometric scheme and those of
// stock coding (tangent_draco_*).
std::vector<GoldenFile> TangentGoldenFiles(bool geometric) {
  std::vector<GoldenFile> files = GoldenFiles();
  files.erase(std::remove_if(files.begin(), files.end(),
                             [&](const GoldenFile &f) {
                               return f.name.find(".tangent_") ==
                                          std::string::npos ||
                                      (f.name.find(".tangent_draco_") ==
                                       std::string::npos) != geometric;
                             }),
              files.end());
  return files;
}

// The stock-coded golden file of the same mesh and -qtg as |name|
// (MESH.tangent_CONVENTION_qtgN.drc -> MESH.tangent_draco_qtgN.drc).
std::string StockTangentName(const std::string &name) {
  const size_t begin = name.find(".tangent_") + 9;
  const size_t end = name.rfind("_qtg");
  return name.substr(0, begin) + "draco" + name.substr(end);
}

// The golden rows really use the scheme (a stock fallback would pin
// nothing of it), stock rows do not, and every tangent golden file decodes
// to exactly the values of the stock-coded file of its mesh and -qtg.
TEST(MalformedInputTest, TangentGoldenFilesUseTheSchemeAndDecodeToStockValues) {
  const std::vector<GoldenFile> files = TangentGoldenFiles(true);
  const std::vector<GoldenFile> stock = TangentGoldenFiles(false);
  ASSERT_FALSE(files.empty()) << "run scripts/make-golden.sh";
  ASSERT_FALSE(stock.empty());
  for (const GoldenFile &file : stock) {
    EXPECT_LT(FindTangentHeader(file.data).guard, 0) << file.name;
  }
  for (const GoldenFile &file : files) {
    EXPECT_GE(FindTangentHeader(file.data).guard, 0) << file.name;
    std::vector<char> reference;
    ASSERT_TRUE(ReadFileToBuffer(
        UvTestdataPath("golden/" + StockTangentName(file.name)), &reference))
        << file.name;
    const auto ours = DecodeDracoMesh(file.data);
    const auto theirs = DecodeDracoMesh(reference);
    ASSERT_TRUE(ours.ok() && theirs.ok()) << file.name;
    for (const GeometryAttribute::Type type :
         {GeometryAttribute::POSITION, GeometryAttribute::NORMAL,
          GeometryAttribute::TEX_COORD, GeometryAttribute::GENERIC}) {
      EXPECT_FALSE(CornerValues(*ours.value(), type).empty()) << file.name;
      EXPECT_EQ(CornerValues(*ours.value(), type),
                CornerValues(*theirs.value(), type))
          << file.name << " attribute type " << type;
    }
  }
}

// Every field of the tangent scheme's header (after the guard: the format
// version, then GeometricTangentConfig: the kind and handedness byte, the
// texture coordinate index, the normals' octahedral bits, the step-2 gain,
// the neighbour thresholds and the TangentGrid) set to values no encoder
// writes, and the residual streams' table starts and first token count:
// each file fails to decode with a message, within bounded memory.
TEST(MalformedInputTest, TangentHeaderValuesOutOfRangeAreRejected) {
  const std::vector<GoldenFile> files = TangentGoldenFiles(true);
  ASSERT_FALSE(files.empty()) << "run scripts/make-golden.sh";
  int tried = 0;
  for (const GoldenFile &file : files) {
    const TangentHeader header = FindTangentHeader(file.data);
    ASSERT_GE(header.guard, 0) << file.name;
    // Re-encoding the configuration gives back the file's bytes, so the
    // variants below differ from it in the one field only.
    ASSERT_EQ(WithConfigBytes(file.data, header, ConfigBytes(header.value)),
              file.data)
        << file.name;
    const auto expect_rejected = [&](const std::vector<char> &data,
                                     const std::string &what) {
      EXPECT_FALSE(Decode(data).ok()) << file.name << ": " << what;
      ++tried;
    };
    const auto with_config = [&](const std::string &what, auto change) {
      GeometricTangentConfig config = header.value;
      change(&config);
      expect_rejected(WithConfigBytes(file.data, header, ConfigBytes(config)),
                      what);
    };
    for (const int version : {0, 2, 3, 255}) {
      std::vector<char> data = file.data;
      data[header.guard + 8] = static_cast<char>(version);
      expect_rejected(data, "format version " + std::to_string(version));
    }
    // The kind (bits 0-1, below kNumGeometricTangentKinds), the handedness
    // flag (bit 2) and the two exception flags (bits 3-4); nothing else.
    for (int byte = 0; byte < 256; ++byte) {
      if ((byte & 3) < kNumGeometricTangentKinds && byte <= 31) {
        continue;
      }
      std::vector<char> data = file.data;
      data[header.config] = static_cast<char>(byte);
      expect_rejected(data, "kind byte " + std::to_string(byte));
    }
    for (const int index : {1, 2, 127, 128, 1 << 30}) {
      with_config("texture coordinate index " + std::to_string(index),
                  [&](GeometricTangentConfig *c) { c->tex_coord_index = index; });
    }
    for (const int bits : {0, 1, 31, 32, 255}) {
      with_config("normal bits " + std::to_string(bits),
                  [&](GeometricTangentConfig *c) { c->normal_bits = bits; });
    }
    for (const int gain : {257, 1000, 65535}) {
      with_config("gain " + std::to_string(gain),
                  [&](GeometricTangentConfig *c) { c->coding.shift_gain = gain; });
    }
    for (const std::array<uint8_t, 2> thresholds :
         {std::array<uint8_t, 2>{1, 0}, std::array<uint8_t, 2>{3, 2},
          std::array<uint8_t, 2>{255, 0}}) {
      with_config("thresholds " + std::to_string(thresholds[0]) + " > " +
                      std::to_string(thresholds[1]),
                  [&](GeometricTangentConfig *c) {
                    c->coding.neighbour_thresholds = thresholds;
                  });
    }
    // TangentGrid: the scale (0, beyond the fixed point's 2^36, the largest
    // uint64), the largest value (2^30 and more), the offsets (beyond
    // +-2^47, the int64 limits).
    for (const int64_t scale :
         {int64_t{0}, TangentGrid::kMaxScale + 1, int64_t{1} << 62,
          std::numeric_limits<int64_t>::max(),
          std::numeric_limits<int64_t>::min()}) {
      with_config("grid scale " + std::to_string(scale),
                  [&](GeometricTangentConfig *c) { c->coding.grid.scale = scale; });
    }
    for (const int32_t max_value :
         {int32_t{1} << 30, std::numeric_limits<int32_t>::max(), -1}) {
      with_config("grid max value " + std::to_string(max_value),
                  [&](GeometricTangentConfig *c) {
                    c->coding.grid.max_value = max_value;
                  });
    }
    for (int c = 0; c < kTangentNumComponents; ++c) {
      for (const int64_t offset :
           {TangentGrid::kMaxOffset + 1, -TangentGrid::kMaxOffset - 1,
            std::numeric_limits<int64_t>::max(),
            std::numeric_limits<int64_t>::min()}) {
        with_config("grid offset " + std::to_string(c) + " = " +
                        std::to_string(offset),
                    [&](GeometricTangentConfig *config) {
                      config->coding.grid.offset[c] = offset;
                    });
      }
    }
    // The residual streams: table starts (uint16; context 0 never starts a
    // table, there are no contexts from kTangentNumContexts on); the token
    // count before them set to 2^32 - 1, far above the number of residuals.
    for (const int bit : {0, kTangentNumContexts}) {
      std::vector<char> data = file.data;
      data[header.streams + bit / 8] |= static_cast<char>(1 << (bit % 8));
      expect_rejected(data, "table start bit " + std::to_string(bit));
    }
    std::vector<char> huge(file.data.begin(), file.data.begin() + header.tokens);
    huge.insert(huge.end(), {'\xff', '\xff', '\xff', '\xff', '\x0f'});
    huge.insert(huge.end(), file.data.begin() + header.streams, file.data.end());
    expect_rejected(huge, "huge token count");
  }
  EXPECT_LT(PeakRssKb(), kMaxPeakRssKb);
  RecordProperty("tangent_header_values", tried);
}

// The tangent attribute's prediction scheme id: the last byte before the
// scheme's guard that holds MESH_PREDICTION_GEOMETRIC_TANGENT followed by
// the wrap transform's type (then come Draco's all-zero corrections, a few
// bytes); -1 where there is none.
int TangentPredictionIdOffset(const std::vector<char> &data, int guard) {
  for (int p = guard - 2; p >= std::max(0, guard - 32); --p) {
    if (data[p] == MESH_PREDICTION_GEOMETRIC_TANGENT &&
        data[p + 1] == PREDICTION_TRANSFORM_WRAP) {
      return p;
    }
  }
  return -1;
}

// Unknown ids and the texture coordinate schemes' ids on the tangents, and
// the tangent scheme's id on texture coordinates, fail with a message;
// stock Draco's ids on the tangents decode or fail, never crash.
TEST(MalformedInputTest, TangentPredictionIdsAreChecked) {
  int tried = 0;
  const int num_ids = NUM_PREDICTION_SCHEMES;
  for (const GoldenFile &file : TangentGoldenFiles(true)) {
    const int id =
        TangentPredictionIdOffset(file.data, FindTangentHeader(file.data).guard);
    ASSERT_GE(id, 0) << file.name;
    // The offset is the id's: an unknown id there fails, the id decodes.
    for (int value = -128; value < 128; ++value) {
      std::vector<char> data = file.data;
      data[id] = static_cast<char>(value);
      const bool decoded = Decode(data).ok();
      if (value == MESH_PREDICTION_GEOMETRIC_TANGENT) {
        EXPECT_TRUE(decoded) << file.name;
      } else if (value >= num_ids || value < PREDICTION_NONE ||
                 IsDracoUvPredictionMethod(value)) {
        EXPECT_FALSE(decoded) << file.name << ": id " << value;
      }
      ++tried;
    }
  }
  for (const std::string mesh : {"torus_uv", "bumpy_cube_sphere", "cube_att"}) {
    for (const std::string variant : {"weighted", "weighted_multi"}) {
      std::vector<char> stock, ours;
      ASSERT_TRUE(ReadFileToBuffer(
          UvTestdataPath("golden/" + mesh + ".stock.drc"), &stock));
      ASSERT_TRUE(ReadFileToBuffer(
          UvTestdataPath("golden/" + mesh + "." + variant + ".drc"), &ours));
      const int id = PredictionIdOffset(ours, stock);
      ours[id] = MESH_PREDICTION_GEOMETRIC_TANGENT;
      EXPECT_FALSE(Decode(ours).ok()) << mesh << "." << variant;
      ++tried;
    }
  }
  EXPECT_LT(PeakRssKb(), kMaxPeakRssKb);
  RecordProperty("tangent_prediction_ids", tried);
}

// The prediction data of Draco's texture coordinate schemes for one
// triangle: |num_orientations| orientation bits (the count as int32 for
// MESH_PREDICTION_TEX_COORDS_PORTABLE, as a varint for the deprecated
// MESH_PREDICTION_TEX_COORDS), then the wrap transform's range.
std::vector<char> TexCoordsPredictionData(int32_t num_orientations,
                                          bool varint_count) {
  EncoderBuffer buffer;
  if (varint_count) {
    EncodeVarint(static_cast<uint32_t>(num_orientations), &buffer);
  } else {
    buffer.Encode(num_orientations);
  }
  RAnsBitEncoder bits;
  bits.StartEncoding();
  for (int i = 0; i < num_orientations; ++i) {
    bits.EncodeBit(i % 2 == 0);
  }
  bits.EndEncoding(&buffer);
  buffer.Encode(int32_t{0});    // Wrap transform: min.
  buffer.Encode(int32_t{100});  // Max.
  return std::vector<char>(buffer.data(), buffer.data() + buffer.size());
}

TEST(MalformedInputTest, OrientationCountsAboveTheCornersAreRejected) {
  // Patch 0012: stock Draco 1.5.5 decoded as many orientation bits as the
  // count said (fuzzed 4.5 KB files took 12-22 s and 256 MB), and extra
  // ones were read as if they belonged to the UVs.
  IndexTypeVector<FaceIndex, CornerTable::FaceType> faces(1);
  faces[FaceIndex(0)] = {VertexIndex(0), VertexIndex(1), VertexIndex(2)};
  const std::unique_ptr<CornerTable> table = CornerTable::Create(faces);
  ASSERT_NE(table, nullptr);
  const std::vector<CornerIndex> data_to_corner = {
      CornerIndex(0), CornerIndex(1), CornerIndex(2)};
  const std::vector<int32_t> vertex_to_data = {0, 1, 2};
  Mesh mesh;
  typedef MeshPredictionSchemeData<CornerTable> MeshData;
  typedef PredictionSchemeWrapDecodingTransform<int32_t> Transform;
  MeshData mesh_data;
  mesh_data.Set(&mesh, table.get(), &data_to_corner, &vertex_to_data);
  PointAttribute uv;
  uv.Init(GeometryAttribute::TEX_COORD, 2, DT_INT32, false, 3);
  for (const bool deprecated : {false, true}) {
    for (const int32_t count : {3, 4, 1 << 20}) {
      std::unique_ptr<PredictionSchemeDecoder<int32_t, Transform>> scheme;
      if (deprecated) {
        scheme.reset(new MeshPredictionSchemeTexCoordsDecoder<
                     int32_t, Transform, MeshData>(
            &uv, Transform(), mesh_data, kDracoMeshBitstreamVersion));
      } else {
        scheme.reset(new MeshPredictionSchemeTexCoordsPortableDecoder<
                     int32_t, Transform, MeshData>(&uv, Transform(),
                                                   mesh_data));
      }
      const std::vector<char> data = TexCoordsPredictionData(count, deprecated);
      DecoderBuffer buffer;
      buffer.Init(data.data(), data.size());
      buffer.set_bitstream_version(kDracoMeshBitstreamVersion);
      EXPECT_EQ(scheme->DecodePredictionData(&buffer), count <= 3)
          << (deprecated ? "deprecated " : "portable ") << count;
    }
  }
}

}  // namespace
}  // namespace draco
