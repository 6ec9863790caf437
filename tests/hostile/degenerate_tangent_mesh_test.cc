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
// The tangent options (-tangent_pred, -qtg) on the meshes people really
// have: zero-area UV and 3D triangles, faces collapsed onto one position,
// repeated corners, zero, NaN and infinite normals, NaN and infinite
// tangents, tangents of another shape, missing, lossy or unquantized
// parents, and tangents that barely vary. Every -tangent_pred name either
// codes the tangents with MESH_PREDICTION_GEOMETRIC_TANGENT and then
// decodes to exactly what stock coding of the same tangents decodes to, or
// keeps stock coding, says why and writes exactly the stock file, or (NaN
// and infinite tangents, which Draco cannot quantize) refuses with a
// message.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "draco/mesh/triangle_soup_mesh_builder.h"
#include "draco_ext/options/uv_encode_settings.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"
#include "tests/uv_soup_mesh.h"

namespace draco {
namespace {

constexpr const char *kTangentNames[] = {"mikktspace", "uniform", "face",
                                         "geometric", "auto"};

// An indexed mesh with one normal, texture coordinate and tangent per
// position (faces index all four alike).
struct TangentSoup {
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<float, 2>> uvs;
  std::vector<std::array<float, 3>> normals;
  std::vector<std::array<float, 4>> tangents;
  std::vector<std::array<int, 3>> faces;
};

// How BuildTangentMesh() shapes the attributes.
struct TangentShape {
  GeometryAttribute::Type tangent_type = GeometryAttribute::TANGENT;
  int tangent_components = 4;
  bool with_normals = true;
  bool with_uvs = true;
};

// A bumpy (n+1) x (n+1) grid, u along x, with the normals and MikkTSpace-
// like tangents (dP/du in the normal plane, w = 1) of its height field.
TangentSoup BumpyTangentGrid(int n = 6) {
  TangentSoup soup;
  const auto height = [](double x, double y) {
    return 0.4 * std::sin(0.7 * x) * std::cos(0.5 * y);
  };
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double hx = 0.28 * std::cos(0.7 * i) * std::cos(0.5 * j);
      const double hy = -0.2 * std::sin(0.7 * i) * std::sin(0.5 * j);
      const double nl = std::sqrt(hx * hx + hy * hy + 1);
      const double normal[3] = {-hx / nl, -hy / nl, 1 / nl};
      // dP/dx = (1, 0, hx) minus its part along the normal.
      const double along = normal[0] + hx * normal[2];
      const double t[3] = {1 - along * normal[0], -along * normal[1],
                     hx - along * normal[2]};
      const double tl = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
      soup.positions.push_back({static_cast<float>(i), static_cast<float>(j),
                                static_cast<float>(height(i, j))});
      soup.uvs.push_back({i / static_cast<float>(n), j / static_cast<float>(n)});
      soup.normals.push_back({static_cast<float>(normal[0]),
                              static_cast<float>(normal[1]),
                              static_cast<float>(normal[2])});
      soup.tangents.push_back({static_cast<float>(t[0] / tl),
                               static_cast<float>(t[1] / tl),
                               static_cast<float>(t[2] / tl), 1.f});
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      soup.faces.push_back({a, b, d});
      soup.faces.push_back({a, d, c});
    }
  }
  return soup;
}

std::unique_ptr<Mesh> BuildTangentMesh(const TangentSoup &soup,
                                       const TangentShape &shape = {}) {
  TriangleSoupMeshBuilder builder;
  builder.Start(static_cast<int>(soup.faces.size()));
  const int pos = builder.AddAttribute(GeometryAttribute::POSITION, 3,
                                       DT_FLOAT32);
  const int uv = shape.with_uvs ? builder.AddAttribute(
                                      GeometryAttribute::TEX_COORD, 2,
                                      DT_FLOAT32)
                                : -1;
  const int normal = shape.with_normals
                         ? builder.AddAttribute(GeometryAttribute::NORMAL, 3,
                                                DT_FLOAT32)
                         : -1;
  const int tangent = builder.AddAttribute(
      shape.tangent_type, shape.tangent_components, DT_FLOAT32);
  for (int f = 0; f < static_cast<int>(soup.faces.size()); ++f) {
    const std::array<int, 3> &v = soup.faces[f];
    builder.SetAttributeValuesForFace(
        pos, FaceIndex(f), soup.positions[v[0]].data(),
        soup.positions[v[1]].data(), soup.positions[v[2]].data());
    if (uv >= 0) {
      builder.SetAttributeValuesForFace(uv, FaceIndex(f), soup.uvs[v[0]].data(),
                                        soup.uvs[v[1]].data(),
                                        soup.uvs[v[2]].data());
    }
    if (normal >= 0) {
      builder.SetAttributeValuesForFace(
          normal, FaceIndex(f), soup.normals[v[0]].data(),
          soup.normals[v[1]].data(), soup.normals[v[2]].data());
    }
    builder.SetAttributeValuesForFace(
        tangent, FaceIndex(f), soup.tangents[v[0]].data(),
        soup.tangents[v[1]].data(), soup.tangents[v[2]].data());
  }
  return builder.Finalize();
}

