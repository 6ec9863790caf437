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
// MESH_PREDICTION_GEOMETRIC_TANGENT set directly on Draco's encoder: every
// asset decodes to exactly the values of the stock-coded file, for every
// convention, quantisation and Edgebreaker variant, and the scheme refuses
// what it cannot code.
#include <filesystem>
#include <string>
#include <vector>

#include "draco/compression/decode.h"
#include "draco/compression/expert_encode.h"
#include "draco/core/draco_test_base.h"
#include "prediction_schemes/tangent/geometric_tangent_settings.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

namespace fs = std::filesystem;

int TangentAttributeId(const Mesh &mesh) {
  return mesh.GetNamedAttributeId(GeometryAttribute::TANGENT);
}

struct TangentEncoding {
  int tangent_bits = 8;
  int speed = 3;  // draco_transcoder's -cl 7.
  bool geometric = true;
  uint8_t kinds = kAllGeometricTangentKinds;
};

// Encodes |mesh| like draco_transcoder -qp 14 -qt 12 -qn 10 -qtg
// |tangent_bits| (TANGENT written as GENERIC), with the geometric scheme on
// TANGENT when asked.
StatusOr<std::vector<char>> EncodeWithTangents(const Mesh &mesh,
                                               const TangentEncoding &e) {
  Mesh copy;
  copy.Copy(mesh);
  ExpertEncoder encoder(copy);
  encoder.SetSpeedOptions(e.speed, e.speed);
  for (int i = 0; i < copy.num_attributes(); ++i) {
    switch (copy.attribute(i)->attribute_type()) {
      case GeometryAttribute::POSITION:
        encoder.SetAttributeQuantization(i, 14);
        break;
      case GeometryAttribute::NORMAL:
        encoder.SetAttributeQuantization(i, 10);
        break;
      case GeometryAttribute::TEX_COORD:
        encoder.SetAttributeQuantization(i, 12);
        break;
      case GeometryAttribute::TANGENT:
        encoder.SetAttributeQuantization(i, e.tangent_bits);
        break;
      default:
        break;
    }
  }
  const int tangent = TangentAttributeId(copy);
  if (tangent < 0) {
    return Status(Status::DRACO_ERROR, "no TANGENT");
  }
  if (e.geometric) {
    DRACO_RETURN_IF_ERROR(encoder.SetAttributePredictionScheme(
        tangent, MESH_PREDICTION_GEOMETRIC_TANGENT));
    SetGeometricTangentKinds(e.kinds, tangent, &encoder.options());
  }
  copy.attribute(tangent)->set_attribute_type(GeometryAttribute::GENERIC);
  EncoderBuffer buffer;
  DRACO_RETURN_IF_ERROR(encoder.EncodeToBuffer(&buffer));
  return std::vector<char>(buffer.data(), buffer.data() + buffer.size());
}

// The bundled CC0 assets with MikkTSpace tangents and the corpus's Khronos
// glTFs with their own tangents (when the corpus is there).
std::vector<std::string> TangentAssetPaths() {
  std::vector<std::string> paths = {
      UvTestdataPath("small_torus_uv_tangents.glb"),
      UvTestdataPath("small_cube_sphere_tangents.glb"),
      UvTestdataPath("crane_spot_tangents.glb")};
  const fs::path corpus = fs::path(CorpusDir()) / "gltf";
  if (fs::is_directory(corpus)) {
    std::vector<std::string> gltfs;
    for (const auto &entry : fs::directory_iterator(corpus)) {
      if (entry.path().extension() == ".gltf") {
        gltfs.push_back(entry.path().string());
      }
    }
    std::sort(gltfs.begin(), gltfs.end());
    paths.insert(paths.end(), gltfs.begin(), gltfs.end());
  }
  return paths;
}

