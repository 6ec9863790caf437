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
#include <random>

#include "draco/compression/attributes/mesh_attribute_indices_encoding_data.h"
#include "draco/compression/attributes/prediction_schemes/mesh_prediction_scheme_data.h"
#include "draco/compression/attributes/prediction_schemes/prediction_scheme_wrap_decoding_transform.h"
#include "draco/compression/attributes/prediction_schemes/prediction_scheme_wrap_encoding_transform.h"
#include "draco/compression/mesh/traverser/depth_first_traverser.h"
#include "draco/compression/mesh/traverser/mesh_attribute_indices_encoding_observer.h"
#include "draco/compression/mesh/traverser/mesh_traversal_sequencer.h"
#include "draco/mesh/mesh_misc_functions.h"
#include "gtest/gtest.h"
#include "prediction_schemes/weighted/mesh_prediction_scheme_tex_coords_weighted_decoder.h"
#include "prediction_schemes/weighted/mesh_prediction_scheme_tex_coords_weighted_encoder.h"
#include "prediction_schemes/weighted/uv_processing_order.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

typedef MeshPredictionSchemeData<CornerTable> MeshData;
typedef MeshPredictionSchemeTexCoordsWeightedEncoder<
    int32_t, PredictionSchemeWrapEncodingTransform<int32_t>, MeshData>
    WeightedEncoder;
typedef MeshPredictionSchemeTexCoordsWeightedDecoder<
    int32_t, PredictionSchemeWrapDecodingTransform<int32_t>, MeshData>
    WeightedDecoder;

// A triangulated (n+1) x (n+1) grid in the plane origin + i u + j v with
// int32 positions, and int32 texture coordinates uv(i, j), one per vertex.
template <class UvFunctionT>
std::unique_ptr<Mesh> MakeGridMesh(int n, const VectorD<int32_t, 3> &origin,
                                   const VectorD<int32_t, 3> &u,
                                   const VectorD<int32_t, 3> &v,
                                   UvFunctionT uv) {
  std::unique_ptr<Mesh> mesh(new Mesh());
  const int num_points = (n + 1) * (n + 1);
  mesh->set_num_points(num_points);
  GeometryAttribute pos, tex;
  pos.Init(GeometryAttribute::POSITION, nullptr, 3, DT_INT32, false, 12, 0);
  tex.Init(GeometryAttribute::TEX_COORD, nullptr, 2, DT_INT32, false, 8, 0);
  const int pos_id = mesh->AddAttribute(pos, true, num_points);
  const int tex_id = mesh->AddAttribute(tex, true, num_points);
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const AttributeValueIndex index(j * (n + 1) + i);
      const VectorD<int32_t, 3> p = origin + u * i + v * j;
      const VectorD<int32_t, 2> t = uv(i, j);
      mesh->attribute(pos_id)->SetAttributeValue(index, &p[0]);
      mesh->attribute(tex_id)->SetAttributeValue(index, &t[0]);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const PointIndex a(j * (n + 1) + i), b(a + 1), c(a + n + 1), d(c + 1);
      mesh->AddFace({a, b, d});
      mesh->AddFace({a, d, c});
    }
  }
  return mesh;
}

// Runs the weighted predictor, encoder and decoder directly on a mesh with
// one texture coordinate per vertex, with Draco's depth-first traversal
// providing the data order.
class WeightedPredictionHarness {
 public:
  explicit WeightedPredictionHarness(const Mesh &mesh)
      : mesh_(mesh),
        corner_table_(CreateCornerTableFromPositionAttribute(&mesh)) {
    typedef MeshAttributeIndicesEncodingObserver<CornerTable> Observer;
    typedef DepthFirstTraverser<CornerTable, Observer> Traverser;
    encoding_data_.Init(corner_table_->num_vertices());
    MeshTraversalSequencer<Traverser> sequencer(&mesh, &encoding_data_);
    Observer observer(corner_table_.get(), &mesh, &sequencer, &encoding_data_);
    Traverser traverser;
    traverser.Init(corner_table_.get(), observer);
    sequencer.SetTraverser(traverser);
    sequencer.GenerateSequence(&point_ids_);
    mesh_data_.Set(&mesh, corner_table_.get(),
                   &encoding_data_.encoded_attribute_value_index_to_corner_map,
                   &encoding_data_.vertex_to_encoded_attribute_value_index_map);
    for (const PointIndex point : point_ids_) {
      int32_t value[2];
      tex()->GetMappedValue(point, value);
      values_.insert(values_.end(), value, value + 2);
    }
  }

  const std::vector<int32_t> &values() const { return values_; }

