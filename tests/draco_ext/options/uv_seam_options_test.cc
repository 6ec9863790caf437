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
#include "draco_ext/options/uv_seam_options.h"

#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

TEST(UvSeamOptionsTest, SetsAndReadsTheCodingOnEncoderOptions) {
  EncoderOptions options = EncoderOptions::CreateDefaultOptions();
  EXPECT_EQ(GetUvSeamCoding(options), UvSeamCoding::kDraco);
  SetUvSeamCoding(UvSeamCoding::kContext, &options);
  EXPECT_EQ(GetUvSeamCoding(options), UvSeamCoding::kContext);
  SetUvSeamCoding(UvSeamCoding::kDraco, &options);
  EXPECT_EQ(GetUvSeamCoding(options), UvSeamCoding::kDraco);
}

class UvSeamConfigureTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto mesh = ReadTestMesh(UvTestdataPath("torus_uv.obj"));
    ASSERT_TRUE(mesh.ok());
    mesh_ = std::move(mesh).value();
  }
  std::unique_ptr<Mesh> mesh_;
};

TEST_F(UvSeamConfigureTest, DracoOrNoNameLeavesTheOutputUnchanged) {
  for (const int cl : {0, 3, 7, 10}) {
    const auto none = EncodeMeshToBytes(*mesh_, {14, 12, cl});
    const auto draco =
        EncodeMeshToBytes(*mesh_, Settings(14, 12, cl, "draco+draco"));
    ASSERT_TRUE(none.ok() && draco.ok());
    EXPECT_EQ(none.value(), draco.value()) << cl;
  }
}

TEST_F(UvSeamConfigureTest, ContextChangesAndShrinksTheSeams) {
  const auto stock = EncodeMeshToBytes(*mesh_, {14, 12, 10});
  const auto context =
      EncodeMeshToBytes(*mesh_, Settings(14, 12, 10, "draco+context"));
  ASSERT_TRUE(stock.ok() && context.ok());
  EXPECT_LT(context.value().size(), stock.value().size());
}

TEST_F(UvSeamConfigureTest, ContextKeepsStockWhereDracoCodesNoSeams) {
  // -cl 1..4: Draco cuts the mesh along the seams.
  const auto stock = EncodeMeshToBytes(*mesh_, {14, 12, 3});
  const auto context =
      EncodeMeshToBytes(*mesh_, Settings(14, 12, 3, "draco+context"));
  ASSERT_TRUE(stock.ok() && context.ok());
  EXPECT_EQ(stock.value(), context.value());
  // Positions only: no seams at all.
  Mesh plain;
  plain.Copy(*mesh_);
  plain.DeleteAttribute(
      plain.GetNamedAttributeId(GeometryAttribute::TEX_COORD));
  const auto plain_stock = EncodeMeshToBytes(plain, {14, 12, 10});
  const auto plain_context =
      EncodeMeshToBytes(plain, Settings(14, 12, 10, "draco+context"));
  ASSERT_TRUE(plain_stock.ok() && plain_context.ok());
  EXPECT_EQ(plain_stock.value(), plain_context.value());
  ExpertEncoder encoder(plain);
  const auto summary =
      ConfigureUvSeams(UvSeamCoding::kContext, &plain, &encoder);
  ASSERT_TRUE(summary.ok());
  EXPECT_NE(summary.value().find("stock coding kept"), std::string::npos);
}

TEST_F(UvSeamConfigureTest, ContextNeedsEdgebreakerAndAMesh) {
  const auto sequential =
      EncodeMeshToBytes(*mesh_, Settings(14, 12, 0, "draco+context"));
  ASSERT_FALSE(sequential.ok());
  EXPECT_NE(sequential.status().error_msg_string().find("-cl"),
            std::string::npos);
  ExpertEncoder encoder(*mesh_);
  EXPECT_FALSE(
      ConfigureUvSeams(UvSeamCoding::kContext, nullptr, &encoder).ok());
  // Stock coding needs nothing and changes nothing.
  const auto stock = ConfigureUvSeams(UvSeamCoding::kDraco, nullptr, &encoder);
  ASSERT_TRUE(stock.ok());
  EXPECT_EQ(stock.value(), "");
  EXPECT_EQ(GetUvSeamCoding(encoder.options()), UvSeamCoding::kDraco);
}

}  // namespace
}  // namespace draco
