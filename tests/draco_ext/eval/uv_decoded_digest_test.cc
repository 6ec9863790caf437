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
#include "draco_ext/eval/uv_decoded_digest.h"

#include <string>
#include <vector>

#include "draco/io/file_utils.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

// A mesh of |num_points| points with one float position each and one face.
std::unique_ptr<Mesh> OneFaceMesh(int num_points, const Mesh::Face &face) {
  std::unique_ptr<Mesh> mesh(new Mesh());
  mesh->set_num_points(num_points);
  GeometryAttribute position;
  position.Init(GeometryAttribute::POSITION, nullptr, 3, DT_FLOAT32, false,
                sizeof(float) * 3, 0);
  const int id = mesh->AddAttribute(position, true, num_points);
  for (AttributeValueIndex i(0); i < num_points; ++i) {
    const float value[3] = {static_cast<float>(i.value()), 0.f, 0.f};
    mesh->attribute(id)->SetAttributeValue(i, value);
  }
  mesh->AddFace(face);
  return mesh;
}

TEST(UvDecodedDigestTest, CheckMeshIndicesAcceptsAValidMesh) {
  const auto mesh =
      OneFaceMesh(3, {PointIndex(0), PointIndex(1), PointIndex(2)});
  EXPECT_TRUE(CheckMeshIndices(*mesh).ok());
}

TEST(UvDecodedDigestTest, CheckMeshIndicesRejectsFacesBeyondThePoints) {
  const auto mesh =
      OneFaceMesh(3, {PointIndex(0), PointIndex(1), PointIndex(3)});
  const Status status = CheckMeshIndices(*mesh);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.error_msg_string().find("uses point 3 of 3"),
            std::string::npos)
      << status.error_msg_string();
}

// Files that stock Draco's sequential connectivity decoder accepts with
// face indices beyond the points (found by scripts/fuzz.sh); the digest
// must report them instead of reading out of bounds.
TEST(UvDecodedDigestTest, RejectsDecodedMeshesWithFacesBeyondThePoints) {
  for (const std::string name :
       {"stock_sequential_faces_beyond_points_1.drc",
        "stock_sequential_faces_beyond_points_2.drc"}) {
    std::vector<char> data;
    ASSERT_TRUE(ReadFileToBuffer(UvTestdataPath("fuzz/decode/" + name), &data));
    for (const bool quantized : {false, true}) {
      const auto digest =
          DecodedMeshDigest(data.data(), data.size(), quantized);
      ASSERT_FALSE(digest.ok()) << name;
      EXPECT_NE(digest.status().error_msg_string().find("uses point"),
                std::string::npos)
          << digest.status().error_msg_string();
    }
  }
}

}  // namespace
}  // namespace draco