// draco_encoder -qp |qp| -qt |qt| -cl |cl| with the UV options |uv|
// ("<uv_pred>[+<uv_seams>]"), -tangent_pred |name| -qtg |qtg|.
UvEncodeSettings TangentSettings(const std::string &name, int cl, int qtg,
                                 const std::string &uv = "auto+context",
                                 int qp = 14, int qt = 12) {
  UvEncodeSettings settings = Settings(qp, qt, cl, uv);
  settings.uv.tangent.prediction = ParseTangentPredictionName(name).value();
  settings.uv.tangent.quantization_bits = qtg;
  return settings;
}

std::string Label(const std::string &name, const UvEncodeSettings &s) {
  return name + ": -qp " + std::to_string(s.qp) + " -qt " +
         std::to_string(s.qt) + " -cl " + std::to_string(s.cl) +
         " -uv_pred " + UvPredictionNameOf(s.uv.prediction) +
         " -tangent_pred " + TangentPredictionNameOf(s.uv.tangent.prediction) +
         " -qtg " + std::to_string(s.uv.tangent.quantization_bits.value_or(0));
}

// The summary's lines about the tangents ("Tangent prediction..."), or "".
std::string TangentSummary(const std::string &summary) {
  std::string lines;
  size_t begin = 0;
  while (begin < summary.size()) {
    size_t end = summary.find('\n', begin);
    end = end == std::string::npos ? summary.size() : end + 1;
    if (summary.compare(begin, 18, "Tangent prediction") == 0) {
      lines += summary.substr(begin, end - begin);
    }
    begin = end;
  }
  return lines;
}

// What the encoder did with the tangents.
enum class TangentCoding { kPredicted, kStock };

// Encodes |mesh| with |settings| and with stock coding of the tangents at
// the same -qtg. Either the summary names the scheme and the file decodes
// to the stock file's values, or it says the tangents keep stock coding
// (auto: chose draco) and the bytes are the stock file's.
TangentCoding ExpectStockValues(const Mesh &mesh,
                                const UvEncodeSettings &settings,
                                const std::string &label) {
  UvEncodeSettings stock_settings = settings;
  stock_settings.uv.tangent.prediction = TangentPrediction::kDraco;
  EncoderBuffer ours, stock;
  std::string summary;
  const Status status =
      EncodeMeshWithSettings(mesh, settings, &ours, &summary);
  EXPECT_TRUE(status.ok()) << label << ": " << status.error_msg_string();
  EXPECT_TRUE(EncodeMeshWithSettings(mesh, stock_settings, &stock).ok())
      << label;
  if (!status.ok()) {
    return TangentCoding::kStock;
  }
  const std::string tangent_line = TangentSummary(summary);
  if (tangent_line.empty() ||
      tangent_line.find("keeps stock coding") != std::string::npos ||
      tangent_line.find("-> draco,") != std::string::npos) {
    EXPECT_TRUE(std::string(ours.data(), ours.size()) ==
                std::string(stock.data(), stock.size()))
        << label << ": " << ours.size() << " bytes, stock " << stock.size()
        << ": " << summary;
    return TangentCoding::kStock;
  }
  const auto decoded = DecodeEncoded(ours);
  const auto expected = DecodeEncoded(stock);
  EXPECT_TRUE(decoded.ok()) << label << ": " << decoded.status().error_msg();
  if (decoded.ok() && expected.ok()) {
    ExpectSameCornerValues(*expected.value(), *decoded.value(), label);
  }
  return TangentCoding::kPredicted;
}

