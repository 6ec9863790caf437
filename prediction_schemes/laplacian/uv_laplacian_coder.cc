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
#include "prediction_schemes/laplacian/uv_laplacian_coder.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "draco/core/varint_decoding.h"
#include "draco/core/varint_encoding.h"
#include "draco_ext/common/uv_residual_coder.h"
#include "prediction_schemes/laplacian/uv_laplacian_decode.h"
#include "prediction_schemes/laplacian/uv_laplacian_system.h"

namespace draco {

namespace {

// Quantised values are kept within this magnitude (far beyond any real
// residual), so that every sum of them fits int64 and every value int32.
constexpr int32_t kMaxQuantizedMagnitude = int32_t{1} << 26;
// Seed of the random anchor selection (fig. 9 of the paper).
constexpr uint32_t kRandomAnchorSeed = 0x5eed1e55;

double StepSize(int step_bits, int frame_bits) {
  return static_cast<double>((uint64_t{1} << frame_bits) - 1) /
         static_cast<double>((uint64_t{1} << step_bits) - 1);
}

int32_t Quantize(double value, double step) {
  const double q = std::round(value / step);
  return static_cast<int32_t>(
      std::max<double>(-kMaxQuantizedMagnitude,
                       std::min<double>(kMaxQuantizedMagnitude, q)));
}

// What encoder and decoder derive from the mesh alone, and the texture
// vertex neighbourhoods of the operator's rows.
class LaplacianSetup {
 public:
  explicit LaplacianSetup(UvLaplacianKind kind) : kind_(kind) {}

  // Computes everything below; |graph| and |boundary| come from
  // UvTextureGraph(mesh).
  void Build(const UvLaplacianMesh &mesh, const MatrixGraph &graph,
             std::vector<bool> boundary) {
    charts_ = ComputeUvCharts(mesh, UvMinChartSizeForSecondAnchor(kind_));
    boundary_ = std::move(boundary);
    op_.Build(mesh, graph, kind_);
  }

  UvLaplacianKind kind() const { return kind_; }
  const UvCharts &charts() const { return charts_; }
  const UvLaplacianOperator &op() const { return op_; }
  int num_vertices() const { return op_.num_rows(); }
  int num_boundary_vertices() const {
    return static_cast<int>(
        std::count(boundary_.begin(), boundary_.end(), true));
  }
  bool has_row(int v) const { return !op_.empty_row(v); }
  // Neighbours of v are op().column(i) for begin(v) <= i < end(v) (the
  // first entry of a row is its diagonal).
  int begin(int v) const { return op_.row_start(v) + 1; }
  int end(int v) const { return op_.row_start(v + 1); }
  int neighbour(int i) const { return op_.column(i); }

  // Context of the value of anchor |i| of |anchors| (the chart anchors,
  // then the extra ones): a chart's first anchor jumps from the previous
  // chart, its second one (farthest in 3D) moves across the chart, which on
  // atlases of many small charts is far shorter, and extra anchors jump
  // anywhere. Separate tables make the corpus atlases' streams 1-3% smaller
  // (qt 10, 2% anchors; benchmarks/laplacian.md).
  int AnchorContext(const std::vector<int> &anchors, size_t i) const {
    if (i >= charts_.anchors.size()) {
      return 2;
    }
    const auto &chart_of = charts_.chart_of_vertex;
    return i > 0 && chart_of[anchors[i]] == chart_of[anchors[i - 1]] ? 1 : 0;
  }

  // Context of the residual of (v, c) from data the decoder has when it
  // reaches it: the boundary, and the magnitudes of the residuals of the
  // neighbours before |v| (and of u for v's own v residual).
  int Context(int v, int c, const std::vector<int32_t> &q) const {
    int64_t activity = c == 1 ? 2 * std::abs(int64_t{q[2 * v]}) : 0;
    for (int i = begin(v); i < end(v); ++i) {
      const int w = neighbour(i);
      if (w < v) {
        activity += std::abs(int64_t{q[2 * w + c]});
      }
    }
    const int level = activity == 0 ? 0 : activity <= 2 ? 1 : 2;
    return level + (boundary_[v] ? 3 : 0);
  }