  // The wrapped residuals of a predictor pass with |config|.
  std::vector<int32_t> Residuals(const UvPredictionConfig &config,
                                 int max_threads = 2) {
    MeshPredictionSchemeTexCoordsWeightedPredictor<int32_t> predictor;
    predictor.set_max_threads(max_threads);
    predictor.SetPositionAttribute(*position());
    predictor.SetEntryToPointIdMap(point_ids_.data());
    PredictionSchemeWrapEncodingTransform<int32_t> transform;
    transform.Init(values_.data(), static_cast<int>(values_.size()), 2);
    std::vector<int32_t> residuals;
    RunUvPrediction(mesh_data_, config, values_.data(), &predictor,
                    [&](int step, int entry) {
                      int32_t correction[2];
                      transform.ComputeCorrection(values_.data() + 2 * entry,
                                                  predictor.predicted_value(),
                                                  correction);
                      residuals.insert(residuals.end(), correction,
                                       correction + 2);
                      predictor.Update(step, values_.data(), correction);
                      return true;
                    });
    return residuals;
  }

  // Encodes with the weighted encoder and decodes with the decoder.
  std::vector<int32_t> RoundTrip() {
    WeightedEncoder encoder(tex(),
                            PredictionSchemeWrapEncodingTransform<int32_t>(),
                            mesh_data_);
    EXPECT_TRUE(encoder.SetParentAttribute(position()));
    std::vector<int32_t> corrections(values_.size());
    EXPECT_TRUE(encoder.ComputeCorrectionValues(
        values_.data(), corrections.data(), static_cast<int>(values_.size()),
        2, point_ids_.data()));
    EncoderBuffer prediction_data;
    EXPECT_TRUE(encoder.EncodePredictionData(&prediction_data));

    WeightedDecoder decoder(tex(),
                            PredictionSchemeWrapDecodingTransform<int32_t>(),
                            mesh_data_);
    EXPECT_TRUE(decoder.SetParentAttribute(position()));
    DecoderBuffer buffer;
    buffer.Init(prediction_data.data(), prediction_data.size());
    buffer.set_bitstream_version(kDracoMeshBitstreamVersion);
    EXPECT_TRUE(decoder.DecodePredictionData(&buffer));
    std::vector<int32_t> decoded(corrections);
    EXPECT_TRUE(decoder.ComputeOriginalValues(
        decoded.data(), decoded.data(), static_cast<int>(decoded.size()), 2,
        point_ids_.data()));
    return decoded;
  }

 private:
  const PointAttribute *tex() const {
    return mesh_.GetNamedAttribute(GeometryAttribute::TEX_COORD);
  }
  const PointAttribute *position() const {
    return mesh_.GetNamedAttribute(GeometryAttribute::POSITION);
  }

  const Mesh &mesh_;
  std::unique_ptr<CornerTable> corner_table_;
  MeshAttributeIndicesEncodingData encoding_data_;
  std::vector<PointIndex> point_ids_;
  MeshData mesh_data_;
  std::vector<int32_t> values_;
};

int CountNonZero(const std::vector<int32_t> &values) {
  return static_cast<int>(
      std::count_if(values.begin(), values.end(), [](int32_t v) { return v; }));
}

// The affine-exactness property on whole meshes: a flat grid in a tilted
// plane whose texture coordinates are an arbitrary affine function of the
// grid coordinates. The weighted parallelogram (and the parallelogram) are
// exact there, so once the adaptive predictor has seen a few vertices it
// predicts every vertex exactly; the chart's first vertices carry its six
// free parameters.
TEST(MeshPredictionSchemeTexCoordsWeightedTest,
     PredictsAffineParameterizationsExactly) {
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> coef(-40, 40);
  for (int trial = 0; trial < 20; ++trial) {
    const int m00 = coef(rng), m01 = coef(rng), m10 = coef(rng),
              m11 = coef(rng);
    if (m00 * m11 - m01 * m10 == 0) {
      continue;
    }
    const auto mesh = MakeGridMesh(
        12, VectorD<int32_t, 3>(100, 200, 300), VectorD<int32_t, 3>(7, 2, 3),
        VectorD<int32_t, 3>(-2, 5, 4), [&](int i, int j) {
          return VectorD<int32_t, 2>(m00 * i + m01 * j + 2000,
                                     m10 * i + m11 * j + 2000);
        });
    WeightedPredictionHarness harness(*mesh);
    const std::vector<int32_t> residuals =
        harness.Residuals({true, UvPredictorKind::kAdaptive});
    const int num_vertices = static_cast<int>(residuals.size()) / 2;
    EXPECT_LE(CountNonZero(residuals), 12) << "trial " << trial << " of "
                                           << num_vertices << " vertices";
    EXPECT_EQ(harness.RoundTrip(), harness.values());
  }
}

