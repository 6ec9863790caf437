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
// Meshes of Draco's testdata and their corner tables, shared by the tests
// of the seam coder.
#ifndef DRACO_UV_TESTS_DRACO_EXT_SEAMS_UV_SEAM_TEST_MESHES_H_
#define DRACO_UV_TESTS_DRACO_EXT_SEAMS_UV_SEAM_TEST_MESHES_H_

#include <memory>
#include <string>

#include "draco/mesh/mesh.h"
#include "draco/mesh/mesh_misc_functions.h"
#include "draco_ext/seams/uv_seam_coder.h"
#include "draco_ext/seams/uv_seam_edgebreaker.h"
#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {

// The corner table of |mesh|'s position connectivity; a test failure if it
// cannot be built.
inline UvSeamCornerTable CornerTableOf(const Mesh &mesh) {
  const std::unique_ptr<CornerTable> table =
      CreateCornerTableFromPositionAttribute(&mesh);
  EXPECT_TRUE(table != nullptr);
  return table == nullptr ? UvSeamCornerTable() : UvSeamCornerTableOf(*table);
}

// Mesh |name| of Draco's testdata; null, and a test failure, if it does
// not load.
inline std::unique_ptr<Mesh> ReadDracoTestMesh(const std::string &name) {
  auto mesh = ReadTestMesh(DracoTestdataPath(name));
  EXPECT_TRUE(mesh.ok()) << name;
  return mesh.ok() ? std::move(mesh).value() : nullptr;
}

}  // namespace draco

#endif  // DRACO_UV_TESTS_DRACO_EXT_SEAMS_UV_SEAM_TEST_MESHES_H_
