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
// The error target (-uv_rmse, -uv_texels): its parsing, the exactness of
// the lossless error it predicts without encoding, and, over the corpus and
// Draco's textured test meshes, that the encoder's output meets the target
// when measured independently from the decoded mesh and is never bigger
// than the lossless coding that meets it.
#include "draco_ext/options/uv_error_target.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "draco/compression/encode.h"
#include "draco_ext/common/uv_rmse.h"
#include "draco_ext/common/uv_vertices.h"
#include "draco_ext/options/uv_configure.h"
#include "draco_ext/options/uv_encode_settings.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

// Error targets of the property test: the benchmark's RMSE, a finer one and
// half a texel of a 4096 texture.
const double kTargets[] = {1.5e-3, 5e-4, 0.5 / 4096};
// Meshes of more UV vertices than this get the first target only, which
// keeps the test's run time within a few minutes.
constexpr int64_t kMaxUvVerticesForAllTargets = 20000;

Status ParseFlag(const std::vector<std::string> &args,
                 UvCompressionOptions *options) {
  std::vector<char *> argv;
  for (const std::string &arg : args) {
    argv.push_back(const_cast<char *>(arg.c_str()));
  }
  int index = 0;
  return ParseUvCompressionFlag(static_cast<int>(argv.size()), argv.data(),
                                &index, options);
}

TEST(UvErrorTargetTest, FlagsRejectNonPositiveAndNonNumericValues) {
  for (const std::string flag : {"-uv_rmse", "-uv_texels"}) {
    for (const std::string value :
         {"0", "-1", "nan", "inf", "abc", "1e-3x", ""}) {
      UvCompressionOptions options;
      const Status status = ParseFlag({flag, value}, &options);
      ASSERT_FALSE(status.ok()) << flag << " " << value;
      EXPECT_EQ(status.error_msg_string(),
                flag + " needs a positive number, got '" + value + "'.");
    }
    UvCompressionOptions options;
    EXPECT_FALSE(ParseFlag({flag}, &options).ok()) << "missing value";
  }
  for (const std::string value : {"0", "-4096", "4k", "1.5"}) {
    UvCompressionOptions options;
    EXPECT_FALSE(ParseFlag({"-uv_texture_size", value}, &options).ok());
  }
}

TEST(UvErrorTargetTest, TexelsAreATargetInTextureUnits) {
  UvCompressionOptions options;
  ASSERT_TRUE(ParseFlag({"-uv_texels", "0.5"}, &options).ok());
  EXPECT_EQ(options.MaxUvRmse().value(), 0.5 / 4096);
  ASSERT_TRUE(ParseFlag({"-uv_texture_size", "1024"}, &options).ok());
  EXPECT_EQ(options.MaxUvRmse().value(), 0.5 / 1024);
  EXPECT_TRUE(options.ChoosesPrediction());
  EXPECT_FALSE(options.IsStock());
  EXPECT_TRUE(CheckUvCompressionOptions(options).ok());
  ASSERT_TRUE(ParseFlag({"-uv_rmse", "0.001"}, &options).ok());
  EXPECT_FALSE(CheckUvCompressionOptions(options).ok()) << "both targets";
  UvCompressionOptions size_alone;
  ASSERT_TRUE(ParseFlag({"-uv_texture_size", "1024"}, &size_alone).ok());
  EXPECT_FALSE(CheckUvCompressionOptions(size_alone).ok());
}

TEST(UvErrorTargetTest, DecodeLimitFlagTakesANumberOfAtLeastOneOrNone) {
  for (const std::string value : {"0", "0.99", "-2", "nan", "inf", "abc", ""}) {
    UvCompressionOptions options;
    const Status status = ParseFlag({"-uv_decode_limit", value}, &options);
    ASSERT_FALSE(status.ok()) << value;
    EXPECT_EQ(status.error_msg_string(),
              "-uv_decode_limit needs a number of at least 1 or 'none', got '" +
                  value + "'.");
  }
  UvCompressionOptions options;
  EXPECT_EQ(options.DecodeLimit(), 2.0) << "default";
  ASSERT_TRUE(ParseFlag({"-uv_decode_limit", "1.5"}, &options).ok());
  EXPECT_EQ(options.DecodeLimit(), 1.5);
  ASSERT_TRUE(ParseFlag({"-uv_decode_limit", "none"}, &options).ok());
  EXPECT_TRUE(std::isinf(options.DecodeLimit()));
  EXPECT_FALSE(ParseFlag({"-uv_decode_limit"}, &options).ok()) << "no value";
}

TEST(UvErrorTargetTest, DecodeLimitNeedsATargetWhoseSchemeTheEncoderChooses) {
  UvCompressionOptions options;
  options.decode_limit = 3;
  EXPECT_FALSE(CheckUvCompressionOptions(options).ok()) << "no target";
  options.rmse = 1e-3;
  EXPECT_TRUE(CheckUvCompressionOptions(options).ok());
  options.prediction = UvPrediction::kAuto;
  EXPECT_TRUE(CheckUvCompressionOptions(options).ok());
  options.prediction = UvPrediction::kWeighted;
  EXPECT_FALSE(CheckUvCompressionOptions(options).ok()) << "named scheme";
}