// Encodes |mesh| with |e| and without the scheme, decodes both and expects
// the same values; returns the two sizes.
std::pair<size_t, size_t> ExpectRoundTrip(const Mesh &mesh,
                                          const TangentEncoding &e,
                                          const std::string &label) {
  TangentEncoding stock = e;
  stock.geometric = false;
  const auto ours = EncodeWithTangents(mesh, e);
  const auto theirs = EncodeWithTangents(mesh, stock);
  EXPECT_TRUE(ours.ok()) << label << ": " << ours.status().error_msg();
  EXPECT_TRUE(theirs.ok()) << label;
  if (!ours.ok() || !theirs.ok()) {
    return {0, 0};
  }
  const auto decoded = DecodeDracoMesh(ours.value());
  const auto expected = DecodeDracoMesh(theirs.value());
  EXPECT_TRUE(decoded.ok()) << label << ": " << decoded.status().error_msg();
  if (decoded.ok() && expected.ok()) {
    ExpectSameCornerValues(*expected.value(), *decoded.value(), label);
  }
  return {ours.value().size(), theirs.value().size()};
}

TEST(MeshPredictionSchemeGeometricTangentTest,
     EveryConventionDecodesToTheStockValues) {
  for (const std::string &path : TangentAssetPaths()) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    for (int kind = 0; kind < kNumGeometricTangentKinds; ++kind) {
      TangentEncoding e;
      e.kinds = GeometricTangentKindBit(static_cast<GeometricTangentKind>(kind));
      ExpectRoundTrip(*mesh.value(), e,
                      path + " kind " + std::to_string(kind));
    }
  }
}

// Speeds 0 to 5 (-cl 5 to 10). At 6 to 9 Draco encodes every attribute with
// the positions' connectivity in one attributes encoder, whose ordering
// (PointCloudEncoder::RearrangeAttributesEncoders() compares a parent's
// attribute id with the encoder's index) accepts no parent but attribute 0,
// so Draco fails to encode the scheme there; the options layer keeps stock
// coding at those levels.
TEST(MeshPredictionSchemeGeometricTangentTest,
     EveryQuantisationAndEdgebreakerVariantDecodesToTheStockValues) {
  const auto mesh = ReadTestMesh(UvTestdataPath("crane_spot_tangents.glb"));
  ASSERT_TRUE(mesh.ok());
  for (const int bits : {2, 5, 8, 12, 16, 21}) {
    for (const int speed : {0, 3, 5}) {
      TangentEncoding e;
      e.tangent_bits = bits;
      e.speed = speed;
      ExpectRoundTrip(*mesh.value(), e,
                      "bits " + std::to_string(bits) + " speed " +
                          std::to_string(speed));
    }
  }
}

// The whole point: predicted tangents cost less than stock Draco's, on
// every asset whose tangents follow one of the conventions.
TEST(MeshPredictionSchemeGeometricTangentTest, SmallerThanStockOnEveryAsset) {
  for (const std::string &path : TangentAssetPaths()) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    for (const int bits : {8, 12}) {
      TangentEncoding e;
      e.tangent_bits = bits;
      const auto [ours, stock] = ExpectRoundTrip(*mesh.value(), e, path);
      EXPECT_LT(ours, stock) << path << " at " << bits << " bits";
    }
  }
}

// Handedness is a convention the encoder learns: the mirror image of every
// w costs the same but for the flag.
TEST(MeshPredictionSchemeGeometricTangentTest, FlippedHandednessCostsTheSame) {
  const auto mesh = ReadTestMesh(UvTestdataPath("crane_spot_tangents.glb"));
  ASSERT_TRUE(mesh.ok());
  Mesh flipped;
  flipped.Copy(*mesh.value());
  PointAttribute *const tangents =
      flipped.attribute(TangentAttributeId(flipped));
  for (AttributeValueIndex i(0); i < tangents->size(); ++i) {
    float value[4];
    tangents->GetValue(i, value);
    value[3] = -value[3];
    tangents->SetAttributeValue(i, value);
  }
  const auto original = ExpectRoundTrip(*mesh.value(), {}, "original");
  const auto mirrored = ExpectRoundTrip(flipped, {}, "flipped");
  EXPECT_NEAR(static_cast<double>(original.first), mirrored.first, 4);
}

