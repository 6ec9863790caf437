// tanlab: how predictable are glTF TANGENTs from what a Draco decoder has?
// Research prototype (doubles, not bit-exact) behind the geometric tangent
// scheme (README.md here): loads glTF/GLB meshes with Draco's reader,
// quantises positions (14 bits), UVs (12), octahedral normals (10) and
// tangents (8, 12) as Draco does, recomputes the tangents from the quantised
// inputs with several conventions and estimates the order-0 entropy of
// several residual codings.
//
// Environment: TANLAB_FLOAT=p,u,n (any of them) uses the float positions,
// UVs or normals instead of the quantised ones (which input's quantisation
// costs what); TANLAB_SIGMAM, TANLAB_ALPHA, TANLAB_GAUSS3 tune the Gaussian
// sequential coding; TANLAB_DETAIL prints per-component entropies.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "draco/attributes/attribute_octahedron_transform.h"
#include "draco/attributes/attribute_quantization_transform.h"
#include "draco/io/mesh_io.h"
#include "draco/mesh/mesh.h"

using V3 = std::array<double, 3>;
static V3 Sub(V3 a, V3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
static V3 Add(V3 a, V3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
static V3 Mul(V3 a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
static double Dot(V3 a, V3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static V3 Cross(V3 a, V3 b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
          a[0] * b[1] - a[1] * b[0]};
}
static double Len(V3 a) { return std::sqrt(Dot(a, a)); }
static V3 Norm(V3 a) {
  const double l = Len(a);
  return l > 0 ? Mul(a, 1 / l) : V3{0, 0, 0};
}
static V3 Proj(V3 v, V3 n) { return Sub(v, Mul(n, Dot(v, n))); }

static double gAlpha = 1.0, gSigmaM = 0.0;
static bool gUseLength = true;
struct Hist {
  std::map<long, long> h;
  long n = 0;
  void Add(long v) { ++h[v]; ++n; }
  double Bits() const {
    double b = 0;
    for (auto &kv : h) b -= kv.second * std::log2(double(kv.second) / n);
    return b;
  }
};

struct Portable {
  std::vector<std::array<int32_t, 4>> v;  // Per point.
  int nc = 0;
};

static Portable Quantize(const draco::PointAttribute &att, int bits,
                         int num_points, draco::AttributeQuantizationTransform *t) {
  t->ComputeParameters(att, bits);
  std::vector<draco::PointIndex> ids;
  for (int i = 0; i < num_points; ++i) ids.push_back(draco::PointIndex(i));
  auto port = t->InitTransformedAttribute(att, num_points);
  t->TransformAttribute(att, ids, port.get());
  Portable p;
  p.nc = att.num_components();
  p.v.resize(num_points);
  for (int i = 0; i < num_points; ++i) {
    std::array<int32_t, 4> x{};
    port->GetValue(draco::AttributeValueIndex(i), x.data());
    p.v[i] = x;
  }
  return p;
}

static Portable Octahedral(const draco::PointAttribute &att, int bits,
                           int num_points) {
  draco::AttributeOctahedronTransform t;
  t.SetParameters(bits);
  std::vector<draco::PointIndex> ids;
  for (int i = 0; i < num_points; ++i) ids.push_back(draco::PointIndex(i));
  auto port = t.InitTransformedAttribute(att, num_points);
  t.TransformAttribute(att, ids, port.get());
  Portable p;
  p.nc = 2;
  p.v.resize(num_points);
  for (int i = 0; i < num_points; ++i) {
    std::array<int32_t, 4> x{};
    port->GetValue(draco::AttributeValueIndex(i), x.data());
    p.v[i] = x;
  }
  return p;
}

// Draco's octahedral decoding in integers (scaled by max_value), normalised.
static V3 OctToVec(int s, int t, int bits) {
  const long max_value = (1L << bits) - 2;
  long y = 2 * s - max_value, z = 2 * t - max_value;
  long x = max_value - std::labs(y) - std::labs(z);
  long off = x < 0 ? -x : 0;
  y += y < 0 ? off : -off;
  z += z < 0 ? off : -off;
  return Norm(V3{double(x), double(y), double(z)});
}

enum Mode { kMikk, kLengyel, kArea, kUniform, kFace, kFaceRaw, kPosNor, kPos, kFaceUnproj, kNumModes };
static const char *kModeNames[] = {"mikk", "lengyel", "area", "uniform", "face", "faceraw", "posnor", "pos", "faceunproj"};

struct Result {
  std::vector<V3> t;     // Per point.
  std::vector<int> w;    // Per point, +1/-1.
  std::vector<double> e; // Per point: estimated direction error (radians).
  std::vector<V3> m;     // Per point: normal of the plane the tangent is in.
};

static std::vector<V3> *gFloatP = nullptr;
static std::vector<std::array<double, 2>> *gFloatUV = nullptr;
static Result Predict(const draco::Mesh &mesh, const Portable &P,
                      const Portable &UV, const std::vector<V3> &N, Mode mode) {
  const int np = mesh.num_points();
  // Group key: (position, normal, uv) portable values.
  std::map<std::array<int32_t, 8>, int> key_of;
  std::vector<int> group(np);
  auto key = [&](int p) {
    std::array<int32_t, 8> k{P.v[p][0], P.v[p][1], P.v[p][2], 0, 0,
                             UV.v[p][0], UV.v[p][1], 0};
    // Normal by its vector bits (quantised ints would be better; fine here).
    k[3] = int32_t(std::lround(N[p][0] * 1e6));
    k[4] = int32_t(std::lround(N[p][1] * 1e6));
    k[7] = int32_t(std::lround(N[p][2] * 1e6));
    return k;
  };
  for (int p = 0; p < np; ++p) {
    if (mode == kFace || mode == kFaceRaw || mode == kFaceUnproj) { group[p] = key_of.size(); key_of[{p,-1,-1,-1,-1,-1,-1,-1}] = p; continue; }
    auto k = key(p);
    if (mode >= kPosNor) { k[5] = k[6] = 0; }
    if (mode == kPos) { k[3] = k[4] = k[7] = 0; }
    auto it = key_of.find(k);
    if (it == key_of.end()) it = key_of.emplace(k, int(key_of.size())).first;
    group[p] = it->second;
  }
  const int ng = key_of.size();
  std::vector<V3> acc[2], fn[2];
  std::vector<double> wsum[2], e2sum[2];
  for (int o = 0; o < 2; ++o) {
    acc[o].assign(ng, V3{0, 0, 0});
    fn[o].assign(ng, V3{0, 0, 0});
    wsum[o].assign(ng, 0);
    e2sum[o].assign(ng, 0);
  }
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    const auto &face = mesh.face(f);
    int p[3] = {int(face[0].value()), int(face[1].value()),
                int(face[2].value())};
    V3 x[3];
    double u[3], v[3];
    for (int i = 0; i < 3; ++i) {
      x[i] = {double(P.v[p[i]][0]), double(P.v[p[i]][1]), double(P.v[p[i]][2])};
      u[i] = UV.v[p[i]][0];
      v[i] = UV.v[p[i]][1];
      if (gFloatP) x[i] = (*gFloatP)[p[i]];
      if (gFloatUV) { u[i] = (*gFloatUV)[p[i]][0]; v[i] = (*gFloatUV)[p[i]][1]; }
    }
    const V3 e1 = Sub(x[1], x[0]), e2 = Sub(x[2], x[0]);
    if (Len(Cross(e1, e2)) == 0) continue;
    const double du1 = u[1] - u[0], dv1 = v[1] - v[0];
    const double du2 = u[2] - u[0], dv2 = v[2] - v[0];
    const double area2 = du1 * dv2 - du2 * dv1;
    if (area2 == 0) continue;
    const int orient = area2 > 0 ? 1 : 0;
    V3 os = Sub(Mul(e1, dv2), Mul(e2, dv1));
    if (area2 < 0) os = Mul(os, -1);
    const V3 grad = Mul(os, 1 / std::fabs(area2));  // dP/du.
    const double area3 = Len(Cross(e1, e2));
    double luv = 0, l3 = 0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      luv = std::max(luv, std::hypot(u[j] - u[i], v[j] - v[i]));
      l3 = std::max(l3, Len(Sub(x[j], x[i])));
    }
    const double eps2 = std::pow(luv / std::fabs(area2), 2) + std::pow(l3 / area3, 2);
    const V3 fnorm = Cross(e1, e2);
    for (int i = 0; i < 3; ++i) {
      const V3 n = N[p[i]];
      V3 contrib;
      double weight = 1;
      if (mode == kFaceUnproj) {
        contrib = Norm(os);
      } else if (mode == kLengyel || mode == kFaceRaw) {
        contrib = grad;
      } else {
        contrib = Norm(Proj(os, n));
        if (mode == kMikk) {
          const V3 a = Norm(Proj(Sub(x[(i + 1) % 3], x[i]), n));
          const V3 b = Norm(Proj(Sub(x[(i + 2) % 3], x[i]), n));
          weight = std::acos(std::clamp(Dot(a, b), -1.0, 1.0));
        } else if (mode == kArea) {
          weight = area3;
        }
      }
      const int g = group[p[i]];
      acc[orient][g] = Add(acc[orient][g], Mul(contrib, weight));
      wsum[orient][g] += weight;
      e2sum[orient][g] += weight * weight * eps2;
      fn[orient][g] = Add(fn[orient][g], fnorm);
    }
  }
  Result r;
  r.t.resize(np);
  r.w.resize(np);
  r.e.resize(np);
  r.m.resize(np);
  for (int pt = 0; pt < np; ++pt) {
    const int g = group[pt];
    const int o = wsum[1][g] > wsum[0][g] ? 1 : 0;
    r.t[pt] = mode == kFaceUnproj ? Norm(acc[o][g]) : Norm(Proj(acc[o][g], N[pt]));
    r.w[pt] = o ? 1 : -1;
    r.e[pt] = wsum[o][g] > 0 ? std::sqrt(e2sum[o][g]) / wsum[o][g] : 1.0;
    r.m[pt] = mode == kFaceUnproj ? Norm(fn[o][g]) : N[pt];
  }
  return r;
}

// Codings of the quantised tangent given the prediction.
struct Coding {
  Hist comp[3], w;
  Hist seq[3];    // Sequential constraint coding.
  Hist angle, rest[3];
  Hist gauss[3];
  std::map<int, Hist> gctx[3];
  long exact = 0, n = 0;
  std::vector<double> angle_err;
};

static double gAlphaDummy;
static void Evaluate(const Portable &Q, const draco::AttributeQuantizationTransform &qt,
                     int bits, const std::vector<V3> &N, const Result &r,
                     int w_flip, Coding *c, const std::vector<int> &reps,
                     const std::vector<std::array<float, 4>> &orig) {
  const double maxq = (1 << bits) - 1;
  const double s = maxq / qt.range();
  double o[4];
  for (int i = 0; i < 4; ++i) o[i] = -qt.min_value(i) * s;
  auto clampq = [&](double g) {
    long q = std::lround(g);
    return std::clamp<long>(q, 0, long(maxq));
  };
  for (int p : reps) {
    const V3 T = r.t[p];
    const V3 n = N[p];
    long q[4] = {Q.v[p][0], Q.v[p][1], Q.v[p][2], Q.v[p][3]};
    ++c->n;
    // Angle error vs the original float tangent.
    V3 to = {orig[p][0], orig[p][1], orig[p][2]};
    c->angle_err.push_back(std::acos(std::clamp(Dot(Norm(to), T), -1.0, 1.0)) *
                           180 / M_PI);
    // Independent components.
    bool ex = true;
    for (int i = 0; i < 3; ++i) {
      long rr = q[i] - clampq(o[i] + s * T[i]);
      c->comp[i].Add(rr);
      ex = ex && rr == 0;
    }
    const int wp = r.w[p] * w_flip;
    const long qw = clampq(o[3] + s * wp);
    c->w.Add(q[3] == qw ? 0 : 1);
    if (ex) ++c->exact;
    // Sequential: a3 = largest |T|, a1 = larger |B| of the rest.
    const V3 B = Cross(n, T);
    int a3 = 0;
    for (int i = 1; i < 3; ++i)
      if (std::fabs(T[i]) > std::fabs(T[a3])) a3 = i;
    int a1 = (a3 + 1) % 3, a2 = (a3 + 2) % 3;
    if (std::fabs(B[a2]) > std::fabs(B[a1])) std::swap(a1, a2);
    long r1 = q[a1] - clampq(o[a1] + s * T[a1]);
    c->seq[0].Add(r1);
    const double x1 = (q[a1] - o[a1]) / s;
    // Point on the circle {cos T + sin B} with component a1 = x1, nearest T.
    const double a = T[a1], b = B[a1];
    const double R2 = a * a + b * b;
    double uu = 1, vv = 0;
    if (R2 > 1e-12) {
      double xr = std::clamp(x1 / std::sqrt(R2), -1.0, 1.0);
      const double R = std::sqrt(R2);
      const double h = std::sqrt(std::max(0.0, 1 - xr * xr));
      // (u, v) = xr (a, b)/R + h (-b, a)/R or minus: pick larger u.
      const double u1 = xr * a / R - h * b / R, v1 = xr * b / R + h * a / R;
      const double u2 = xr * a / R + h * b / R, v2 = xr * b / R - h * a / R;
      if (u1 >= u2) { uu = u1; vv = v1; } else { uu = u2; vv = v2; }
    }
    const V3 T2 = Add(Mul(T, uu), Mul(B, vv));
    long r2 = q[a2] - clampq(o[a2] + s * T2[a2]);
    c->seq[1].Add(r2);
    const double x2 = (q[a2] - o[a2]) / s;
    const double x3 = std::copysign(std::sqrt(std::max(0.0, 1 - x1 * x1 - x2 * x2)),
                                    T2[a3]);
    long r3 = q[a3] - clampq(o[a3] + s * x3);
    c->seq[2].Add(r3);
    // Gaussian sequential coding in the frame (T, B, M).
    {
      const V3 M = r.m[p];
      const V3 Bm = Norm(Cross(M, T));
      const double sb = std::max(gAlpha * r.e[p] * s, 0.25), sm = gSigmaM * s,
                   st = 0.05;
      double S[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          S[i][j] = sb * sb * Bm[i] * Bm[j] + sm * sm * M[i] * M[j] +
                    st * st * T[i] * T[j] + (i == j ? 1.0 / 12 : 0.0);
      int b3 = 0;
      for (int i = 1; i < 3; ++i)
        if (std::fabs(T[i]) > std::fabs(T[b3])) b3 = i;
      int b1 = (b3 + 1) % 3, b2 = (b3 + 2) % 3;
      if (std::fabs(Bm[b2]) > std::fabs(Bm[b1])) std::swap(b1, b2);
      double g[3];
      for (int i = 0; i < 3; ++i) g[i] = o[i] + s * T[i];
      // 1st.
      long e1 = q[b1] - clampq(g[b1]);
      const double d1 = q[b1] - g[b1];
      const double c1 = std::sqrt(S[b1][b1]);
      // 2nd given 1st.
      const double g2 = g[b2] + S[b2][b1] / S[b1][b1] * d1;
      const double v2 = S[b2][b2] - S[b2][b1] * S[b2][b1] / S[b1][b1];
      long e2 = q[b2] - clampq(g2);
      const double d2 = q[b2] - g2;
      // 3rd: length constraint with the sign of the prediction.
      const double x1 = (q[b1] - o[b1]) / s, x2 = (q[b2] - o[b2]) / s;
      double g3;
      if (gUseLength) {
        g3 = o[b3] + s * std::copysign(std::sqrt(std::max(0.0, 1 - x1 * x1 - x2 * x2)), T[b3]);
      } else {
        // Gaussian conditioning on both.
        const double a11 = S[b1][b1], a12 = S[b1][b2], a22 = S[b2][b2];
        const double det = a11 * a22 - a12 * a12;
        const double w1 = (S[b3][b1] * a22 - S[b3][b2] * a12) / det;
        const double w2 = (S[b3][b2] * a11 - S[b3][b1] * a12) / det;
        g3 = g[b3] + w1 * (q[b1] - g[b1]) + w2 * (q[b2] - g[b2]);
      }
      long e3 = q[b3] - clampq(g3);
      (void)d2;
      c->gauss[0].Add(e1);
      c->gauss[1].Add(e2);
      c->gauss[2].Add(e3);
      auto bucket = [](double sd) { return std::clamp(int(std::floor(2 * std::log2(sd + 1e-9))) + 4, 0, 20); };
      c->gctx[0][bucket(c1)].Add(e1);
      c->gctx[1][bucket(std::sqrt(std::max(v2, 1e-9)))].Add(e2);
      c->gctx[2][0].Add(e3);
    }
    // Angle index + rest.
    V3 tq = {(q[0] - o[0]) / s, (q[1] - o[1]) / s, (q[2] - o[2]) / s};
    const double th = std::atan2(Dot(tq, B), Dot(tq, T));
    const long k = std::lround(th * s);
    c->angle.Add(k);
    const double thk = k / s;
    const V3 Tk = Add(Mul(T, std::cos(thk)), Mul(B, std::sin(thk)));
    for (int i = 0; i < 3; ++i) c->rest[i].Add(q[i] - clampq(o[i] + s * Tk[i]));
  }
}

static double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
static double Pct(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(p * v.size()))];
}