// The error predicted without encoding is the one a decoder reproduces.
TEST(UvErrorTargetTest, QuantizationRmseIsTheDecodedErrorOfLosslessCoding) {
  for (const std::string &path : TexturedObjPlyMeshPaths()) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    const PointAttribute &uv =
        *mesh.value()->GetNamedAttribute(GeometryAttribute::TEX_COORD);
    for (const int qt : {4, 10, 16}) {
      const auto predicted = QuantizationRmse(*mesh.value(), uv, qt);
      ASSERT_TRUE(predicted.ok()) << path;
      const auto encoded =
          EncodeMeshToBytes(*mesh.value(), Settings(14, qt, 10, ""));
      ASSERT_TRUE(encoded.ok()) << path;
      const auto decoded = DecodeDracoMesh(encoded.value());
      ASSERT_TRUE(decoded.ok()) << path;
      const auto measured = UvRmseOf(*mesh.value(), *decoded.value(), 14, 0);
      ASSERT_TRUE(measured.ok()) << path;
      EXPECT_NEAR(predicted.value(), measured.value(), 1e-9 * measured.value())
          << path << " qt " << qt;
    }
  }
}

// A named -uv_pred with a target keeps its scheme and only chooses -qt.
TEST(UvErrorTargetTest, ANamedPredictionKeepsItsScheme) {
  const auto mesh = ReadTestMesh(UvTestdataPath("crane_spot.obj"));
  ASSERT_TRUE(mesh.ok());
  const int att_id =
      mesh.value()->GetNamedAttributeId(GeometryAttribute::TEX_COORD);
  for (const std::string name : {"weighted", "laplacian_mv"}) {
    if (name == "laplacian_mv" && !HasUvLaplacianCoder()) {
      continue;
    }
    UvCompressionOptions options = UvOptions(name);
    options.rmse = 1e-3;
    Encoder encoder;
    encoder.SetAttributeQuantization(GeometryAttribute::POSITION, 14);
    encoder.SetAttributeQuantization(GeometryAttribute::TEX_COORD, 12);
    encoder.SetSpeedOptions(0, 0);
    ExpertEncoder expert(*mesh.value());
    expert.Reset(encoder.CreateExpertEncoderOptions(*mesh.value()));
    const auto summary =
        ConfigureUvCompression(options, mesh.value().get(), &expert);
    ASSERT_TRUE(summary.ok()) << name << ": " << summary.status().error_msg();
    EXPECT_NE(summary.value().find("-> " + name + " -qt "), std::string::npos)
        << summary.value();
    EXPECT_EQ(expert.options().GetAttributeInt(att_id, "prediction_scheme", -1),
              UvPredictionMethod(options.prediction));
  }
}

// What ConfigureUvCompression() chose for the TEX_COORD attribute of |mesh|
// at RMSE 1.5e-3 with |decode_limit| (unset: the default).
struct TargetChoice {
  std::string summary;
  int prediction_scheme = -1;
  size_t bytes = 0;
};

TargetChoice ChooseForTarget(const Mesh &mesh,
                             std::optional<double> decode_limit) {
  UvCompressionOptions options;
  options.rmse = 1.5e-3;
  options.decode_limit = decode_limit;
  Encoder encoder;
  encoder.SetAttributeQuantization(GeometryAttribute::POSITION, 14);
  encoder.SetAttributeQuantization(GeometryAttribute::TEX_COORD, 12);
  encoder.SetSpeedOptions(0, 0);
  ExpertEncoder expert(mesh);
  expert.Reset(encoder.CreateExpertEncoderOptions(mesh));
  const auto summary = ConfigureUvCompression(options, &mesh, &expert);
  TargetChoice choice;
  EXPECT_TRUE(summary.ok()) << summary.status().error_msg();
  if (!summary.ok()) {
    return choice;
  }
  choice.summary = summary.value();
  choice.prediction_scheme = expert.options().GetAttributeInt(
      mesh.GetNamedAttributeId(GeometryAttribute::TEX_COORD),
      "prediction_scheme", -1);
  EncoderBuffer buffer;
  EXPECT_TRUE(expert.EncodeToBuffer(&buffer).ok());
  choice.bytes = buffer.size();
  return choice;
}

// Small meshes of our testdata and, when present, of the corpus (the
// Laplacian wins at RMSE 1.5e-3 on khr_suzanne without a limit).
std::vector<std::string> DecodeLimitMeshes() {
  std::vector<std::string> paths = {UvTestdataPath("crane_spot.obj"),
                                    UvTestdataPath("torus_uv.obj")};
  for (const std::string &path : CorpusMeshPaths()) {
    for (const std::string name : {"khr_suzanne", "khr_waterbottle"}) {
      if (path.find("/" + name + ".obj") != std::string::npos) {
        paths.push_back(path);
      }
    }
  }
  return paths;
}

