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
// The Laplacian texture coordinate coder of [Váša & Brunnett 2014] section 5
// on its own (uv_laplacian_coder.h).
#include "prediction_schemes/laplacian/uv_laplacian_coder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "draco/compression/config/compression_shared.h"
#include "gtest/gtest.h"
#include "tests/prediction_schemes/laplacian/uv_laplacian_test_cases.h"

namespace draco {
namespace {

UvLaplacianEncoderOptions Options(UvLaplacianKind kind, int step_bits,
                                  int anchors = 50) {
  UvLaplacianEncoderOptions options;
  options.kind = kind;
  options.step_bits = step_bits;
  options.frame_bits = kFrameBits;
  options.extra_anchors = anchors;
  return options;
}

double Step(int step_bits) {
  return ((1 << kFrameBits) - 1.0) / ((1 << step_bits) - 1.0);
}

double Rmse(const UvValues &a, const UvValues &b) {
  return std::sqrt((a - b).squaredNorm() / std::max<Eigen::Index>(1, a.rows()));
}

// Encodes and decodes |c|; the decoded values, or an empty matrix on
// failure. |stream| receives the encoded data.
UvValues RoundTrip(const UvTestCase &c,
                   const UvLaplacianEncoderOptions &options,
                   std::vector<char> *stream = nullptr) {
  EncoderBuffer buffer;
  if (!EncodeUvLaplacian(c.mesh, c.uv, options, &buffer)) {
    return UvValues();
  }
  if (stream != nullptr) {
    stream->assign(buffer.data(), buffer.data() + buffer.size());
  }
  DecoderBuffer in;
  in.Init(buffer.data(), buffer.size(), kDracoMeshBitstreamVersion);
  UvValues decoded;
  int frame_bits;
  if (!DecodeUvLaplacian(c.mesh, &in, &decoded, &frame_bits) ||
      frame_bits != kFrameBits) {
    return UvValues();
  }
  return decoded;
}

TEST(UvLaplacianCoderTest, ErrorFallsAsTheStepShrinks) {
  for (const UvTestCase &c : TestdataCases()) {
    if (c.mesh.num_vertices() < 100) {
      continue;  // Too few residuals for a trend (cube_att: 4 UVs).
    }
    for (const UvLaplacianKind kind : kKinds) {
      double previous = std::numeric_limits<double>::max();
      for (const int step_bits : {6, 10, 14}) {
        const UvValues decoded = RoundTrip(c, Options(kind, step_bits));
        ASSERT_EQ(decoded.rows(), c.uv.rows()) << c.name;
        const double rmse = Rmse(decoded, c.uv);
        EXPECT_LT(rmse, previous) << c.name << " step bits " << step_bits;
        previous = rmse;
      }
    }
  }
}

TEST(UvLaplacianCoderTest, DecoderReproducesTheEncodersReconstruction) {
  std::vector<UvTestCase> cases = TestdataCases();
  cases.push_back(ManyChartsCase(30, 20));
  for (const UvTestCase &c : cases) {
    for (const UvLaplacianKind kind : kKinds) {
      EncoderBuffer buffer;
      UvValues expected;
      ASSERT_TRUE(EncodeUvLaplacian(c.mesh, c.uv, Options(kind, 10), &buffer,
                                    &expected));
      const UvValues decoded = RoundTrip(c, Options(kind, 10));
      ASSERT_EQ(decoded.rows(), expected.rows());
      EXPECT_LT((decoded - expected).cwiseAbs().maxCoeff(), 1e-6)
          << c.name << " kind " << static_cast<int>(kind);
    }
  }
}

TEST(UvLaplacianCoderTest, CodesManySmallAndBoundaryOnlyCharts) {
  const UvTestCase c = ManyChartsCase(300, 20);
  for (const UvLaplacianKind kind : kKinds) {
    for (const int anchors : {0, 50}) {
      const UvValues decoded = RoundTrip(c, Options(kind, 12, anchors));
      ASSERT_EQ(decoded.rows(), c.uv.rows());
      // Errors stay within a small multiple of the step: the charts are
      // tiny, so the inverse Laplacian cannot accumulate much quantisation
      // error.
      EXPECT_LT(Rmse(decoded, c.uv), 2 * Step(12)) << static_cast<int>(kind);
      EXPECT_LT((decoded - c.uv).cwiseAbs().maxCoeff(), 16 * Step(12))
          << static_cast<int>(kind);
    }
  }
}

TEST(UvLaplacianCoderTest, DegenerateGeometryStillCodes) {
  // All 3D positions coincide: no cotangent or mean-value weight is usable,
  // and every chart has a single anchor.
  UvTestCase c = TestdataCases().back();
  for (auto &p : c.mesh.positions) {
    p = {1.0, 2.0, 3.0};
  }
  for (const UvLaplacianKind kind : kKinds) {
    const UvValues decoded = RoundTrip(c, Options(kind, 12));
    ASSERT_EQ(decoded.rows(), c.uv.rows()) << static_cast<int>(kind);
    EXPECT_LT(Rmse(decoded, c.uv), 0.01 * (1 << kFrameBits));
  }
}

TEST(UvLaplacianCoderTest, GreedyAnchorsLowerTheError) {
  // Paper section 5: extra anchors where the reconstruction error is
  // largest. (Greedy against random anchors, fig. 9, is measured on the
  // corpus in benchmarks/laplacian.md: greedy wins on most meshes, not all.)
  for (const UvTestCase &c : TestdataCases()) {
    if (c.mesh.num_vertices() < 200) {
      continue;
    }
    for (const UvLaplacianKind kind : kKinds) {
      const UvValues none = RoundTrip(c, Options(kind, 8, 0));
      const UvValues greedy = RoundTrip(c, Options(kind, 8, 50));
      ASSERT_EQ(none.rows(), c.uv.rows()) << c.name;
      ASSERT_EQ(greedy.rows(), c.uv.rows()) << c.name;
      EXPECT_LT(Rmse(greedy, c.uv), Rmse(none, c.uv))
          << c.name << " kind " << static_cast<int>(kind);
    }
  }
}

TEST(UvLaplacianCoderTest, DefaultAnchorsFollowTheRule) {
  std::vector<UvTestCase> cases = TestdataCases();
  cases.push_back(ManyChartsCase(300, 20));
  for (const UvTestCase &c : cases) {
    std::vector<bool> boundary;
    UvTextureGraph(c.mesh, &boundary);
    const int rule = UvDefaultExtraAnchors(
        c.mesh.num_vertices(),
        static_cast<int>(std::count(boundary.begin(), boundary.end(), true)));
    for (const UvLaplacianKind kind : kKinds) {
      std::vector<char> by_default, by_rule, by_fifty;
      ASSERT_EQ(RoundTrip(c, Options(kind, 10, kUvLaplacianDefaultExtraAnchors),
                          &by_default)
                    .rows(),
                c.uv.rows())
          << c.name;
      ASSERT_EQ(RoundTrip(c, Options(kind, 10, rule), &by_rule).rows(),
                c.uv.rows());
      EXPECT_EQ(by_default, by_rule) << c.name << " " << rule;
      if (rule != 50 && c.mesh.num_vertices() > 100) {
        RoundTrip(c, Options(kind, 10, 50), &by_fifty);
        EXPECT_NE(by_default, by_fifty) << c.name << " " << rule;
      }
    }
  }
}

TEST(UvLaplacianCoderTest, RandomAnchorsAreDeterministic) {
  const UvTestCase c = TestdataCases().back();
  UvLaplacianEncoderOptions options = Options(UvLaplacianKind::kTutte, 8);
  options.selection = UvAnchorSelection::kRandom;
  std::vector<char> a, b;
  ASSERT_EQ(RoundTrip(c, options, &a).rows(), c.uv.rows());
  ASSERT_EQ(RoundTrip(c, options, &b).rows(), c.uv.rows());
  EXPECT_EQ(a, b);
}

TEST(UvLaplacianCoderTest, RejectsEveryTruncation) {
  const UvTestCase c = TestdataCases().back();
  std::vector<char> stream;
  ASSERT_GT(RoundTrip(c, Options(UvLaplacianKind::kCotangent, 10), &stream)
                .rows(),
            0);
  for (size_t size = 0; size < stream.size(); ++size) {
    DecoderBuffer in;
    in.Init(stream.data(), size, kDracoMeshBitstreamVersion);
    UvValues decoded;
    int frame_bits;
    EXPECT_FALSE(DecodeUvLaplacian(c.mesh, &in, &decoded, &frame_bits))
        << size << " of " << stream.size() << " bytes";
  }
}

TEST(UvLaplacianCoderTest, CorruptStreamsFailOrDecodeFiniteValues) {
  const UvTestCase c = TestdataCases().back();
  std::vector<char> stream;
  ASSERT_GT(RoundTrip(c, Options(UvLaplacianKind::kTutte, 10), &stream).rows(),
            0);
  std::mt19937 random(3);
  int rejected = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<char> corrupt = stream;
    for (int flips = 0; flips < 3; ++flips) {
      corrupt[random() % corrupt.size()] ^= static_cast<char>(1 + random() % 255);
    }
    DecoderBuffer in;
    in.Init(corrupt.data(), corrupt.size(), kDracoMeshBitstreamVersion);
    UvValues decoded;
    int frame_bits;
    if (DecodeUvLaplacian(c.mesh, &in, &decoded, &frame_bits)) {
      EXPECT_TRUE(decoded.allFinite());
    } else {
      ++rejected;
    }
  }
  EXPECT_GT(rejected, 0);
}

}  // namespace
}  // namespace draco