// Tangents that have nothing to do with the UVs (random unit vectors, zero
// vectors, w neither +1 nor -1) still decode to exactly the stock values.
TEST(MeshPredictionSchemeGeometricTangentTest, UnrelatedTangentsRoundTrip) {
  const auto mesh = ReadTestMesh(UvTestdataPath("crane_spot_tangents.glb"));
  ASSERT_TRUE(mesh.ok());
  Mesh scrambled;
  scrambled.Copy(*mesh.value());
  PointAttribute *const tangents =
      scrambled.attribute(TangentAttributeId(scrambled));
  uint32_t state = 1;
  const auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / (1 << 24) * 2 - 1;
  };
  for (AttributeValueIndex i(0); i < tangents->size(); ++i) {
    float value[4] = {next(), next(), next(), next()};
    if (i.value() % 7 == 0) {
      value[0] = value[1] = value[2] = 0;
    }
    tangents->SetAttributeValue(i, value);
  }
  ExpectRoundTrip(scrambled, {}, "scrambled");
}

TEST(MeshPredictionSchemeGeometricTangentTest,
     RefusesAttributesThatAreNotTangents) {
  const auto mesh = ReadTestMesh(UvTestdataPath("crane_spot_tangents.glb"));
  ASSERT_TRUE(mesh.ok());
  Mesh copy;
  copy.Copy(*mesh.value());
  ExpertEncoder encoder(copy);
  const int tex = copy.GetNamedAttributeId(GeometryAttribute::TEX_COORD);
  const int normal = copy.GetNamedAttributeId(GeometryAttribute::NORMAL);
  EXPECT_FALSE(encoder
                   .SetAttributePredictionScheme(
                       tex, MESH_PREDICTION_GEOMETRIC_TANGENT)
                   .ok());
  EXPECT_FALSE(encoder
                   .SetAttributePredictionScheme(
                       normal, MESH_PREDICTION_GEOMETRIC_TANGENT)
                   .ok());
}

// Without one of its parents Draco drops the scheme and codes the tangents
// without prediction, a stock file; with float normals (unquantised, no
// octahedral portable values) the scheme refuses them and the encode fails
// with an error.
TEST(MeshPredictionSchemeGeometricTangentTest, NeedsItsParents) {
  const auto mesh = ReadTestMesh(UvTestdataPath("crane_spot_tangents.glb"));
  ASSERT_TRUE(mesh.ok());
  for (const GeometryAttribute::Type missing :
       {GeometryAttribute::NORMAL, GeometryAttribute::TEX_COORD}) {
    Mesh copy;
    copy.Copy(*mesh.value());
    copy.DeleteAttribute(copy.GetNamedAttributeId(missing));
    const auto ours = EncodeWithTangents(copy, {});
    TangentEncoding stock;
    stock.geometric = false;
    const auto theirs = EncodeWithTangents(copy, stock);
    ASSERT_TRUE(ours.ok() && theirs.ok()) << missing;
    const auto decoded = DecodeDracoMesh(ours.value());
    ASSERT_TRUE(decoded.ok());
    ExpectSameCornerValues(*DecodeDracoMesh(theirs.value()).value(),
                           *decoded.value(), "without a parent");
  }
  Mesh copy;
  copy.Copy(*mesh.value());
  ExpertEncoder encoder(copy);
  encoder.SetAttributeQuantization(
      copy.GetNamedAttributeId(GeometryAttribute::POSITION), 14);
  encoder.SetAttributeQuantization(
      copy.GetNamedAttributeId(GeometryAttribute::TEX_COORD), 12);
  encoder.SetAttributeQuantization(TangentAttributeId(copy), 8);
  ASSERT_TRUE(encoder
                  .SetAttributePredictionScheme(
                      TangentAttributeId(copy),
                      MESH_PREDICTION_GEOMETRIC_TANGENT)
                  .ok());
  copy.attribute(TangentAttributeId(copy))
      ->set_attribute_type(GeometryAttribute::GENERIC);
  EncoderBuffer buffer;
  EXPECT_FALSE(encoder.EncodeToBuffer(&buffer).ok());
}

}  // namespace
}  // namespace draco