// The limit is a bound on the estimate: a limit just below a mesh's
// estimate never gives the Laplacian, one just above it and none give
// the same choice as each other, never bigger than under the lower limit,
// and the default of 2 decides as a limit of 2.
TEST(UvErrorTargetTest,
     DecodeLimitExcludesTheLaplacianWhereItsEstimateIsAbove) {
  if (!HasUvLaplacianCoder()) {
    GTEST_SKIP() << "no Laplacian coder in this build";
  }
  const int laplacian = MESH_PREDICTION_TEX_COORDS_LAPLACIAN;
  bool laplacian_chosen = false;
  for (const std::string &path : DecodeLimitMeshes()) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    const auto estimate = EstimateUvLaplacianDecode(
        *mesh.value(),
        mesh.value()->GetNamedAttributeId(GeometryAttribute::TEX_COORD));
    ASSERT_TRUE(estimate.ok()) << path << ": " << estimate.status().error_msg();
    const double ratio = estimate.value().ratio;
    EXPECT_GT(ratio, 1.0) << path;
    const TargetChoice below =
        ChooseForTarget(*mesh.value(), std::max(1.0, ratio * 0.99));
    EXPECT_NE(below.prediction_scheme, laplacian) << path << below.summary;
    EXPECT_NE(below.summary.find("not tried"), std::string::npos)
        << below.summary;
    const TargetChoice above = ChooseForTarget(*mesh.value(), ratio * 1.01);
    const TargetChoice none =
        ChooseForTarget(*mesh.value(), std::numeric_limits<double>::infinity());
    EXPECT_EQ(above.prediction_scheme, none.prediction_scheme) << path;
    EXPECT_EQ(above.bytes, none.bytes) << path;
    EXPECT_LE(none.bytes, below.bytes) << path;
    EXPECT_NE(none.summary.find("no -uv_decode_limit"), std::string::npos)
        << none.summary;
    laplacian_chosen |= none.prediction_scheme == laplacian;
    const TargetChoice by_default = ChooseForTarget(*mesh.value(), {});
    const TargetChoice two = ChooseForTarget(*mesh.value(), 2.0);
    EXPECT_EQ(by_default.bytes, two.bytes) << path;
    if (ratio > 2.0) {
      EXPECT_NE(by_default.prediction_scheme, laplacian) << path;
    }
  }
  if (!CorpusMeshPaths().empty()) {
    EXPECT_TRUE(laplacian_chosen) << "no mesh where lifting the limit matters";
  }
}

// Encodes |mesh| to |max_rmse| and checks the decoded error of every UV set
// and the size against stock Draco's and -uv_pred auto's lossless coding at
// the coarsest grid that meets the target.
void ExpectMeetsTarget(const std::string &name, const Mesh &mesh,
                       double max_rmse) {
  UvEncodeSettings settings = Settings(14, 12, 10, "");
  settings.uv.rmse = max_rmse;
  const auto encoded = EncodeMeshToBytes(mesh, settings);
  ASSERT_TRUE(encoded.ok()) << name << ": " << encoded.status().error_msg();
  const auto decoded = DecodeDracoMesh(encoded.value());
  ASSERT_TRUE(decoded.ok()) << name;
  int grid_qt = 0;
  for (int i = 0; i < mesh.NumNamedAttributes(GeometryAttribute::TEX_COORD);
       ++i) {
    const auto rmse = UvRmseOf(mesh, *decoded.value(), 14, i);
    ASSERT_TRUE(rmse.ok()) << name;
    EXPECT_LE(rmse.value(), max_rmse) << name << " UV set " << i;
    const auto qt = SmallestQuantizationBitsFor(
        mesh, *mesh.GetNamedAttribute(GeometryAttribute::TEX_COORD, i),
        max_rmse, 30);
    ASSERT_TRUE(qt.ok()) << name;
    grid_qt = std::max(grid_qt, qt.value());
  }
  for (const std::string scheme : {"", "auto"}) {
    const auto lossless =
        EncodeMeshToBytes(mesh, Settings(14, grid_qt, 10, scheme));
    ASSERT_TRUE(lossless.ok()) << name;
    EXPECT_LE(encoded.value().size(), lossless.value().size())
        << name << " RMSE " << max_rmse << " vs '" << scheme << "' -qt "
        << grid_qt;
  }
}

std::vector<std::string> TexturedMeshes() {
  std::vector<std::string> paths = CorpusMeshPaths();
  for (const std::string &name : DracoTestdataTexturedMeshes()) {
    paths.push_back(DracoTestdataPath(name));
  }
  return paths;
}

TEST(UvErrorTargetTest, MeetsTheTargetAndBeatsLosslessOnEveryMesh) {
  for (const std::string &path : TexturedMeshes()) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    const int64_t uv_vertices = NumUvVertices(
        *mesh.value(),
        *mesh.value()->GetNamedAttribute(GeometryAttribute::TEX_COORD));
    for (const double max_rmse : kTargets) {
      ExpectMeetsTarget(path, *mesh.value(), max_rmse);
      if (uv_vertices > kMaxUvVerticesForAllTargets) {
        break;
      }
    }
  }
}

}  // namespace
}  // namespace draco
