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
// Mesh Laplacians over the texture connectivity, with weights from the 3D
// geometry, for the Laplacian texture coordinate coder of
//   [Váša & Brunnett 2014] L. Váša, G. Brunnett: Efficient encoding of
//     texture coordinates guided by mesh geometry. CGF 33(5), section 5.
// Weights (eq. 6-8):
//   Tutte       w_ij = 1                                         (eq. 6)
//   cotangent   w_ij = cot(gamma) + cot(theta)           [Pinkall & Polthier
//               1993], the angles opposite edge ij                (eq. 8)
//   mean value  w_ij = (tan(alpha / 2) + tan(beta / 2)) / |p_i - p_j|
//               [Floater 2003], the angles at p_i next to edge ij (eq. 8)
// Every row is scaled so that its diagonal is -1 (section 5): the row applied
// to the texture coordinates is the prediction residual "weighted mean of the
// neighbours minus the vertex" (eq. 7), in texture coordinate units.
#ifndef PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_OPERATOR_H_
#define PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_OPERATOR_H_

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "draco_ext/linalg/matrix_graph.h"
#include "prediction_schemes/laplacian/uv_laplacian_mesh.h"
#include "prediction_schemes/laplacian/uv_laplacian_settings.h"

namespace draco {

// Texture coordinates of all texture vertices (u, v per row), in the units
// the coder quantises.
typedef Eigen::Matrix<double, Eigen::Dynamic, 2> UvValues;

// The connected components of the texture connectivity ("charts") and their
// anchors. One anchor per chart makes the system regular (the Laplacian of
// a chart vanishes on constants only); a second one, as far from the first
// as possible, pins the chart's scale and rotation, which otherwise drift
// with the accumulated quantisation error of the boundary rows (on the
// corpus atlases 20-40% lower RMSE for about 1.5% more bits). Small charts
// drift little when all weights are positive, and on atlases of many small
// charts the second anchors are a large share of the bits
// (UvMinChartSizeForSecondAnchor()).
struct UvCharts {
  std::vector<int> chart_of_vertex;
  // Per chart its smallest texture vertex and, if the chart has at least
  // the minimum size given to ComputeUvCharts(), the vertex farthest from it
  // in 3D.
  std::vector<int> anchors;
  int num_charts = 0;
};

// Charts of fewer texture vertices than this get one anchor only: 16 for
// the Tutte and mean-value weights, which are positive (about 4% fewer bits
// at the same RMSE on the corpus atlases, benchmarks/laplacian.md); every
// chart of two or more vertices for the cotangent weights, whose negative
// weights (obtuse triangles) leave a small chart's scale and rotation
// nearly free.
int UvMinChartSizeForSecondAnchor(UvLaplacianKind kind);

// The texture one-ring graph: the neighbours of every texture vertex across
// its faces' edges, sorted, without duplicates or the vertex itself. It is
// the pattern of every operator of the mesh (UvLaplacianOperator::Build())
// without the diagonal, and, needing no 3D geometry, the first thing
// encoder and decoder compute, so that the unknowns can be ordered while
// the weights are computed (UvLaplacianSystem::Analyze()). |boundary|, if
// not null, receives the texture vertices on the boundary of the texture
// connectivity: those with an edge that is not shared by exactly two faces
// with distinct corners (counted while the neighbour lists are compacted).
MatrixGraph UvTextureGraph(const UvLaplacianMesh &mesh,
                           std::vector<bool> *boundary = nullptr);

UvCharts ComputeUvCharts(const UvLaplacianMesh &mesh,
                         int min_size_for_second_anchor);

// The sparse operator L, one row per texture vertex, compressed by row; it
// applies to the u and the v column alike. Rows of vertices without
// neighbours are empty.
class UvLaplacianOperator {
 public:
  // Row i has the diagonal, then the neighbours of i in |graph|, which must
  // be UvTextureGraph(mesh).
  void Build(const UvLaplacianMesh &mesh, const MatrixGraph &graph,
             UvLaplacianKind kind);

  int num_rows() const { return static_cast<int>(row_start_.size()) - 1; }

  int row_start(int row) const { return row_start_[row]; }
  int column(int entry) const { return column_[entry]; }
  double value(int entry) const { return value_[entry]; }
  bool empty_row(int row) const {
    return row_start_[row] == row_start_[row + 1];
  }
  // Rows whose weights were unusable (degenerate triangles, a weight sum
  // that is not clearly positive) and fell back to Tutte weights.
  int num_fallback_rows() const { return num_fallback_rows_; }

  // L x.
  UvValues Apply(const UvValues &x) const;
  // L^T r.
  UvValues ApplyTransposed(const UvValues &r) const;

 private:
  int num_fallback_rows_ = 0;
  std::vector<int> row_start_;
  std::vector<int> column_;
  std::vector<double> value_;
};

}  // namespace draco

#endif  // PREDICTION_SCHEMES_LAPLACIAN_UV_LAPLACIAN_OPERATOR_H_
