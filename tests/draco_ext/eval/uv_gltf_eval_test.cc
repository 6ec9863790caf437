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
#include "draco_ext/eval/uv_gltf_eval.h"

#include <filesystem>
#include <string>
#include <vector>

#include "draco/io/scene_io.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

namespace fs = std::filesystem;

// draco_transcoder -qp 14 -qt 12 -qn 10 -qtg |qtg|.
DracoCompressionOptions TangentCompression(int qtg) {
  DracoCompressionOptions options;
  options.quantization_position.SetQuantizationBits(14);
  options.quantization_bits_tex_coord = 12;
  options.quantization_bits_normal = 10;
  options.quantization_bits_tangent = qtg;
  return options;
}

std::string Transcoded(const std::string &input, const std::string &name,
                       const DracoCompressionOptions &options,
                       bool without_tangents = false) {
  const std::string output = UvTempPath("gltf_eval/" + name);
  fs::create_directories(fs::path(output).parent_path());
  const Status status =
      without_tangents
          ? TranscodeGltfFileWithoutTangents(input, output, options)
          : TranscodeGltfFile(input, output, options);
  EXPECT_TRUE(status.ok()) << input << ": " << status.error_msg();
  return output;
}

int64_t SumOfDracoBytes(const std::vector<GltfDracoPrimitive> &primitives) {
  int64_t bytes = 0;
  for (const GltfDracoPrimitive &primitive : primitives) {
    bytes += primitive.draco_bytes;
  }
  return bytes;
}

// The Draco buffers of a file are in it, and each primitive's TANGENT count
// is that of the points Draco coded, one value each: at least the points
// Draco's reader gives back (it merges the points that quantization made
// equal).
TEST(UvGltfEvalTest, DracoPrimitivesAreTheFilesBuffersWithTheirTangentCounts) {
  for (const std::string &asset :
       {UvTestdataPath("crane_spot_tangents.glb"),
        DracoTestdataPath("Lantern/glTF/Lantern.gltf"),
        DracoTestdataPath("CesiumMilkTruck/glTF/CesiumMilkTruck.gltf")}) {
    const std::string file =
        Transcoded(asset, "primitives.glb", TangentCompression(8));
    const auto primitives = ReadGltfDracoPrimitives(file);
    ASSERT_TRUE(primitives.ok()) << asset;
    const auto scene = ReadSceneFromFile(file);
    ASSERT_TRUE(scene.ok()) << asset;
    ASSERT_EQ(primitives.value().size(), scene.value()->NumMeshes()) << asset;
    EXPECT_LT(SumOfDracoBytes(primitives.value()),
              TranscodedGltfBytes(file).value());
    for (MeshIndex i(0); i < scene.value()->NumMeshes(); ++i) {
      const Mesh &mesh = scene.value()->GetMesh(i);
      const GltfDracoPrimitive &primitive = primitives.value()[i.value()];
      EXPECT_GT(primitive.draco_bytes, 0) << asset;
      const bool has_tangents =
          mesh.NumNamedAttributes(GeometryAttribute::TANGENT) > 0;
      EXPECT_EQ(primitive.tangent_values > 0, has_tangents) << asset;
      if (has_tangents) {
        EXPECT_GE(primitive.tangent_values, mesh.num_points())
            << asset << " " << primitive.primitive;
        EXPECT_LE(primitive.tangent_values, 3 * mesh.num_faces()) << asset;
      }
    }
  }
}

// Without tangents: the same primitives and geometry, no TANGENT, and
// smaller Draco buffers.
TEST(UvGltfEvalTest, TranscodingWithoutTangentsDropsOnlyTheTangents) {
  for (const std::string &asset : TangentGltfAssetPaths()) {
    const DracoCompressionOptions options = TangentCompression(8);
    const std::string with = Transcoded(asset, "with.glb", options);
    const std::string without = Transcoded(asset, "without.glb", options,
                                           /*without_tangents=*/true);
    const auto with_primitives = ReadGltfDracoPrimitives(with);
    const auto without_primitives = ReadGltfDracoPrimitives(without);
    ASSERT_TRUE(with_primitives.ok() && without_primitives.ok()) << asset;
    ASSERT_EQ(with_primitives.value().size(),
              without_primitives.value().size());
    for (size_t i = 0; i < with_primitives.value().size(); ++i) {
      const GltfDracoPrimitive &a = with_primitives.value()[i];
      const GltfDracoPrimitive &b = without_primitives.value()[i];
      EXPECT_EQ(a.primitive, b.primitive);
      EXPECT_EQ(b.tangent_values, 0) << asset;
      EXPECT_LT(b.draco_bytes, a.draco_bytes) << asset << " " << a.primitive;
    }
    const auto with_scene = ReadSceneFromFile(with);
    const auto without_scene = ReadSceneFromFile(without);
    ASSERT_TRUE(with_scene.ok() && without_scene.ok()) << asset;
    for (MeshIndex i(0); i < with_scene.value()->NumMeshes(); ++i) {
      Mesh expected;
      expected.Copy(with_scene.value()->GetMesh(i));
      while (expected.NumNamedAttributes(GeometryAttribute::TANGENT) > 0) {
        expected.DeleteAttribute(
            expected.GetNamedAttributeId(GeometryAttribute::TANGENT));
      }
      const Mesh &actual = without_scene.value()->GetMesh(i);
      EXPECT_EQ(CornerValues(actual, GeometryAttribute::POSITION),
                CornerValues(expected, GeometryAttribute::POSITION))
          << asset;
      EXPECT_EQ(CornerValues(actual, GeometryAttribute::NORMAL),
                CornerValues(expected, GeometryAttribute::NORMAL))
          << asset;
      EXPECT_EQ(CornerValues(actual, GeometryAttribute::TEX_COORD),
                CornerValues(expected, GeometryAttribute::TEX_COORD))
          << asset;
    }
  }
}