// Conformal parameterisations (a rotation and uniform scale of the plane)
// are predicted exactly by the similarity rule as well, so both kinds reach
// exact predictions.
TEST(MeshPredictionSchemeTexCoordsWeightedTest,
     PredictsConformalParameterizationsExactly) {
  const auto mesh = MakeGridMesh(
      10, VectorD<int32_t, 3>(0, 0, 0), VectorD<int32_t, 3>(20, 0, 0),
      VectorD<int32_t, 3>(0, 20, 0), [](int i, int j) {
        return VectorD<int32_t, 2>(3 * i - 4 * j + 500, 4 * i + 3 * j + 500);
      });
  WeightedPredictionHarness harness(*mesh);
  for (const UvPredictorKind kind :
       {UvPredictorKind::kAdaptive, UvPredictorKind::kAgreementWeighted,
        UvPredictorKind::kReachAdaptive, UvPredictorKind::kReachMean}) {
    const bool max_degree_order = !UsesReachStencil(kind);
    EXPECT_LE(CountNonZero(harness.Residuals({max_degree_order, kind})),
              4)
        << static_cast<int>(kind);
  }
}

// Decoding must reproduce the encoder's input exactly for any values (random
// UVs stress every fallback and the range guards).
TEST(MeshPredictionSchemeTexCoordsWeightedTest, DecoderInvertsEncoderOnRandomUvs) {
  std::mt19937 rng(23);
  for (const int range : {4, 1000, (1 << 20) - 1}) {
    std::uniform_int_distribution<int32_t> uv(0, range);
    const auto mesh = MakeGridMesh(
        9, VectorD<int32_t, 3>(0, 0, 0), VectorD<int32_t, 3>(300, 10, -40),
        VectorD<int32_t, 3>(5, 280, 90),
        [&](int, int) { return VectorD<int32_t, 2>(uv(rng), uv(rng)); });
    WeightedPredictionHarness harness(*mesh);
    EXPECT_EQ(harness.RoundTrip(), harness.values()) << "range " << range;
  }
}

// Large meshes (this grid has 10,201 vertices) have their stencils' frames
// computed ahead on a second thread; the residuals must not depend on it. Smooth texture coordinates
// exercise the stencils, noisy ones the fallbacks.
TEST(MeshPredictionSchemeTexCoordsWeightedTest,
     PredictionIsTheSameOnOneAndTwoThreads) {
  std::mt19937 rng(29);
  std::uniform_int_distribution<int32_t> noise(-3, 3);
  for (const int noise_scale : {0, 1, 1000}) {
    const auto mesh = MakeGridMesh(
        100, VectorD<int32_t, 3>(0, 0, 0), VectorD<int32_t, 3>(30, 1, -4),
        VectorD<int32_t, 3>(2, 28, 9), [&](int i, int j) {
          return VectorD<int32_t, 2>(
              5 * i + j * j / 7 + noise_scale * noise(rng) + 4000,
              3 * j - i * j / 9 + noise_scale * noise(rng) + 4000);
        });
    WeightedPredictionHarness harness(*mesh);
    for (const UvPredictorKind kind :
         {UvPredictorKind::kAdaptive, UvPredictorKind::kAgreementWeighted,
          UvPredictorKind::kReachAdaptive, UvPredictorKind::kReachMean}) {
      const UvPredictionConfig config{!UsesReachStencil(kind), kind};
      const std::vector<int32_t> one_thread = harness.Residuals(config, 1);
      EXPECT_GT(CountNonZero(one_thread), 0);
      EXPECT_EQ(harness.Residuals(config, 2), one_thread)
          << "noise " << noise_scale << " kind " << static_cast<int>(kind);
    }
  }
}

struct RoundTripCase {
  int qp;
  int qt;
  int cl;
  const char *scheme;
};