 private:
  UvLaplacianKind kind_;
  UvCharts charts_;
  std::vector<bool> boundary_;
  UvLaplacianOperator op_;
};

// The values the anchors are coded relative to, in the stream's order (the
// chart anchors, then the extra ones): a chart anchor's is the previous
// anchor's value; an extra anchor's the previous extra anchor of its chart,
// else the chart's first anchor. Extra anchors lie inside their chart, closer
// to its anchors than to the previous extra anchor in vertex order, which may
// be in another chart (qt 10, 2 % anchors, mean value: 0.3-0.5 % fewer UV
// bytes on the atlas and conformal meshes; RMSE unchanged).
class AnchorReferences {
 public:
  AnchorReferences(const LaplacianSetup &setup, const std::vector<int> &anchors)
      : setup_(setup),
        anchors_(anchors),
        last_in_chart_(setup.charts().num_charts) {}

  std::array<int64_t, 2> Of(size_t i) const {
    return i < setup_.charts().anchors.size() ? last_
                                              : last_in_chart_[Chart(i)];
  }

  void Record(size_t i, const std::array<int64_t, 2> &value) {
    last_ = value;
    if (setup_.AnchorContext(anchors_, i) != 1) {
      last_in_chart_[Chart(i)] = value;
    }
  }

 private:
  int Chart(size_t i) const {
    return setup_.charts().chart_of_vertex[anchors_[i]];
  }

  const LaplacianSetup &setup_;
  const std::vector<int> &anchors_;
  std::array<int64_t, 2> last_ = {0, 0};
  std::vector<std::array<int64_t, 2>> last_in_chart_;
};

// Quantised residuals (u, v per texture vertex) times the step.
UvValues Dequantize(const std::vector<int32_t> &q, double step) {
  UvValues r(q.size() / 2, 2);
  for (size_t v = 0; v < q.size() / 2; ++v) {
    r(v, 0) = q[2 * v] * step;
    r(v, 1) = q[2 * v + 1] * step;
  }
  return r;
}

UvValues DequantizeAnchors(const std::vector<std::array<int32_t, 2>> &q,
                           double step) {
  UvValues values(q.size(), 2);
  for (size_t i = 0; i < q.size(); ++i) {
    values(i, 0) = q[i][0] * step;
    values(i, 1) = q[i][1] * step;
  }
  return values;
}

// --- Encoder ---------------------------------------------------------------

class LaplacianEncoder {
 public:
  LaplacianEncoder(const UvLaplacianMesh &mesh, const UvValues &uv,
                   const UvLaplacianEncoderOptions &options,
                   UvLaplacianKind kind)
      : mesh_(mesh),
        uv_(uv),
        options_(options),
        step_(StepSize(options.step_bits, options.frame_bits)),
        setup_(kind) {}

  // Encodes into |buffer|; false when the system is singular.
  bool Run(EncoderBuffer *buffer, UvValues *reconstruction) {
    std::vector<bool> boundary;
    const MatrixGraph graph = UvTextureGraph(mesh_, &boundary);
    auto build_operator = [&] {
      setup_.Build(mesh_, graph, std::move(boundary));
      QuantizeResiduals();
      return &setup_.op();
    };
    if (!system_.Analyze(graph,
                         UvLaplacianMaxFactorEntries(mesh_.num_vertices()),
                         build_operator) ||
        !system_.Factorize(setup_.charts().anchors)) {
      return false;
    }
    for (const int a : setup_.charts().anchors) {
      AppendAnchorValue(a);
    }
    residuals_ = Dequantize(q_, step_);
    if (options_.selection == UvAnchorSelection::kGreedy) {
      SelectGreedyAnchors();
    } else {
      SelectRandomAnchors();
    }
    if (reconstruction != nullptr) {
      *reconstruction = Reconstruct();
    }
    return Write(buffer);
  }