// A scene that differs from another in one value of any attribute (here
// the tangents and the normals) does not compare equal, and the error says
// where.
TEST(UvGltfEvalTest, SceneComparisonCoversEveryAttribute) {
  const auto scene =
      ReadSceneFromFile(UvTestdataPath("crane_spot_tangents.glb"));
  ASSERT_TRUE(scene.ok());
  EXPECT_TRUE(CompareSceneGeometry(*scene.value(), *scene.value()).ok());
  for (const GeometryAttribute::Type type :
       {GeometryAttribute::TANGENT, GeometryAttribute::NORMAL}) {
    auto changed = ReadSceneFromFile(UvTestdataPath("crane_spot_tangents.glb"));
    ASSERT_TRUE(changed.ok());
    PointAttribute *const att = changed.value()
                                    ->GetMesh(MeshIndex(0))
                                    .attribute(changed.value()
                                                   ->GetMesh(MeshIndex(0))
                                                   .GetNamedAttributeId(type));
    ASSERT_NE(att, nullptr);
    float value[4] = {0, 0, 0, 0};
    att->GetValue(AttributeValueIndex(0), value);
    value[0] = -value[0] + 0.5f;
    att->SetAttributeValue(AttributeValueIndex(0), value);
    const Status status =
        CompareSceneGeometry(*scene.value(), *changed.value());
    ASSERT_FALSE(status.ok()) << GeometryAttribute::TypeToString(type);
    EXPECT_NE(
        status.error_msg_string().find(GeometryAttribute::TypeToString(type)),
        std::string::npos)
        << status.error_msg_string();
  }
}

// On every asset with tangents, at -qtg 8 and 12: rows of the stock
// tangent coding show the stock file, those of -tangent_pred auto a file
// no bigger, with tangents no bigger, and every row reads back like stock
// coding. The tangent sums are the per-primitive costs'.
TEST(UvGltfEvalTest, TangentRowsMeasureEveryPrimitiveWithTangents) {
  UvGltfEvalOptions options;
  options.schemes = {"draco"};
  options.tangents = {"draco", "auto"};
  options.glb = true;
  for (const std::string &asset : TangentGltfAssetPaths()) {
    for (const int qtg : {8, 12}) {
      options.compression = TangentCompression(qtg);
      const auto rows = EvaluateGltfAsset(asset, fs::path(asset).filename(),
                                          options, UvTempPath("gltf_eval"));
      ASSERT_TRUE(rows.ok()) << asset << ": " << rows.status().error_msg();
      ASSERT_EQ(rows.value().size(), 2u);
      for (const UvGltfEvalRow &row : rows.value()) {
        const std::string label =
            asset + " -qtg " + std::to_string(qtg) + " " + row.tangents;
        EXPECT_EQ(row.qtg, qtg);
        EXPECT_TRUE(row.round_trip_ok) << label << ": " << row.detail;
        ASSERT_FALSE(row.tangent_costs.empty()) << label;
        int64_t values = 0, bytes = 0, stock_bytes = 0;
        for (const UvGltfTangentCost &cost : row.tangent_costs) {
          values += cost.values;
          bytes += cost.bytes;
          stock_bytes += cost.stock_bytes;
          EXPECT_GT(cost.stock_bytes, 0) << label << " " << cost.primitive;
        }
        EXPECT_EQ(row.tangent_values, values) << label;
        EXPECT_EQ(row.tangent_bytes, bytes) << label;
        EXPECT_EQ(row.stock_tangent_bytes, stock_bytes) << label;
        EXPECT_LE(row.bytes, row.stock_bytes) << label;
        EXPECT_LE(row.draco_bytes, row.stock_draco_bytes) << label;
        if (row.tangents == "draco") {
          EXPECT_EQ(row.bytes, row.stock_bytes) << label;
          EXPECT_EQ(row.tangent_bytes, row.stock_tangent_bytes) << label;
          EXPECT_FALSE(row.requires_extension) << label;
        } else if (row.requires_extension) {
          EXPECT_LT(row.tangent_bytes, row.stock_tangent_bytes) << label;
        }
      }
    }
  }
}

TEST(UvGltfEvalTest, AssetsWithoutTangentsHaveNoTangentCosts) {
  UvGltfEvalOptions options;
  options.schemes = {"auto"};
  options.tangents = {"auto"};
  const std::string asset =
      DracoTestdataPath("CesiumMilkTruck/glTF/CesiumMilkTruck.gltf");
  const auto rows =
      EvaluateGltfAsset(asset, "truck", options, UvTempPath("gltf_eval"));
  ASSERT_TRUE(rows.ok());
  for (const UvGltfEvalRow &row : rows.value()) {
    EXPECT_TRUE(row.round_trip_ok) << row.detail;
    EXPECT_TRUE(row.tangent_costs.empty());
    EXPECT_EQ(row.tangent_values, 0);
    EXPECT_EQ(row.tangent_bytes, 0);
  }
}

TEST(UvGltfEvalTest, BitsAndRatiosOfNothingAreZero) {
  EXPECT_DOUBLE_EQ(TangentBitsPerValue(100, 200), 4.0);
  EXPECT_DOUBLE_EQ(TangentBitsPerValue(100, 0), 0.0);
  EXPECT_DOUBLE_EQ(UvGltfRatio(50, 200), 0.25);
  EXPECT_DOUBLE_EQ(UvGltfRatio(50, 0), 0.0);
}

}  // namespace
}  // namespace draco
