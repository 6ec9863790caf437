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
// The Laplacian texture coordinate coder as Draco's
// MESH_PREDICTION_TEX_COORDS_LAPLACIAN (-uv_pred laplacian_*).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "draco_ext/common/uv_bitstream_guard.h"
#include "draco_ext/eval/uv_eval.h"
#include "gtest/gtest.h"
#include "prediction_schemes/laplacian/mesh_prediction_scheme_tex_coords_laplacian_shared.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

constexpr const char *kSchemes[] = {"laplacian_tutte", "laplacian_cotan",
                                    "laplacian_mv"};

std::vector<std::string> PipelineMeshes() {
  std::vector<std::string> paths = {UvTestdataPath("torus_uv.obj"),
                                    UvTestdataPath("bumpy_cube_sphere.obj")};
  for (const std::string &path : CorpusMeshPaths()) {
    // The small corpus meshes keep the test quick.
    if (path.find("spot") != std::string::npos ||
        path.find("suzanne") != std::string::npos ||
        path.find("milktruck") != std::string::npos) {
      paths.push_back(path);
    }
  }
  return paths;
}

double UvRange(const Mesh &mesh) {
  const PointAttribute &tex =
      *mesh.GetNamedAttribute(GeometryAttribute::TEX_COORD);
  float lo = std::numeric_limits<float>::max(), hi = -lo;
  for (AttributeValueIndex i(0); i < tex.size(); ++i) {
    std::array<float, 2> uv;
    tex.GetValue(i, uv.data());
    lo = std::min({lo, uv[0], uv[1]});
    hi = std::max({hi, uv[0], uv[1]});
  }
  return hi - lo;
}

TEST(UvLaplacianSchemeTest, RmseFallsWithQtForEveryLaplacian) {
  for (const std::string &path : PipelineMeshes()) {
    auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    ASSERT_NE(mesh.value()->GetNamedAttribute(GeometryAttribute::TEX_COORD),
              nullptr)
        << path;
    for (const char *scheme : kSchemes) {
      double previous = std::numeric_limits<double>::max();
      for (const int qt : {7, 10, 13}) {
        const auto bytes =
            EncodeMeshToBytes(*mesh.value(), Settings(14, qt, 10, scheme));
        ASSERT_TRUE(bytes.ok()) << path << " " << scheme << ": "
                                << bytes.status().error_msg_string();
        const auto decoded = DecodeDracoMesh(bytes.value());
        ASSERT_TRUE(decoded.ok()) << path << " " << scheme;
        const auto rmse = UvRmse(*mesh.value(), *decoded.value(), 14);
        ASSERT_TRUE(rmse.ok()) << path;
        EXPECT_LT(rmse.value(), previous) << path << " " << scheme << " qt " << qt;
        // Within a few -qt steps of the UV range.
        EXPECT_LT(rmse.value(), 8 * UvRange(*mesh.value()) / ((1 << qt) - 1))
            << path << " " << scheme << " qt " << qt;
        previous = rmse.value();
      }
    }
  }
}

TEST(UvLaplacianSchemeTest, DecodingIsDeterministic) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  const auto bytes =
      EncodeMeshToBytes(*mesh.value(), Settings(14, 10, 10, "laplacian_mv"));
  ASSERT_TRUE(bytes.ok());
  const auto a = DecodeDracoMesh(bytes.value());
  const auto b = DecodeDracoMesh(bytes.value());
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(CornerValues(*a.value(), GeometryAttribute::TEX_COORD),
            CornerValues(*b.value(), GeometryAttribute::TEX_COORD));
  const auto again =
      EncodeMeshToBytes(*mesh.value(), Settings(14, 10, 10, "laplacian_mv"));
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(bytes.value(), again.value());
}

TEST(UvLaplacianSchemeTest, AnchorOptionChangesTheStream) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  std::map<std::string, size_t> sizes;
  for (const std::string anchors : {"", "50", "0", "random:50"}) {
    const auto bytes = EncodeMeshToBytes(
        *mesh.value(), Settings(14, 10, 10, "laplacian_cotan", anchors));
    ASSERT_TRUE(bytes.ok()) << anchors;
    ASSERT_TRUE(DecodeDracoMesh(bytes.value()).ok()) << anchors;
    sizes[anchors] = bytes.value().size();
  }
  EXPECT_LT(sizes["0"], sizes["50"]);
  // The default places anchors too (UvDefaultExtraAnchors(); that the
  // coder takes its count is UvLaplacianCoderTest.DefaultAnchorsFollowTheRule).
  EXPECT_LT(sizes["0"], sizes[""]);
}