 private:
  // r = L u, quantised in texture vertex order; each rounding error is
  // spread over the later neighbours' residuals (error diffusion).
  void QuantizeResiduals() {
    const UvValues r = setup_.op().Apply(uv_);
    const int n = setup_.num_vertices();
    std::vector<double> target(2 * n);
    for (int v = 0; v < n; ++v) {
      for (int c = 0; c < 2; ++c) {
        target[2 * v + c] = r(v, c);
      }
    }
    q_.assign(2 * n, 0);
    std::vector<int> later;
    for (int v = 0; v < n; ++v) {
      if (!setup_.has_row(v)) {
        continue;
      }
      later.clear();
      for (int i = setup_.begin(v); i < setup_.end(v); ++i) {
        const int w = setup_.neighbour(i);
        if (w > v && setup_.has_row(w)) {
          later.push_back(w);
        }
      }
      for (int c = 0; c < 2; ++c) {
        q_[2 * v + c] = Quantize(target[2 * v + c], step_);
        const double error = target[2 * v + c] - q_[2 * v + c] * step_;
        if (options_.error_diffusion && !later.empty()) {
          for (const int w : later) {
            target[2 * w + c] += error / later.size();
          }
        }
      }
    }
  }

  // The extra anchors asked for: K, or the default rule's number for this
  // mesh.
  int NumExtraAnchors() const {
    return options_.extra_anchors == kUvLaplacianDefaultExtraAnchors
               ? UvDefaultExtraAnchors(setup_.num_vertices(),
                                       setup_.num_boundary_vertices())
               : options_.extra_anchors;
  }

  void AppendAnchorValue(int vertex) {
    anchor_q_.push_back({Quantize(uv_(vertex, 0), step_),
                         Quantize(uv_(vertex, 1), step_)});
  }

  UvValues Reconstruct() const {
    return system_.Solve(residuals_, DequantizeAnchors(anchor_q_, step_));
  }

  // [Váša & Brunnett 2014] section 5: anchors where the reconstruction
  // error is largest, several per round (see the file comment).
  void SelectGreedyAnchors() {
    const int n = setup_.num_vertices();
    std::vector<bool> anchored(n, false);
    for (const int a : setup_.charts().anchors) {
      anchored[a] = true;
    }
    int remaining = NumExtraAnchors();
    int round_size = 1;
    std::vector<double> error(n);
    while (remaining > 0) {
      const UvValues x = Reconstruct();
      for (int v = 0; v < n; ++v) {
        error[v] = anchored[v] ? -1.0 : (x.row(v) - uv_.row(v)).squaredNorm();
      }
      const std::vector<int> picked =
          LargestLocalMaxima(error, std::min(round_size, remaining));
      if (picked.empty()) {
        break;
      }
      for (const int v : picked) {
        anchored[v] = true;
        system_.AddAnchor(v);
        extra_anchors_.push_back(v);
        AppendAnchorValue(v);
      }
      remaining -= static_cast<int>(picked.size());
      round_size *= 2;
    }
  }

  // Up to |count| vertices with positive error, largest first, that are
  // maxima of the error over their two-ring.
  std::vector<int> LargestLocalMaxima(const std::vector<double> &error,
                                      int count) const {
    auto above = [&](int a, int b) {
      return error[a] > error[b] || (error[a] == error[b] && a < b);
    };
    std::vector<int> maxima;
    for (int v = 0; v < setup_.num_vertices(); ++v) {
      bool is_maximum = error[v] > 0;
      for (int i = setup_.begin(v); is_maximum && i < setup_.end(v); ++i) {
        const int w = setup_.neighbour(i);
        is_maximum = above(v, w);
        for (int j = setup_.begin(w); is_maximum && j < setup_.end(w); ++j) {
          const int z = setup_.neighbour(j);
          is_maximum = z == v || above(v, z);
        }
      }
      if (is_maximum) {
        maxima.push_back(v);
      }
    }
    const size_t kept = std::min<size_t>(count, maxima.size());
    std::partial_sort(maxima.begin(), maxima.begin() + kept, maxima.end(),
                      above);
    maxima.resize(kept);
    return maxima;
  }

