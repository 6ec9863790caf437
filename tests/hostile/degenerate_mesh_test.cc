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
// The encoder copes with the meshes people really have: zero-area 3D and UV
// triangles, duplicate vertices, repeated corners, non-manifold edges,
// isolated triangles, far-away UVs, NaN and infinities, missing positions or
// texture coordinates, and the awkward corpus meshes. Every draco-uv scheme
// (and auto) either encodes, and then decodes to exactly what stock Draco's
// encoding at the same settings decodes to, or refuses with a "-uv_pred"
// message that names the reason.
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"
#include "tests/uv_soup_mesh.h"

namespace draco {
namespace {

constexpr const char *kSchemes[] = {"weighted", "weighted_multi", "auto"};

// A bumpy (n+1) x (n+1) grid with one UV per vertex (a seamless chart).
SoupMesh BumpyGrid(int n = 5) {
  SoupMesh soup;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      soup.positions.push_back(
          {static_cast<float>(i), static_cast<float>(j), 0.1f * ((i * j) % 3)});
      soup.uvs.push_back(
          {i / static_cast<float>(n), j / static_cast<float>(n)});
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      soup.faces.push_back({{a, b, d}, {a, b, d}});
      soup.faces.push_back({{a, d, c}, {a, d, c}});
    }
  }
  return soup;
}

std::vector<UvEncodeSettings> SettingsGrid() {
  std::vector<UvEncodeSettings> grid;
  for (const char *scheme : kSchemes) {
    for (const int cl : {1, 5, 10}) {
      for (const int qp : {3, 14}) {
        for (const int qt : {2, 12, 20}) {
          grid.push_back(Settings(qp, qt, cl, scheme));
        }
      }
    }
  }
  return grid;
}

std::string Label(const UvEncodeSettings &s) {
  return "-qp " + std::to_string(s.qp) + " -qt " + std::to_string(s.qt) +
         " -cl " + std::to_string(s.cl) + " -uv_pred " +
         UvPredictionNameOf(s.uv.prediction);
}

// Every setting encodes |mesh| and decodes it to stock Draco's values.
void ExpectExactRoundTrips(const Mesh &mesh, const std::string &name) {
  for (const UvEncodeSettings &settings : SettingsGrid()) {
    const UvRoundTrip result = RoundTripAgainstStock(mesh, settings);
    ASSERT_TRUE(result.encoded.ok()) << name << " " << Label(settings) << ": "
                                     << result.encoded.error_msg_string();
    ASSERT_TRUE(result.decoded.ok()) << name << " " << Label(settings);
    ASSERT_TRUE(result.stock_encoded) << name << " " << Label(settings);
    EXPECT_TRUE(result.identical) << name << " " << Label(settings);
  }
}

// Every draco-uv scheme refuses |mesh| with a message containing |reason|.
void ExpectClearRefusal(const Mesh &mesh, const std::string &reason,
                        const std::string &name) {
  for (const char *scheme : {"weighted", "weighted_multi"}) {
    const UvEncodeSettings settings = Settings(14, 12, 10, scheme);
    EncoderBuffer buffer;
    const Status status = EncodeMeshWithSettings(mesh, settings, &buffer);
    EXPECT_FALSE(status.ok()) << name << " " << scheme;
    EXPECT_NE(status.error_msg_string().find(reason), std::string::npos)
        << name << " " << scheme << ": " << status.error_msg_string();
  }
}

TEST(DegenerateMeshTest, ZeroArea3dTrianglesRoundTripExactly) {
  SoupMesh soup = BumpyGrid();
  // Collapse a row of vertices onto one point and make another row
  // collinear: their triangles have zero area in 3D, not in UV.
  for (int i = 0; i <= 5; ++i) {
    soup.positions[6 + i] = soup.positions[6];
    soup.positions[18 + i] = {static_cast<float>(i), 3.f, 0.f};
    soup.positions[24 + i] = {static_cast<float>(i) + 0.5f, 3.f, 0.f};
  }
  ExpectExactRoundTrips(*BuildSoupMesh(soup), "zero-area 3D");
}

