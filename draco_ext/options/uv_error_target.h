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
// -uv_rmse R and -uv_texels T: encoding to an error target. Per TEX_COORD
// attribute the encoder picks the smallest coding whose decoded texture
// coordinates have an RMSE (eq. 9 of [Váša & Brunnett 2014], UV units) of
// at most R, among
//  - the lossless schemes (-uv_pred auto's candidates) at every -qt: their
//    error is that of Draco's quantisation grid, known without encoding,
//    so only the smallest -qt whose grid meets R is encoded;
//  - the lossy Laplacian coder (laplacian_mv, default anchors) at every
//    -qt: its error is measured by decoding a trial encode, the -qt that
//    meets R predicted from it assuming RMSE ~ 2^-qt, then stepped by one
//    until the smallest -qt that meets R is found (typically 2-3 trials).
// Where the encoder chooses the scheme (no -uv_pred, or auto), the Laplacian
// is tried only if decoding the whole mesh with it is estimated to cost at
// most options.DecodeLimit() times decoding the stock-coded file
// (EstimateUvLaplacianDecode()); the summary line gives the estimate and
// the decision.
// The target replaces -qt for TEX_COORD attributes. Weak spots: the
// Laplacian's RMSE is assumed to fall with -qt (it does on the corpus);
// other anchor counts are not searched; builds without Draco's decoder
// (the WebAssembly encoder) cannot measure the Laplacian and search the
// lossless schemes only.
#ifndef DRACO_EXT_OPTIONS_UV_ERROR_TARGET_H_
#define DRACO_EXT_OPTIONS_UV_ERROR_TARGET_H_

#include <string>

#include "draco/attributes/point_attribute.h"
#include "draco/compression/expert_encode.h"
#include "draco/core/status_or.h"
#include "draco/mesh/mesh.h"
#include "draco_ext/options/uv_compression_options.h"
#include "prediction_schemes/laplacian/uv_laplacian_settings.h"

namespace draco {

// Eq. (9) for a lossless coding of the float attribute |att| of |mesh| with
// |quantization_bits|: the RMSE over the points of |mesh|'s faces between
// each value and its dequantised one, in the float arithmetic of Draco's
// AttributeQuantizationTransform and Dequantizer, so it is exactly the
// error a decoder reproduces. Fails for non-float attributes and
// non-finite values.
StatusOr<double> QuantizationRmse(const Mesh &mesh, const PointAttribute &att,
                                  int quantization_bits);

// The smallest quantization bits (1 to |max_bits|) whose QuantizationRmse()
// is at most |max_rmse|, or -1 when none is.
StatusOr<int> SmallestQuantizationBitsFor(const Mesh &mesh,
                                          const PointAttribute &att,
                                          double max_rmse, int max_bits);

// What decoding a Laplacian coding of a TEX_COORD attribute costs.
struct UvLaplacianDecodeEstimate {
  UvLaplacianDecodeWork work;
  // Whole-mesh decode of the file with the Laplacian coding, in multiples
  // of the stock-coded file's.
  double ratio = 0;
};

// The decode cost of coding TEX_COORD attribute |att_id| of |mesh| with
// the Laplacian coder, estimated without encoding: the decoder's factor
// (ComputeUvLaplacianDecodeWork() on the attribute's texture connectivity)
// and a linear model of decoding instructions fitted on the corpus
// (benchmarks/laplacian.md, "Decode cost of the error target's choice"):
// the stock-coded file's from the faces and attribute values, the
// Laplacian's extra from the factor's flops and entries and the texture
// vertices. Weak where: other texture coordinate sets coded with the
// Laplacian add their own cost, which this per-attribute ratio leaves out;
// the model counts instructions of a native x86-64 build, and WebAssembly
// decodes the factorisation's dense kernels relatively slower; the
// decoder numbers the texture vertices in Edgebreaker's order, which may
// order the factor a little differently. Fails in builds without the
// Laplacian coder or Draco's decoder, and when the decoder would refuse
// the system.
StatusOr<UvLaplacianDecodeEstimate> EstimateUvLaplacianDecode(const Mesh &mesh,
                                                              int att_id);

// Configures TEX_COORD attribute |att_id| of |mesh| on |encoder| for the
// error target options.MaxUvRmse(): quantization bits, prediction scheme
// and Laplacian settings. options.prediction kDraco or kAuto search all
// codings; a lossless name searches only its -qt, a Laplacian name its -qt
// with options.anchors. |encoder|'s other options (-cl, -qp, seams) must be
// set. Fails when no candidate meets the target. Returns the summary line.
StatusOr<std::string> ConfigureUvErrorTarget(
    const UvCompressionOptions &options, const Mesh &mesh, int att_id,
    ExpertEncoder *encoder);

}  // namespace draco

#endif  // DRACO_EXT_OPTIONS_UV_ERROR_TARGET_H_