  void SelectRandomAnchors() {
    const int n = setup_.num_vertices();
    std::vector<bool> anchored(n, false);
    for (const int a : setup_.charts().anchors) {
      anchored[a] = true;
    }
    std::vector<int> free;
    for (int v = 0; v < n; ++v) {
      if (!anchored[v]) {
        free.push_back(v);
      }
    }
    std::mt19937 random(kRandomAnchorSeed);
    const int count = std::min<int>(NumExtraAnchors(), free.size());
    for (int i = 0; i < count; ++i) {
      const int pick = i + static_cast<int>(random() % (free.size() - i));
      std::swap(free[i], free[pick]);
      system_.AddAnchor(free[i]);
      extra_anchors_.push_back(free[i]);
      AppendAnchorValue(free[i]);
    }
  }

  bool Write(EncoderBuffer *buffer) const {
    buffer->Encode(static_cast<uint8_t>(setup_.kind()));
    buffer->Encode(static_cast<uint8_t>(options_.step_bits));
    buffer->Encode(static_cast<uint8_t>(options_.frame_bits));
    return WriteAnchors(buffer) && WriteResiduals(buffer);
  }

  bool WriteAnchors(EncoderBuffer *buffer) const {
    // Extra anchors ascending, their values in the same order.
    const size_t num_chart_anchors = setup_.charts().anchors.size();
    std::vector<size_t> order(extra_anchors_.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return extra_anchors_[a] < extra_anchors_[b];
    });
    EncodeVarint(static_cast<uint32_t>(extra_anchors_.size()), buffer);
    int previous = -1;
    std::vector<int> anchors = setup_.charts().anchors;
    std::vector<std::array<int32_t, 2>> values(
        anchor_q_.begin(), anchor_q_.begin() + num_chart_anchors);
    for (const size_t i : order) {
      EncodeVarint(static_cast<uint32_t>(extra_anchors_[i] - previous - 1),
                   buffer);
      previous = extra_anchors_[i];
      anchors.push_back(extra_anchors_[i]);
      values.push_back(anchor_q_[num_chart_anchors + i]);
    }
    UvResidualEncoder coder;
    coder.Reset(static_cast<int>(2 * values.size()));
    AnchorReferences references(setup_, anchors);
    for (size_t i = 0; i < values.size(); ++i) {
      const std::array<int64_t, 2> value = {values[i][0], values[i][1]};
      const std::array<int64_t, 2> reference = references.Of(i);
      for (int c = 0; c < 2; ++c) {
        coder.Add(setup_.AnchorContext(anchors, i),
                  static_cast<int32_t>(value[c] - reference[c]));
      }
      references.Record(i, value);
    }
    return coder.Encode(buffer);
  }

  bool WriteResiduals(EncoderBuffer *buffer) const {
    UvResidualEncoder coder;
    coder.Reset(static_cast<int>(q_.size()));
    for (int v = 0; v < setup_.num_vertices(); ++v) {
      if (setup_.has_row(v)) {
        for (int c = 0; c < 2; ++c) {
          coder.Add(setup_.Context(v, c, q_), q_[2 * v + c]);
        }
      }
    }
    return coder.Encode(buffer);
  }