int main(int argc, char **argv) {
  if (getenv("TANLAB_ALPHA")) gAlpha = atof(getenv("TANLAB_ALPHA"));
  if (getenv("TANLAB_SIGMAM")) gSigmaM = atof(getenv("TANLAB_SIGMAM"));
  if (getenv("TANLAB_GAUSS3")) gUseLength = false;
  printf("asset\tbits\tmode\tvalues\tmed_deg\tp90_deg\tindep_bpv\tw_bpv\tseq_bpv\tangle_bpv\texact\tgauss_bpv\tgctx_bpv\n");
  for (int ai = 1; ai < argc; ++ai) {
    auto mr = draco::ReadMeshFromFile(argv[ai]);
    if (!mr.ok()) {
      fprintf(stderr, "%s: %s\n", argv[ai], mr.status().error_msg());
      continue;
    }
    auto mesh = std::move(mr).value();
    const auto *pos = mesh->GetNamedAttribute(draco::GeometryAttribute::POSITION);
    const auto *nor = mesh->GetNamedAttribute(draco::GeometryAttribute::NORMAL);
    const auto *tex = mesh->GetNamedAttribute(draco::GeometryAttribute::TEX_COORD);
    const auto *tan = mesh->GetNamedAttribute(draco::GeometryAttribute::TANGENT);
    if (!pos || !nor || !tex || !tan) {
      fprintf(stderr, "%s: missing attribute\n", argv[ai]);
      continue;
    }
    const int np = mesh->num_points();
    draco::AttributeQuantizationTransform pt, ut;
    Portable P = Quantize(*pos, 14, np, &pt);
    Portable UV = Quantize(*tex, 12, np, &ut);
    Portable ON = Octahedral(*nor, 10, np);
    std::vector<V3> N(np);
    for (int p = 0; p < np; ++p) N[p] = OctToVec(ON.v[p][0], ON.v[p][1], 10);
    const char *fl = getenv("TANLAB_FLOAT");
    std::string fls = fl ? fl : "";
    std::vector<V3> fp(np);
    std::vector<std::array<double, 2>> fu(np);
    for (int p = 0; p < np; ++p) {
      float a[4];
      pos->GetMappedValue(draco::PointIndex(p), a);
      fp[p] = {a[0] * 16383.0 / pt.range(), a[1] * 16383.0 / pt.range(), a[2] * 16383.0 / pt.range()};
      tex->GetMappedValue(draco::PointIndex(p), a);
      fu[p] = {a[0] * 4095.0 / ut.range(), a[1] * 4095.0 / ut.range()};
      if (fls.find('n') != std::string::npos) {
        nor->GetMappedValue(draco::PointIndex(p), a);
        N[p] = Norm(V3{a[0], a[1], a[2]});
      }
    }
    gFloatP = fls.find('p') != std::string::npos ? &fp : nullptr;
    gFloatUV = fls.find('u') != std::string::npos ? &fu : nullptr;
    std::vector<std::array<float, 4>> orig(np);
    for (int p = 0; p < np; ++p)
      tan->GetMappedValue(draco::PointIndex(p), orig[p].data());
    // One representative point per tangent value with distinct pos/nor/uv.
    std::map<std::array<int32_t, 8>, int> seen;
    std::vector<int> reps;
    for (int p = 0; p < np; ++p) {
      std::array<int32_t, 8> k{P.v[p][0], P.v[p][1], P.v[p][2], ON.v[p][0],
                               ON.v[p][1], UV.v[p][0], UV.v[p][1],
                               int32_t(tan->mapped_index(draco::PointIndex(p)).value())};
      if (seen.emplace(k, p).second) reps.push_back(p);
    }
    {
      std::vector<double> dn, len;
      for (int p : reps) {
        float a[4];
        nor->GetMappedValue(draco::PointIndex(p), a);
        V3 nf = Norm(V3{a[0], a[1], a[2]});
        V3 tf = {orig[p][0], orig[p][1], orig[p][2]};
        dn.push_back(std::fabs(90 - std::acos(std::clamp(Dot(nf, Norm(tf)), -1.0, 1.0)) * 180 / M_PI));
        len.push_back(std::fabs(Len(tf) - 1));
      }
      fprintf(stderr, "%s: |90-angle(T,N)| median %.4f p90 %.4f max %.4f; |len-1| p90 %.2e\n", argv[ai], Median(dn), Pct(dn, 0.9), Pct(dn, 1.0), Pct(len, 0.9));
    }
    std::string name = argv[ai];
    name = name.substr(name.find_last_of('/') + 1);
    for (int mode = 0; mode < kNumModes; ++mode) {
      Result r = Predict(*mesh, P, UV, N, Mode(mode));
      // Learn the w convention.
      long agree = 0;
      for (int p : reps) agree += (orig[p][3] > 0) == (r.w[p] > 0);
      const int w_flip = 2 * agree >= long(reps.size()) ? 1 : -1;
      for (int bits : {8, 12}) {
        draco::AttributeQuantizationTransform tt;
        Portable Q = Quantize(*tan, bits, np, &tt);
        Coding c;
        Evaluate(Q, tt, bits, N, r, w_flip, &c, reps, orig);
        const double n = c.n;
        double indep = 0, seq = 0, ang = c.angle.Bits(), ga = 0, gc = 0;
        for (int i = 0; i < 3; ++i) {
          ga += c.gauss[i].Bits();
          for (auto &kv : c.gctx[i]) gc += kv.second.Bits() + 0 * kv.second.h.size();
          indep += c.comp[i].Bits();
          seq += c.seq[i].Bits();
          ang += c.rest[i].Bits();
        }
        if (getenv("TANLAB_DETAIL")) {
          fprintf(stderr, "%s %d %s gauss comps: %.2f %.2f %.2f | indep %.2f %.2f %.2f\n", name.c_str(), bits, kModeNames[mode],
                  c.gauss[0].Bits() / n, c.gauss[1].Bits() / n, c.gauss[2].Bits() / n,
                  c.comp[0].Bits() / n, c.comp[1].Bits() / n, c.comp[2].Bits() / n);
          for (auto &kv : c.gctx[0]) {
            double ma = 0; for (auto &h : kv.second.h) ma += std::labs(h.first) * h.second;
            fprintf(stderr, "   ctx %d: n=%ld mean|e1|=%.2f bits=%.2f\n", kv.first, kv.second.n, ma / kv.second.n, kv.second.Bits() / kv.second.n);
          }
        }
        printf("%s\t%d\t%s\t%ld\t%.3f\t%.3f\t%.2f\t%.3f\t%.2f\t%.2f\t%.2f\t%.2f\t%.2f\n",
               name.c_str(), bits, kModeNames[mode], c.n, Median(c.angle_err),
               Pct(c.angle_err, 0.9), indep / n, c.w.Bits() / n, seq / n,
               ang / n, c.exact / n, ga / n, gc / n);
      }
    }
    fflush(stdout);
  }
  return 0;
}
