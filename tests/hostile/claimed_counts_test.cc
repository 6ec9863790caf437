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
// Headers that claim huge counts whose data is entropy coded, on which
// stock Draco allocates before anything contradicts them (patches/0014,
// draco_ext/hooks/decode_limits.h): an Edgebreaker mesh claiming 2^26 and
// 2^28 vertices, faces and symbols, and a sequential point cloud claiming
// 2^26 points. Each must fail with an error at once, without the memory the
// counts would take; the files they are made of still decode.
#include <sys/resource.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "draco/compression/decode.h"
#include "draco/compression/encode.h"
#include "draco/core/varint_decoding.h"
#include "draco/core/varint_encoding.h"
#include "draco/io/file_utils.h"
#include "draco/io/point_cloud_io.h"
#include "draco_ext/hooks/decode_limits.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

// Draco's header: "DRACO", version, encoder type, method, 16-bit flags.
constexpr int kHeaderBytes = 11;
// A refused file must fail within this time and peak memory (decoding the
// originals takes a few ms and MB; the claimed counts would take gigabytes).
constexpr double kMaxSeconds = 1.0;
constexpr long kMaxPeakRssKb = 256 * 1024;

long PeakRssKb() {
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// |data| with the varints starting at |offset| replaced by |values| (a
// negative value keeps that varint).
std::vector<char> ReplaceVarints(const std::vector<char> &data, size_t offset,
                                 const std::vector<int64_t> &values) {
  DecoderBuffer in;
  in.Init(data.data(), data.size());
  in.Advance(offset);
  EncoderBuffer out;
  out.Encode(data.data(), offset);
  for (const int64_t value : values) {
    uint64_t old = 0;
    EXPECT_TRUE(DecodeVarint(&old, &in));
    EncodeVarint<uint64_t>(value < 0 ? old : value, &out);
  }
  out.Encode(in.data_head(), in.remaining_size());
  return std::vector<char>(out.data(), out.data() + out.size());
}

// The size of the varint at |offset| of |data|.
size_t VarintSize(const std::vector<char> &data, size_t offset) {
  size_t size = 1;
  while (static_cast<uint8_t>(data[offset + size - 1]) & 0x80) {
    ++size;
  }
  return size;
}

// torus_uv.stock.drc (Edgebreaker, valence traversal) claiming |n|
// vertices, faces and symbols: traversal byte, varints vertices and faces,
// attribute data byte, varint symbols.
std::vector<char> EdgebreakerClaiming(const std::vector<char> &original,
                                      int64_t n) {
  const size_t vertices_at = kHeaderBytes + 1;
  std::vector<char> data = ReplaceVarints(original, vertices_at, {n, n});
  size_t symbols_at = vertices_at + VarintSize(data, vertices_at);
  symbols_at += VarintSize(data, symbols_at) + 1;
  return ReplaceVarints(data, symbols_at, {n});
}

// torus_uv.obj as a point cloud, sequential coding at draco_encoder's
// -cl 0 -point_cloud and default quantization.
std::vector<char> EncodedPointCloud() {
  auto cloud = ReadPointCloudFromFile(UvTestdataPath("torus_uv.obj"));
  EXPECT_TRUE(cloud.ok()) << cloud.status().error_msg_string();
  Encoder encoder;
  encoder.SetSpeedOptions(10, 10);
  encoder.SetEncodingMethod(POINT_CLOUD_SEQUENTIAL_ENCODING);
  encoder.SetAttributeQuantization(GeometryAttribute::POSITION, 11);
  encoder.SetAttributeQuantization(GeometryAttribute::TEX_COORD, 10);
  encoder.SetAttributeQuantization(GeometryAttribute::NORMAL, 8);
  EncoderBuffer buffer;
  const Status status =
      encoder.EncodePointCloudToBuffer(*cloud.value(), &buffer);
  EXPECT_TRUE(status.ok()) << status.error_msg_string();
  return std::vector<char>(buffer.data(), buffer.data() + buffer.size());
}

// |data| with the point count (int32 after the header) set to |n|.
std::vector<char> PointCloudClaiming(std::vector<char> data, int32_t n) {
  std::memcpy(&data[kHeaderBytes], &n, sizeof(n));
  return data;
}

// Decodes |data| as its header says; returns the status and the seconds.
Status Decode(const std::vector<char> &data, double *seconds) {
  const auto start = std::chrono::steady_clock::now();
  DecoderBuffer buffer;
  buffer.Init(data.data(), data.size());
  Decoder decoder;
  const auto type = Decoder::GetEncodedGeometryType(&buffer);
  Status status = type.status();
  if (type.ok() && type.value() == TRIANGULAR_MESH) {
    status = decoder.DecodeMeshFromBuffer(&buffer).status();
  } else if (type.ok()) {
    status = decoder.DecodePointCloudFromBuffer(&buffer).status();
  }
  *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
                 .count();
  return status;
}

void ExpectRefused(const std::vector<char> &data, const std::string &what) {
  double seconds = 0;
  const Status status = Decode(data, &seconds);
  EXPECT_FALSE(status.ok()) << what << " decoded";
  EXPECT_FALSE(status.error_msg_string().empty()) << what;
  EXPECT_LT(seconds, kMaxSeconds) << what;
  EXPECT_LT(PeakRssKb(), kMaxPeakRssKb) << what;
}

TEST(ClaimedCountsTest, EdgebreakerFacesBeyondTheLimitsAreRefused) {
  std::vector<char> original;
  ASSERT_TRUE(ReadFileToBuffer(UvTestdataPath("golden/torus_uv.stock.drc"),
                               &original));
  ASSERT_EQ(original[7], TRIANGULAR_MESH);
  ASSERT_EQ(original[8], MESH_EDGEBREAKER_ENCODING);
  ASSERT_EQ(original[kHeaderBytes], MESH_EDGEBREAKER_VALENCE_ENCODING);
  double seconds = 0;
  ASSERT_TRUE(Decode(original, &seconds).ok());
  for (const int64_t n : {int64_t{1} << 26, int64_t{1} << 28}) {
    ExpectRefused(EdgebreakerClaiming(original, n),
                  "Edgebreaker mesh claiming " + std::to_string(n) +
                      " vertices, faces and symbols");
  }
}

TEST(ClaimedCountsTest, SequentialPointCloudPointsBeyondTheLimitsAreRefused) {
  const std::vector<char> original = EncodedPointCloud();
  ASSERT_GT(original.size(), kHeaderBytes + 4);
  ASSERT_EQ(original[7], POINT_CLOUD);
  ASSERT_EQ(original[8], POINT_CLOUD_SEQUENTIAL_ENCODING);
  double seconds = 0;
  ASSERT_TRUE(Decode(original, &seconds).ok());
  ExpectRefused(PointCloudClaiming(original, int32_t{1} << 26),
                "point cloud claiming 2^26 points");
}

// Counts that need at most 256 MB are left to the decoders' own checks;
// above that, expansions up to 65,536-fold of the bytes left are accepted,
// with 32-bit pointers only up to 2 GB.
TEST(ClaimedCountsTest, LimitsFollowMemoryAndRemainingBytes) {
  constexpr uint64_t kFloor = uint64_t{1} << 28;
  constexpr uint64_t kTwoGb = uint64_t{1} << 31;
  EXPECT_TRUE(DecodedSizeWithinLimits(0, 0));
  EXPECT_TRUE(DecodedSizeWithinLimits(kFloor, 0));
  EXPECT_FALSE(DecodedSizeWithinLimits(kFloor + 1, 0));
  EXPECT_FALSE(DecodedSizeWithinLimits(kFloor + 65536, 4095));
  EXPECT_TRUE(DecodedSizeWithinLimits(kFloor + 65536, 4097));
  EXPECT_TRUE(DecodedSizeWithinLimits(kTwoGb, kTwoGb / 65536));
  const bool wide = sizeof(void *) == 8;
  EXPECT_EQ(DecodedSizeWithinLimits(uint64_t{1} << 40, int64_t{1} << 24),
            wide);
  EXPECT_FALSE(DecodedSizeWithinLimits(uint64_t{1} << 40, (1 << 24) - 1));
}

}  // namespace
}  // namespace draco