// Vertices moved onto a neighbour's position (a different OBJ vertex with
// the same coordinates; their UVs stay apart): Draco merges the positions,
// and the edgebreaker encoder drops the faces that become degenerate, so
// the decoder never sees them (the encoder's predictions must not either;
// stk_abyss_track in AwkwardCorpusMeshesRoundTripExactly is the case that
// showed it). Random grids at every compression level.
TEST(DegenerateMeshTest, FacesCollapsedOntoOnePositionRoundTripExactly) {
  std::mt19937 rng(8);
  for (int mesh = 0; mesh < 12; ++mesh) {
    SoupMesh soup = BumpyGrid(9);
    const int num_vertices = static_cast<int>(soup.positions.size());
    std::uniform_int_distribution<int> vertex(0, num_vertices - 11);
    for (int k = 0; k < 12; ++k) {
      // Onto the neighbour to the right or above (rows of 10 vertices).
      const int v = vertex(rng);
      soup.positions[v] = soup.positions[v + (k % 2 == 0 ? 1 : 10)];
    }
    const auto built = BuildSoupMesh(soup);
    for (const char *scheme : kSchemes) {
      for (int cl = 1; cl <= 10; ++cl) {
        const UvEncodeSettings settings = Settings(11, 12, cl, scheme);
        const UvRoundTrip result = RoundTripAgainstStock(*built, settings);
        ASSERT_TRUE(result.encoded.ok() && result.decoded.ok())
            << "mesh " << mesh << " " << Label(settings) << ": "
            << result.encoded.error_msg_string();
        EXPECT_TRUE(result.stock_encoded && result.identical)
            << "mesh " << mesh << " " << Label(settings);
      }
    }
  }
}

TEST(DegenerateMeshTest, ZeroAreaUvTrianglesRoundTripExactly) {
  SoupMesh soup = BumpyGrid();
  for (int i = 0; i <= 5; ++i) {
    soup.uvs[i] = {0.5f, 0.5f};               // Coincident.
    soup.uvs[12 + i] = {0.1f * i, 0.1f * i};  // Collinear rows.
    soup.uvs[18 + i] = {0.1f * i + 0.05f, 0.1f * i + 0.05f};
  }
  ExpectExactRoundTrips(*BuildSoupMesh(soup), "zero-area UV");
}

TEST(DegenerateMeshTest, RepeatedCornersAndDuplicateVerticesRoundTripExactly) {
  SoupMesh soup = BumpyGrid();
  // Faces with a vertex twice or three times.
  soup.faces.push_back({{0, 0, 7}, {0, 0, 7}});
  soup.faces.push_back({{8, 8, 8}, {8, 8, 8}});
  // A second copy of a vertex (same position and UV, another index) used
  // by some of its faces.
  soup.positions.push_back(soup.positions[14]);
  soup.uvs.push_back(soup.uvs[14]);
  for (SoupMesh::Face &face : soup.faces) {
    if (face.position[0] == 14) {
      face.position[0] = face.uv[0] = 36;
    }
  }
  ExpectExactRoundTrips(*BuildSoupMesh(soup), "repeated corners");
}

TEST(DegenerateMeshTest, NonManifoldEdgesAndIsolatedTrianglesRoundTripExactly) {
  SoupMesh soup = BumpyGrid();
  const int base = static_cast<int>(soup.positions.size());
  // Three fins on the grid's edge (0, 7), each with its own UV.
  for (int k = 0; k < 3; ++k) {
    soup.positions.push_back({0.5f, 0.5f, 1.f + k});
    soup.uvs.push_back({0.9f, 0.1f * k});
    soup.faces.push_back({{0, 7, base + k}, {0, 7, base + k}});
  }
  // Isolated triangles, one far away, one sharing a single vertex.
  for (int k = 0; k < 3; ++k) {
    soup.positions.push_back({10.f + k, 10.f + k * k, -5.f});
    soup.uvs.push_back({2.f + k, -1.f});
  }
  soup.faces.push_back(
      {{base + 3, base + 4, base + 5}, {base + 3, base + 4, base + 5}});
  soup.faces.push_back({{35, base + 4, base + 5}, {35, base + 4, base + 5}});
  ExpectExactRoundTrips(*BuildSoupMesh(soup), "non-manifold");
}

TEST(DegenerateMeshTest, UvsFarOutsideTheUnitSquareRoundTripExactly) {
  SoupMesh soup = BumpyGrid();
  soup.uvs[3] = {1e4f, -3e5f};
  soup.uvs[20] = {-7e6f, 2.5f};
  ExpectExactRoundTrips(*BuildSoupMesh(soup), "far UVs");
  // Every UV far away but close together: a tiny chart at 1e6.
  for (auto &uv : soup.uvs) {
    uv = {1e6f + uv[0] * 64.f, -1e6f + uv[1] * 64.f};
  }
  ExpectExactRoundTrips(*BuildSoupMesh(soup), "offset UVs");
}