// Every name at Edgebreaker levels, tangent quantisations and UV options:
// decodes to the stock values; returns the names that used the scheme at
// least once.
std::set<std::string> ExpectStockValuesEverywhere(const Mesh &mesh,
                                                  const std::string &name) {
  std::set<std::string> predicted;
  for (const char *tangent : kTangentNames) {
    for (const int cl : {5, 7, 10}) {
      for (const int qtg : {3, 8, 12, 21}) {
        for (const char *uv : {"", "auto+context"}) {
          const UvEncodeSettings settings =
              TangentSettings(tangent, cl, qtg, uv);
          if (ExpectStockValues(mesh, settings,
                                name + " " + Label(tangent, settings)) ==
              TangentCoding::kPredicted) {
            predicted.insert(tangent);
          }
        }
      }
    }
  }
  return predicted;
}

// The scheme must really run on the degenerate meshes, with every name, not
// step aside (auto only where it is smaller than stock coding: not for
// constant tangents, whose stock deltas are all zero).
void ExpectEveryNamePredicted(const std::set<std::string> &predicted,
                              const std::string &name, bool auto_too = true) {
  for (const char *tangent : kTangentNames) {
    if (auto_too || std::string(tangent) != "auto") {
      EXPECT_EQ(predicted.count(tangent), 1u) << name << ": " << tangent;
    }
  }
}

TEST(DegenerateTangentMeshTest, TheRegularGridUsesTheScheme) {
  const auto mesh = BuildTangentMesh(BumpyTangentGrid());
  ExpectEveryNamePredicted(ExpectStockValuesEverywhere(*mesh, "grid"), "grid");
}

TEST(DegenerateTangentMeshTest, ZeroAreaUvTrianglesDecodeToTheStockValues) {
  TangentSoup soup = BumpyTangentGrid();
  for (int i = 0; i <= 6; ++i) {
    soup.uvs[i] = {0.5f, 0.5f};                 // Coincident.
    soup.uvs[14 + i] = {0.1f * i, 0.1f * i};    // Collinear rows.
    soup.uvs[21 + i] = {0.1f * i + 0.05f, 0.1f * i + 0.05f};
  }
  const auto mesh = BuildTangentMesh(soup);
  ExpectEveryNamePredicted(ExpectStockValuesEverywhere(*mesh, "zero-area UV"),
                        "zero-area UV");
  // Every UV the same: no triangle has a gradient, nothing is predicted.
  for (auto &uv : soup.uvs) {
    uv = {0.25f, 0.75f};
  }
  ExpectStockValuesEverywhere(*BuildTangentMesh(soup), "one UV");
}

TEST(DegenerateTangentMeshTest, ZeroArea3dAndCollapsedFacesDecodeToTheStockValues) {
  TangentSoup soup = BumpyTangentGrid();
  // A row of vertices collapsed onto one point and a collinear row.
  for (int i = 0; i <= 6; ++i) {
    soup.positions[7 + i] = soup.positions[7];
    soup.positions[21 + i] = {static_cast<float>(i), 3.f, 0.f};
  }
  ExpectEveryNamePredicted(
      ExpectStockValuesEverywhere(*BuildTangentMesh(soup), "zero-area 3D"),
      "zero-area 3D");
  // Vertices moved onto a neighbour's position (other UVs, normals and
  // tangents): the Edgebreaker encoder drops the faces that collapse, which
  // the decoder never sees.
  std::mt19937 rng(11);
  for (int round = 0; round < 6; ++round) {
    TangentSoup collapsed = BumpyTangentGrid(9);
    std::uniform_int_distribution<int> vertex(
        0, static_cast<int>(collapsed.positions.size()) - 11);
    for (int k = 0; k < 12; ++k) {
      const int v = vertex(rng);
      collapsed.positions[v] = collapsed.positions[v + (k % 2 == 0 ? 1 : 10)];
    }
    const auto mesh = BuildTangentMesh(collapsed);
    for (const char *tangent : kTangentNames) {
      for (int cl = 5; cl <= 10; ++cl) {
        const UvEncodeSettings settings = TangentSettings(tangent, cl, 8);
        ExpectStockValues(*mesh, settings,
                          "collapsed " + std::to_string(round) + " " +
                              Label(tangent, settings));
      }
    }
  }
}

TEST(DegenerateTangentMeshTest, RepeatedCornersDecodeToTheStockValues) {
  TangentSoup soup = BumpyTangentGrid();
  soup.faces.push_back({0, 0, 8});
  soup.faces.push_back({9, 9, 9});
  soup.faces.push_back({10, 17, 10});
  ExpectEveryNamePredicted(
      ExpectStockValuesEverywhere(*BuildTangentMesh(soup), "repeated corners"),
      "repeated corners");
}