  const UvLaplacianMesh &mesh_;
  const UvValues &uv_;
  const UvLaplacianEncoderOptions &options_;
  const double step_;
  LaplacianSetup setup_;
  std::vector<int32_t> q_;
  UvValues residuals_;
  std::vector<std::array<int32_t, 2>> anchor_q_;  // Chart anchors, then extra.
  std::vector<int> extra_anchors_;
  UvLaplacianSystem system_;
};

// --- Decoder ---------------------------------------------------------------

bool DecodeHeader(DecoderBuffer *buffer, UvLaplacianKind *kind, double *step,
                  int *frame) {
  uint8_t kind_byte, step_bits, frame_bits;
  if (!buffer->Decode(&kind_byte) || !buffer->Decode(&step_bits) ||
      !buffer->Decode(&frame_bits) || kind_byte >= kNumUvLaplacianKinds ||
      step_bits < 1 || step_bits > kUvLaplacianMaxStepBits ||
      frame_bits < step_bits || frame_bits > kUvLaplacianMaxFrameBits) {
    return false;
  }
  *kind = static_cast<UvLaplacianKind>(kind_byte);
  *step = StepSize(step_bits, frame_bits);
  *frame = frame_bits;
  return true;
}

// Extra anchors (ascending, distinct, no chart anchor) appended to
// |anchors|, and the values of all anchors.
bool DecodeAnchors(const LaplacianSetup &setup, DecoderBuffer *buffer,
                   std::vector<int> *anchors,
                   std::vector<std::array<int32_t, 2>> *values) {
  const int num_vertices = setup.num_vertices();
  std::vector<bool> anchored(num_vertices, false);
  for (const int a : *anchors) {
    anchored[a] = true;
  }
  uint32_t count;
  if (!DecodeVarint(&count, buffer) ||
      count > static_cast<uint32_t>(num_vertices)) {
    return false;
  }
  int64_t previous = -1;
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t delta;
    if (!DecodeVarint(&delta, buffer)) {
      return false;
    }
    const int64_t vertex = previous + 1 + delta;
    if (vertex >= num_vertices || anchored[vertex]) {
      return false;
    }
    anchored[vertex] = true;
    anchors->push_back(static_cast<int>(vertex));
    previous = vertex;
  }
  UvResidualDecoder coder;
  if (!coder.Decode(static_cast<int>(2 * anchors->size()), buffer)) {
    return false;
  }
  AnchorReferences references(setup, *anchors);
  for (size_t i = 0; i < anchors->size(); ++i) {
    std::array<int64_t, 2> value = references.Of(i);
    for (int c = 0; c < 2; ++c) {
      int32_t delta;
      if (!coder.Next(setup.AnchorContext(*anchors, i), &delta)) {
        return false;
      }
      value[c] += delta;
      if (std::abs(value[c]) > kMaxQuantizedMagnitude) {
        return false;
      }
    }
    references.Record(i, value);
    values->push_back(
        {static_cast<int32_t>(value[0]), static_cast<int32_t>(value[1])});
  }
  return true;
}

bool DecodeResiduals(const LaplacianSetup &setup, DecoderBuffer *buffer,
                     std::vector<int32_t> *q) {
  const int n = setup.num_vertices();
  int count = 0;
  for (int v = 0; v < n; ++v) {
    count += setup.has_row(v) ? 2 : 0;
  }
  UvResidualDecoder coder;
  if (!coder.Decode(count, buffer)) {
    return false;
  }
  q->assign(2 * n, 0);
  for (int v = 0; v < n; ++v) {
    if (!setup.has_row(v)) {
      continue;
    }
    for (int c = 0; c < 2; ++c) {
      int32_t value;
      if (!coder.Next(setup.Context(v, c, *q), &value) ||
          std::abs(int64_t{value}) > kMaxQuantizedMagnitude) {
        return false;
      }
      (*q)[2 * v + c] = value;
    }
  }
  return true;
}

}  // namespace