TEST(DegenerateMeshTest, SeamsOnEveryEdgeRoundTripExactly) {
  // Every face its own UV triangle: a UV vertex per corner.
  SoupMesh soup = BumpyGrid(4);
  std::vector<std::array<float, 2>> uvs;
  for (SoupMesh::Face &face : soup.faces) {
    for (int i = 0; i < 3; ++i) {
      uvs.push_back({soup.uvs[face.uv[i]][0] + 0.01f * (uvs.size() % 5),
                     soup.uvs[face.uv[i]][1]});
      face.uv[i] = static_cast<int>(uvs.size()) - 1;
    }
  }
  soup.uvs = uvs;
  ExpectExactRoundTrips(*BuildSoupMesh(soup), "all seams");
}

TEST(DegenerateMeshTest, NanOrInfiniteValuesAreRefused) {
  for (const float bad : {std::nanf(""), INFINITY, -INFINITY}) {
    for (const int index : {0, 13}) {
      SoupMesh uv_soup = BumpyGrid();
      uv_soup.uvs[index][1] = bad;
      ExpectClearRefusal(*BuildSoupMesh(uv_soup), "NaN or infinite",
                         "bad UV at " + std::to_string(index));
      SoupMesh pos_soup = BumpyGrid();
      pos_soup.positions[index][2] = bad;
      ExpectClearRefusal(*BuildSoupMesh(pos_soup), "NaN or infinite",
                         "bad position at " + std::to_string(index));
    }
  }
}

TEST(DegenerateMeshTest, MeshWithoutPositionsIsRefused) {
  SoupMesh soup = BumpyGrid();
  soup.positions.clear();
  ExpectClearRefusal(*BuildSoupMesh(soup), "no POSITION", "no positions");
}

TEST(DegenerateMeshTest, MeshWithoutTextureCoordinatesEncodesAsStock) {
  SoupMesh soup = BumpyGrid();
  soup.uvs.clear();
  const auto mesh = BuildSoupMesh(soup);
  for (const char *scheme : kSchemes) {
    const UvEncodeSettings settings = Settings(14, 12, 10, scheme);
    EncoderBuffer ours, stock;
    ASSERT_TRUE(EncodeMeshWithSettings(*mesh, settings, &ours).ok());
    ASSERT_TRUE(EncodeMeshWithSettings(*mesh, {14, 12, 10}, &stock).ok());
    EXPECT_EQ(std::string(ours.data(), ours.size()),
              std::string(stock.data(), stock.size()))
        << scheme;
  }
}

// The corpus meshes with the most awkward UV layouts: SuperTuxKart's
// (overlapping, mirrored, far outside [0, 1]), MultiUVTest's two layouts and
// the milk truck's body; at coarse and fine quantisation, where many
// triangles become degenerate.
TEST(DegenerateMeshTest, AwkwardCorpusMeshesRoundTripExactly) {
  std::vector<std::string> awkward;
  for (const std::string &path : CorpusMeshPaths()) {
    const std::string name = path.substr(path.find_last_of('/') + 1);
    if (name.rfind("stk_", 0) == 0 || name.rfind("khr_multiuvtest_", 0) == 0 ||
        name == "khr_cesiummilktruck_body.obj") {
      awkward.push_back(path);
    }
  }
  if (awkward.empty()) {
    GTEST_SKIP() << "corpus not found at " << CorpusDir();
  }
  for (const std::string &path : awkward) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    for (const char *scheme : {"weighted", "weighted_multi"}) {
      for (const UvEncodeSettings settings :
           {Settings(6, 4, 10, scheme), Settings(8, 20, 5, scheme),
            Settings(14, 16, 1, scheme)}) {
        const UvRoundTrip result =
            RoundTripAgainstStock(*mesh.value(), settings);
        ASSERT_TRUE(result.encoded.ok() && result.decoded.ok())
            << path << " " << Label(settings) << ": "
            << result.encoded.error_msg_string();
        EXPECT_TRUE(result.stock_encoded && result.identical)
            << path << " " << Label(settings);
      }
    }
  }
}

}  // namespace
}  // namespace draco