// Decodes |mesh| encoded with -uv_pred |c.scheme| and with stock Draco under
// the same settings; the texture coordinates (and everything else) must be
// bit-identical, since both are lossless on the same quantisation grid.
void ExpectWeightedMatchesStock(const Mesh &mesh, const RoundTripCase &c,
                                const std::string &label) {
  const auto stock = EncodeMeshToBytes(mesh, {c.qp, c.qt, c.cl});
  ASSERT_TRUE(stock.ok()) << label << ": " << stock.status().error_msg();
  const auto ours =
      EncodeMeshToBytes(mesh, Settings(c.qp, c.qt, c.cl, c.scheme));
  ASSERT_TRUE(ours.ok()) << label << ": " << ours.status().error_msg();
  const auto stock_mesh = DecodeDracoMesh(stock.value());
  const auto our_mesh = DecodeDracoMesh(ours.value());
  ASSERT_TRUE(stock_mesh.ok() && our_mesh.ok()) << label;
  const int num_tex =
      stock_mesh.value()->NumNamedAttributes(GeometryAttribute::TEX_COORD);
  ASSERT_EQ(num_tex,
            our_mesh.value()->NumNamedAttributes(GeometryAttribute::TEX_COORD));
  for (int i = 0; i < num_tex; ++i) {
    EXPECT_EQ(CornerValues(*stock_mesh.value(), GeometryAttribute::TEX_COORD, i),
              CornerValues(*our_mesh.value(), GeometryAttribute::TEX_COORD, i))
        << label << " TEX_COORD " << i;
  }
  EXPECT_EQ(CornerValues(*stock_mesh.value(), GeometryAttribute::POSITION),
            CornerValues(*our_mesh.value(), GeometryAttribute::POSITION))
      << label;
}

TEST(MeshPredictionSchemeTexCoordsWeightedTest, RoundTripsBitExactOnDracoTestdata) {
  const std::vector<std::string> meshes = DracoTestdataTexturedMeshes();
  ASSERT_GE(meshes.size(), 10u);
  for (const std::string &name : meshes) {
    const auto mesh = ReadTestMesh(DracoTestdataPath(name));
    ASSERT_TRUE(mesh.ok()) << name;
    for (const RoundTripCase c :
         {RoundTripCase{11, 8, 10, "weighted"}, {11, 10, 7, "weighted"},
          {14, 12, 10, "weighted"}, {14, 14, 10, "weighted"},
          {20, 12, 10, "weighted"}, {11, 10, 10, "weighted_multi"},
          {14, 12, 7, "weighted_multi"}}) {
      ExpectWeightedMatchesStock(*mesh.value(), c,
                                 name + " " + c.scheme + " qp" +
                                     std::to_string(c.qp) + " qt" +
                                     std::to_string(c.qt));
    }
  }
}

// A copy of |mesh| whose attributes are in reverse order, POSITION last, as
// a glTF reader may give them.
std::unique_ptr<Mesh> WithPositionLast(const Mesh &mesh) {
  auto copy = std::make_unique<Mesh>();
  copy->set_num_points(mesh.num_points());
  for (FaceIndex f(0); f < mesh.num_faces(); ++f) {
    copy->AddFace(mesh.face(f));
  }
  for (int i = mesh.num_attributes() - 1; i >= 0; --i) {
    auto att = std::make_unique<PointAttribute>();
    att->CopyFrom(*mesh.attribute(i));
    copy->AddAttribute(std::move(att));
  }
  return copy;
}

// At speed 6 and above (-cl 3, 4) Edgebreaker encodes every attribute in
// one attributes encoder; the prediction's POSITION parent must be ordered
// within it wherever it is (patch 0015).
TEST(MeshPredictionSchemeTexCoordsWeightedTest,
     RoundTripsAtHighSpeedsWhateverTheAttributeOrder) {
  const std::vector<std::string> meshes = DracoTestdataTexturedMeshes();
  ASSERT_GE(meshes.size(), 10u);
  for (const std::string &name : meshes) {
    const auto mesh = ReadTestMesh(DracoTestdataPath(name));
    ASSERT_TRUE(mesh.ok()) << name;
    const auto reordered = WithPositionLast(*mesh.value());
    ASSERT_NE(reordered->GetNamedAttributeId(GeometryAttribute::POSITION), 0);
    for (const int cl : {3, 4}) {
      for (const char *scheme : {"weighted", "weighted_multi", "portable"}) {
        ExpectWeightedMatchesStock(*reordered, {11, 10, cl, scheme},
                                   name + " POSITION last " + scheme +
                                       " cl" + std::to_string(cl));
      }
    }
  }
}

TEST(MeshPredictionSchemeTexCoordsWeightedTest, RoundTripsBitExactOnCorpus) {
  const std::vector<std::string> meshes = CorpusMeshPaths();
  if (meshes.empty()) {
    GTEST_SKIP() << "corpus not found at " << CorpusDir();
  }
  for (const std::string &path : meshes) {
    const auto mesh = ReadTestMesh(path);
    ASSERT_TRUE(mesh.ok()) << path;
    for (const int qt : {8, 10, 12, 14}) {
      for (const char *scheme : {"weighted", "weighted_multi"}) {
        ExpectWeightedMatchesStock(*mesh.value(), {14, qt, 10, scheme},
                                   path + " " + scheme + " qt" +
                                       std::to_string(qt));
      }
    }
  }
}

}  // namespace
}  // namespace draco
