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
// The least-squares reconstruction of [Váša & Brunnett 2014] section 5
// (uv_laplacian_system.h).
#include "prediction_schemes/laplacian/uv_laplacian_system.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "gtest/gtest.h"
#include "tests/prediction_schemes/laplacian/uv_laplacian_test_cases.h"

namespace draco {
namespace {

// Analyze() and Factorize() of the system of |op| with |anchors|.
bool SetUpSystem(const UvLaplacianMesh &mesh, const UvLaplacianOperator &op,
                 const std::vector<int> &anchors, UvLaplacianSystem *system) {
  return system->Analyze(UvTextureGraph(mesh), int64_t{1} << 26, [&] {
    return &op;
  }) && system->Factorize(anchors);
}

TEST(UvLaplacianSystemTest, FailsWhenTheOperatorCannotBeBuilt) {
  const UvTestCase c = TestdataCases().back();
  UvLaplacianSystem system;
  EXPECT_FALSE(system.Analyze(UvTextureGraph(c.mesh), int64_t{1} << 26,
                              [] { return nullptr; }));
}

TEST(UvLaplacianSystemTest, SolvesExactlyWithoutQuantization) {
  for (const UvTestCase &c : TestdataCases()) {
    for (const UvLaplacianKind kind : kKinds) {
      UvLaplacianOperator op;
      op.Build(c.mesh, UvTextureGraph(c.mesh), kind);
      const UvCharts charts =
          ComputeUvCharts(c.mesh, UvMinChartSizeForSecondAnchor(kind));
      UvLaplacianSystem system;
      ASSERT_TRUE(SetUpSystem(c.mesh, op, charts.anchors, &system)) << c.name;
      UvValues anchor_values(charts.anchors.size(), 2);
      for (size_t i = 0; i < charts.anchors.size(); ++i) {
        anchor_values.row(i) = c.uv.row(charts.anchors[i]);
      }
      const UvValues x = system.Solve(op.Apply(c.uv), anchor_values);
      EXPECT_LT((x - c.uv).cwiseAbs().maxCoeff(), 1e-6 * (1 << kFrameBits))
          << c.name << " kind " << static_cast<int>(kind);
    }
  }
}

TEST(UvLaplacianSystemTest, RankOneAnchorsMatchAFreshFactorization) {
  const UvTestCase c = TestdataCases().back();
  UvLaplacianOperator op;
  op.Build(c.mesh, UvTextureGraph(c.mesh), UvLaplacianKind::kCotangent);
  std::vector<int> anchors =
      ComputeUvCharts(
          c.mesh, UvMinChartSizeForSecondAnchor(UvLaplacianKind::kCotangent))
          .anchors;
  UvLaplacianSystem updated;
  ASSERT_TRUE(SetUpSystem(c.mesh, op, anchors, &updated));
  for (int v = 3; v < c.mesh.num_vertices(); v += c.mesh.num_vertices() / 7) {
    if (std::find(anchors.begin(), anchors.end(), v) == anchors.end()) {
      updated.AddAnchor(v);
      anchors.push_back(v);
    }
  }
  UvLaplacianSystem fresh;
  ASSERT_TRUE(SetUpSystem(c.mesh, op, anchors, &fresh));
  UvValues residuals = op.Apply(c.uv);
  residuals.array() += 100.0;  // Inconsistent: anchors matter.
  UvValues anchor_values(anchors.size(), 2);
  for (size_t i = 0; i < anchors.size(); ++i) {
    anchor_values.row(i) = c.uv.row(anchors[i]);
  }
  const UvValues a = updated.Solve(residuals, anchor_values);
  const UvValues b = fresh.Solve(residuals, anchor_values);
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-6 * (1 << kFrameBits));
}

}  // namespace
}  // namespace draco