TEST(DegenerateTangentMeshTest, ZeroNormalsDecodeToTheStockValues) {
  TangentSoup soup = BumpyTangentGrid();
  for (const int v : {0, 5, 24, 25, 48}) {
    soup.normals[v] = {0.f, 0.f, 0.f};
  }
  ExpectEveryNamePredicted(
      ExpectStockValuesEverywhere(*BuildTangentMesh(soup), "some zero normals"),
      "some zero normals");
  for (auto &normal : soup.normals) {
    normal = {0.f, 0.f, 0.f};
  }
  ExpectStockValuesEverywhere(*BuildTangentMesh(soup), "zero normals");
}

TEST(DegenerateTangentMeshTest, NonFiniteNormalsKeepStockCodingWithAMessage) {
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity()}) {
    TangentSoup soup = BumpyTangentGrid();
    soup.normals[12][1] = bad;
    const auto mesh = BuildTangentMesh(soup);
    for (const char *tangent : kTangentNames) {
      const UvEncodeSettings settings = TangentSettings(tangent, 10, 8);
      std::string summary;
      EncoderBuffer buffer;
      ASSERT_TRUE(EncodeMeshWithSettings(*mesh, settings, &buffer, &summary)
                      .ok());
      EXPECT_NE(summary.find("NORMAL has NaN or infinite values"),
                std::string::npos)
          << summary;
      EXPECT_EQ(ExpectStockValues(*mesh, settings, Label(tangent, settings)),
                TangentCoding::kStock);
    }
  }
}

TEST(DegenerateTangentMeshTest, NonFiniteTangentsAreAnError) {
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity()}) {
    for (const int component : {0, 3}) {
      TangentSoup soup = BumpyTangentGrid();
      soup.tangents[20][component] = bad;
      // As TANGENT (Draco's glTF reader) and as GENERIC (glTF-Transform's
      // and gltf-pipeline's Draco encoders), where the options find the
      // tangents by their other values.
      for (const GeometryAttribute::Type type :
           {GeometryAttribute::TANGENT, GeometryAttribute::GENERIC}) {
        TangentShape shape;
        shape.tangent_type = type;
        const auto mesh = BuildTangentMesh(soup, shape);
        for (const char *tangent : kTangentNames) {
          const UvEncodeSettings settings = TangentSettings(tangent, 10, 8);
          const std::string label =
              Label(tangent, settings) + " " + std::to_string(bad) + " at " +
              std::to_string(component) +
              (type == GeometryAttribute::TANGENT ? " TANGENT" : " GENERIC");
          EncoderBuffer buffer;
          const Status status = EncodeMeshWithSettings(*mesh, settings, &buffer);
          EXPECT_FALSE(status.ok()) << label;
          EXPECT_NE(status.error_msg_string().find("NaN or infinite"),
                    std::string::npos)
              << label << ": " << status.error_msg_string();
        }
      }
    }
  }
}

// TANGENT attributes of 3 or 2 components keep stock coding with a
// message; GENERIC ones are no tangents (glTF tangents have 4) and are left
// alone.
TEST(DegenerateTangentMeshTest, TangentsOfAnotherShapeKeepStockCoding) {
  const TangentSoup soup = BumpyTangentGrid();
  for (const GeometryAttribute::Type type :
       {GeometryAttribute::TANGENT, GeometryAttribute::GENERIC}) {
    for (const int components : {2, 3}) {
      TangentShape shape;
      shape.tangent_type = type;
      shape.tangent_components = components;
      const auto mesh = BuildTangentMesh(soup, shape);
      for (const char *tangent : kTangentNames) {
        const UvEncodeSettings settings = TangentSettings(tangent, 10, 8);
        const std::string label =
            Label(tangent, settings) + " " + std::to_string(components) +
            (type == GeometryAttribute::TANGENT ? " TANGENT" : " GENERIC");
        std::string summary;
        EncoderBuffer buffer;
        ASSERT_TRUE(
            EncodeMeshWithSettings(*mesh, settings, &buffer, &summary).ok())
            << label;
        if (type == GeometryAttribute::TANGENT) {
          EXPECT_NE(summary.find("not 4 float components"), std::string::npos)
              << label << ": " << summary;
        } else {
          EXPECT_EQ(summary.find("Tangent prediction"), std::string::npos)
              << label << ": " << summary;
        }
        EXPECT_EQ(ExpectStockValues(*mesh, settings, label),
                  TangentCoding::kStock)
            << label;
      }
    }
  }
}