TEST(UvLaplacianSchemeTest, AutoNeverPicksALossyScheme) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  std::string summary;
  EncoderBuffer buffer;
  ASSERT_TRUE(EncodeMeshWithSettings(*mesh.value(), Settings(14, 6, 10, "auto"),
                                     &buffer, &summary)
                  .ok());
  EXPECT_EQ(summary.find("laplacian"), std::string::npos) << summary;
}

TEST(UvLaplacianSchemeTest, TruncatedFilesFailToDecode) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  const auto bytes =
      EncodeMeshToBytes(*mesh.value(), Settings(14, 10, 10, "laplacian_tutte"));
  ASSERT_TRUE(bytes.ok());
  for (size_t size = 0; size < bytes.value().size(); size += 7) {
    const std::vector<char> truncated(bytes.value().begin(),
                                      bytes.value().begin() + size);
    EXPECT_FALSE(DecodeDracoMesh(truncated).ok()) << size;
  }
}

TEST(UvLaplacianSchemeTest, RejectsOtherFormatVersions) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  const auto bytes =
      EncodeMeshToBytes(*mesh.value(), Settings(14, 10, 10, "laplacian_mv"));
  ASSERT_TRUE(bytes.ok());
  ASSERT_TRUE(DecodeDracoMesh(bytes.value()).ok());
  // The scheme's data start with the 8-byte guard, then the version.
  char guard[8];
  const int32_t words[2] = {kUvGuardFirst, kUvGuardSecond};
  std::memcpy(guard, words, sizeof(guard));
  const auto it = std::search(bytes.value().begin(), bytes.value().end(), guard,
                              guard + sizeof(guard));
  ASSERT_NE(it, bytes.value().end());
  const size_t version = (it - bytes.value().begin()) + sizeof(guard);
  ASSERT_EQ(bytes.value()[version], kTexCoordsLaplacianFormatVersion);
  for (int value = 0; value < 256; ++value) {
    if (value == kTexCoordsLaplacianFormatVersion) {
      continue;
    }
    std::vector<char> other = bytes.value();
    other[version] = static_cast<char>(value);
    EXPECT_FALSE(DecodeDracoMesh(other).ok()) << value;
  }
}

TEST(UvLaplacianSchemeTest, CorruptFilesFailOrDecodeFiniteUvs) {
  auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
  ASSERT_TRUE(mesh.ok());
  const auto bytes =
      EncodeMeshToBytes(*mesh.value(), Settings(14, 10, 10, "laplacian_cotan"));
  ASSERT_TRUE(bytes.ok());
  std::mt19937 random(11);
  int rejected = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<char> corrupt = bytes.value();
    corrupt[random() % corrupt.size()] ^= static_cast<char>(1 + random() % 255);
    const auto decoded = DecodeDracoMesh(corrupt);
    if (!decoded.ok()) {
      ++rejected;
      continue;
    }
    for (const float value :
         CornerValues(*decoded.value(), GeometryAttribute::TEX_COORD)) {
      ASSERT_TRUE(std::isfinite(value));
    }
  }
  EXPECT_GT(rejected, 0);
}

// The lossy golden files pin the encoder's bytes (scripts/make-golden.sh
// --check-encode) and seed scripts/fuzz.sh's decode:laplacian target; a
// format change must renew them, and they must decode.
TEST(UvLaplacianSchemeTest, LossyGoldenFilesDecode) {
  namespace fs = std::filesystem;
  const fs::path folder = UvTestdataPath("golden/lossy");
  ASSERT_TRUE(fs::is_directory(folder)) << folder;
  int seeds = 0;
  for (const auto &entry : fs::directory_iterator(folder)) {
    if (entry.path().extension() != ".drc") {
      continue;
    }
    std::ifstream stream(entry.path(), std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(stream)),
                                  std::istreambuf_iterator<char>());
    const auto decoded = DecodeDracoMesh(bytes);
    ASSERT_TRUE(decoded.ok()) << entry.path();
    const auto uvs =
        CornerValues(*decoded.value(), GeometryAttribute::TEX_COORD);
    EXPECT_FALSE(uvs.empty()) << entry.path();
    for (const float value : uvs) {
      ASSERT_TRUE(std::isfinite(value)) << entry.path();
    }
    ++seeds;
  }
  EXPECT_GE(seeds, 12);
}

}  // namespace
}  // namespace draco