int64_t UvLaplacianMaxFactorEntries(int num_vertices) {
  constexpr int64_t kEntriesPerVertex = 1024;
  constexpr int64_t kMinEntries = int64_t{1} << 20;
  constexpr int64_t kMaxEntries = int64_t{1} << 28;
  return std::min(kMaxEntries,
                  kMinEntries + kEntriesPerVertex * std::max(0, num_vertices));
}

bool ComputeUvLaplacianDecodeWork(const UvLaplacianMesh &mesh,
                                  UvLaplacianDecodeWork *work) {
  work->num_vertices = mesh.num_vertices();
  return UvLaplacianSystem::FactorWork(
      UvTextureGraph(mesh), UvLaplacianMaxFactorEntries(mesh.num_vertices()),
      &work->factor_entries, &work->factor_flops);
}

bool EncodeUvLaplacian(const UvLaplacianMesh &mesh, const UvValues &uv,
                       const UvLaplacianEncoderOptions &options,
                       EncoderBuffer *buffer, UvValues *reconstruction) {
  if (uv.rows() != mesh.num_vertices() || options.step_bits < 1 ||
      options.step_bits > kUvLaplacianMaxStepBits ||
      options.frame_bits < options.step_bits ||
      options.frame_bits > kUvLaplacianMaxFrameBits ||
      (options.extra_anchors < 0 &&
       options.extra_anchors != kUvLaplacianDefaultExtraAnchors)) {
    return false;
  }
  std::vector<UvLaplacianKind> kinds = {options.kind};
  if (options.kind != UvLaplacianKind::kTutte) {
    kinds.push_back(UvLaplacianKind::kTutte);
  }
  for (const UvLaplacianKind kind : kinds) {
    LaplacianEncoder encoder(mesh, uv, options, kind);
    EncoderBuffer attempt;
    if (encoder.Run(&attempt, reconstruction)) {
      buffer->Encode(attempt.data(), attempt.size());
      return true;
    }
  }
  return false;
}

bool DecodeUvLaplacian(const UvLaplacianMesh &mesh, DecoderBuffer *buffer,
                       UvValues *uv, int *frame_bits) {
  const int n = mesh.num_vertices();
  UvLaplacianKind kind;
  double step;
  if (!DecodeHeader(buffer, &kind, &step, frame_bits)) {
    return false;
  }
  std::vector<bool> boundary;
  const MatrixGraph graph = UvTextureGraph(mesh, &boundary);
  LaplacianSetup setup(kind);
  auto build_operator = [&] {
    setup.Build(mesh, graph, std::move(boundary));
    return &setup.op();
  };
  UvLaplacianSystem system;
  system.set_dense_kernels(DenseKernels::kFastestHere);
  if (!system.Analyze(graph, UvLaplacianMaxFactorEntries(n), build_operator)) {
    return false;
  }
  std::vector<int> anchors = setup.charts().anchors;
  std::vector<std::array<int32_t, 2>> anchor_q;
  std::vector<int32_t> q;
  if (!DecodeAnchors(setup, buffer, &anchors, &anchor_q) ||
      !DecodeResiduals(setup, buffer, &q) || !system.Factorize(anchors)) {
    return false;
  }
  *uv = system.Solve(Dequantize(q, step), DequantizeAnchors(anchor_q, step));
  return uv->allFinite();
}

bool DecodeUvLaplacianValues(const UvLaplacianMesh &mesh, const char *data,
                             size_t size, uint16_t bitstream_version,
                             std::vector<double> *uv, int *frame_bits) {
  DecoderBuffer buffer;
  buffer.Init(data, size, bitstream_version);
  UvValues values;
  if (!DecodeUvLaplacian(mesh, &buffer, &values, frame_bits)) {
    return false;
  }
  uv->resize(2 * static_cast<size_t>(values.rows()));
  for (int row = 0; row < values.rows(); ++row) {
    (*uv)[2 * row] = values(row, 0);
    (*uv)[2 * row + 1] = values(row, 1);
  }
  return true;
}

}  // namespace draco