// Without normals or texture coordinates, with lossy (Laplacian) or
// unquantized texture coordinates and with unquantized positions the
// tangents keep stock coding and the summary says which parent is missing.
TEST(DegenerateTangentMeshTest, MissingInexactOrUnquantizedParentsKeepStockCoding) {
  const TangentSoup soup = BumpyTangentGrid();
  TangentShape no_normals;
  no_normals.with_normals = false;
  TangentShape no_uvs;
  no_uvs.with_uvs = false;
  const auto full = BuildTangentMesh(soup);
  struct Case {
    std::unique_ptr<Mesh> mesh;
    std::string uv;
    int qp, qt;
    std::string why;
  };
  std::vector<Case> cases;
  cases.push_back(
      {BuildTangentMesh(soup, no_normals), "", 14, 12, "the mesh has no NORMAL"});
  cases.push_back({BuildTangentMesh(soup, no_uvs), "", 14, 12,
                   "the mesh has no TEX_COORD 0"});
  cases.push_back({nullptr, "laplacian_mv", 14, 12, "coded lossily"});
  cases.push_back({nullptr, "", 14, 0, "TEX_COORD 0 is not quantized"});
  cases.push_back({nullptr, "", 0, 12, "POSITION is not quantized"});
  for (const Case &c : cases) {
    const Mesh &mesh = c.mesh != nullptr ? *c.mesh : *full;
    for (const char *tangent : kTangentNames) {
      const UvEncodeSettings settings =
          TangentSettings(tangent, 10, 8, c.uv, c.qp, c.qt);
      std::string summary;
      EncoderBuffer buffer;
      ASSERT_TRUE(EncodeMeshWithSettings(mesh, settings, &buffer, &summary).ok())
          << c.why;
      EXPECT_NE(summary.find("keeps stock coding"), std::string::npos)
          << c.why << ": " << summary;
      EXPECT_NE(summary.find(c.why), std::string::npos)
          << c.why << ": " << summary;
      EXPECT_EQ(ExpectStockValues(mesh, settings, c.why + " " +
                                                      Label(tangent, settings)),
                TangentCoding::kStock);
    }
  }
}

// Every convention keeps stock coding of |mesh|'s tangents at -qtg |qtg|
// and says that their grid is too fine.
void ExpectTooFineAGrid(const Mesh &mesh, int qtg) {
  for (const char *tangent : kTangentNames) {
    const UvEncodeSettings settings = TangentSettings(tangent, 10, qtg);
    std::string summary;
    EncoderBuffer buffer;
    ASSERT_TRUE(EncodeMeshWithSettings(mesh, settings, &buffer, &summary).ok())
        << Label(tangent, settings);
    EXPECT_NE(summary.find("keeps stock coding: its values span too small a "
                           "range for " + std::to_string(qtg) + " bits"),
              std::string::npos)
        << Label(tangent, settings) << ": " << summary;
  }
}

// Tangents that barely vary (a flat grid, one tangent up to float noise)
// or that span less than the unit range on every axis: Draco's quantization
// grid is then finer than the scheme's fixed point can hold, at any -qtg.
TEST(DegenerateTangentMeshTest, NearlyConstantTangentsDecodeToTheStockValues) {
  TangentSoup soup = BumpyTangentGrid();
  for (size_t v = 0; v < soup.positions.size(); ++v) {
    soup.positions[v][2] = 0.f;
    soup.normals[v] = {0.f, 0.f, 1.f};
    soup.tangents[v] = {1.f, (v % 3) * 1e-7f, 0.f, 1.f};
  }
  const auto nearly_constant = BuildTangentMesh(soup);
  ExpectStockValuesEverywhere(*nearly_constant, "nearly constant");
  ExpectTooFineAGrid(*nearly_constant, 8);
  // Exactly constant: Draco quantizes a zero range as a unit one.
  for (auto &t : soup.tangents) {
    t = {1.f, 0.f, 0.f, 1.f};
  }
  ExpectEveryNamePredicted(
      ExpectStockValuesEverywhere(*BuildTangentMesh(soup), "constant"),
      "constant", /*auto_too=*/false);
  // All w = 1 and x, y, z within [-0.7, 0.7]: a range below 2.
  TangentSoup tilted = BumpyTangentGrid();
  for (size_t v = 0; v < tilted.positions.size(); ++v) {
    const float a = 0.1f * static_cast<float>(v % 7);
    tilted.tangents[v] = {0.7f * std::cos(a), 0.7f * std::sin(a), 0.7141428f,
                          1.f};
  }
  const auto narrow = BuildTangentMesh(tilted);
  ExpectStockValuesEverywhere(*narrow, "range below 2");
  ExpectTooFineAGrid(*narrow, 21);
}

}  // namespace
}  // namespace draco
