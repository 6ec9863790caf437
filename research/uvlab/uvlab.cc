// uvlab.cc - research prototype: residual entropy of UV predictors guided by
// mesh geometry (Draco extension study).  Not production code.
//
// Build: g++ -O2 -std=c++17 -o uvlab uvlab.cc
// Usage: uvlab [--qp 14] [--qt 10,12] [--selftest] name=file.obj ...
// Output: TSV rows on stdout (see header line), mesh info rows prefixed "#info".
//
// All predictors that are meant for production (parallelogram, portable,
// affine "c", similarity "d", their averages, median, weighted, adaptive)
// use only 64-bit integer arithmetic on quantised values.  The eq. 5 angle
// normalisation family ("g*") uses double/libm because it is a measurement.

#include <algorithm>
#include <array>
#include <cassert>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

using namespace std;
typedef int64_t i64;
typedef uint64_t u64;

// ---------------------------------------------------------------- integer helpers
static inline int bitlen(u64 x) { return x ? 64 - __builtin_clzll(x) : 0; }
static inline u64 uabs(i64 x) { return x < 0 ? (u64)0 - (u64)x : (u64)x; }
// floor(sqrt(x)), bit-by-bit, deterministic, valid for all x < 2^64.
static u64 isqrt64(u64 x) {
  u64 r = 0, bit = (u64)1 << 62;
  while (bit > x) bit >>= 2;
  while (bit) {
    if (x >= r + bit) { x -= r + bit; r = (r >> 1) + bit; }
    else r >>= 1;
    bit >>= 2;
  }
  return r;
}
// round(n / d), d > 0, ties away from zero.  Requires |n| + d/2 < 2^63.
static inline i64 rdiv(i64 n, i64 d) {
  return n >= 0 ? (n + d / 2) / d : -((-n + d / 2) / d);
}
// Shift magnitude right (truncation toward zero) - portable for negatives.
static inline i64 shr0(i64 x, int k) { return x >= 0 ? (x >> k) : -((-x) >> k); }

// Draco's IntSqrt (math_utils.h), reproduced for the portable predictor.
static u64 DracoIntSqrt(u64 number) {
  if (number == 0) return 0;
  u64 act = number, sr = 1;
  while (act >= 2) { sr *= 2; act /= 4; }
  do { sr = (sr + number / sr) / 2; } while (sr * sr > number);
  return sr;
}

struct Ent { double bits = 0, tab = 0; };
static int g_qt = 12;
static const int FRAC = 8;  // fixed-point fraction bits used for averaging

// out = base*2^frac + round( ((f*A + g*Bc) * 2^frac) / D ), per component.
// Inputs: |f|,|g| < 2^qt (UV differences), D > 0, |A|,|Bc|,D < 2^62.
// The three coefficients are first reduced by a common right shift so that
// max(|A|,|Bc|,D) < 2^(52-qt); then |f*A + g*Bc| < 2^53 and << frac(<=8) < 2^61.
// Guard: returns false if D vanishes after the shift or a weight exceeds 2^16.
static bool lin2(const i64 base[2], const i64 f[2], i64 A, const i64 g[2], i64 Bc,
                 i64 D, int frac, i64 out[2], i64 *coef = nullptr) {
  if (D <= 0) return false;
  u64 m = max(max(uabs(A), uabs(Bc)), (u64)D);
  int k = max(0, bitlen(m) - (52 - g_qt));
  A = shr0(A, k); Bc = shr0(Bc, k); D = D >> k;
  if (D == 0) return false;
  if (uabs(A) > ((u64)D << 16) || uabs(Bc) > ((u64)D << 16)) return false;
  if (coef) {  // the two weights A/D and Bc/D in 16-bit fixed point, clamped to +-2^20
    const i64 lim = (i64)1 << 20;
    coef[0] = max(-lim, min(lim, rdiv(A * 65536, D)));   // |A| < 2^40 -> no overflow
    coef[1] = max(-lim, min(lim, rdiv(Bc * 65536, D)));
  }
  for (int i = 0; i < 2; ++i) {
    i64 num = f[i] * A + g[i] * Bc;
    num = num * ((i64)1 << frac);
    out[i] = base[i] * ((i64)1 << frac) + rdiv(num, D);
  }
  return true;
}

// ---------------------------------------------------------------- OBJ loading
struct Obj {
  vector<array<float, 3>> v;
  vector<array<float, 2>> vt;
  vector<array<int, 3>> fv, ft;
  int dropped_degenerate = 0;
};

static bool load_obj(const char *path, Obj &o) {
  FILE *fp = fopen(path, "rb");
  if (!fp) return false;
  fseek(fp, 0, SEEK_END);
  long sz = ftell(fp);
  fseek(fp, 0, SEEK_SET);
  string buf(sz, '\0');
  if (fread(&buf[0], 1, sz, fp) != (size_t)sz) { fclose(fp); return false; }
  fclose(fp);
  const char *p = buf.c_str(), *end = p + sz;
  vector<int> pv, pt;
  while (p < end) {
    const char *le = (const char *)memchr(p, '\n', end - p);
    if (!le) le = end;
    string line(p, le);
    p = le + 1;
    const char *s = line.c_str();
    while (*s == ' ' || *s == '\t') ++s;
    if (s[0] == 'v' && (s[1] == ' ' || s[1] == '\t')) {
      char *q;
      array<float, 3> a;
      a[0] = strtof(s + 1, &q); a[1] = strtof(q, &q); a[2] = strtof(q, &q);
      o.v.push_back(a);
    } else if (s[0] == 'v' && s[1] == 't' && (s[2] == ' ' || s[2] == '\t')) {
      char *q;
      array<float, 2> a;
      a[0] = strtof(s + 2, &q); a[1] = strtof(q, &q);
      o.vt.push_back(a);
    } else if (s[0] == 'f' && (s[1] == ' ' || s[1] == '\t')) {
      pv.clear(); pt.clear();
      const char *q = s + 1;
      while (*q) {
        while (*q == ' ' || *q == '\t' || *q == '\r') ++q;
        if (!*q) break;
        char *e;
        long a = strtol(q, &e, 10);
        long b = 0;
        q = e;
        if (*q == '/') {
          ++q;
          if (*q != '/') { b = strtol(q, &e, 10); q = e; }
          if (*q == '/') { ++q; strtol(q, &e, 10); q = e; }
        }
        while (*q && *q != ' ' && *q != '\t') ++q;
        if (a < 0) a = (long)o.v.size() + a + 1;
        if (b < 0) b = (long)o.vt.size() + b + 1;
        pv.push_back((int)a - 1);
        pt.push_back((int)b - 1);
      }
      for (size_t i = 2; i < pv.size(); ++i) {
        array<int, 3> f = {pv[0], pv[i - 1], pv[i]};
        array<int, 3> t = {pt[0], pt[i - 1], pt[i]};
        if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) { o.dropped_degenerate++; continue; }
        if (t[0] < 0 || t[1] < 0 || t[2] < 0) { fprintf(stderr, "face without vt\n"); return false; }
        o.fv.push_back(f);
        o.ft.push_back(t);
      }
    }
  }
  return true;
}

// ---------------------------------------------------------------- UV connectivity
static inline int nx(int c) { return (c % 3 == 2) ? c - 2 : c + 1; }
static inline int pv(int c) { return (c % 3 == 0) ? c + 2 : c - 1; }

struct UF {
  vector<int> p;
  UF(int n) : p(n) { iota(p.begin(), p.end(), 0); }
  int f(int x) { while (p[x] != x) { p[x] = p[p[x]]; x = p[x]; } return x; }
  void u(int a, int b) { a = f(a); b = f(b); if (a != b) p[max(a, b)] = min(a, b); }
};

struct Geo {
  int F = 0, NP = 0, NV = 0;
  vector<int> cpos, cuv;   // corner -> position index, uv-value id
  vector<int> opp, vert;   // UV corner table
  vector<int> vposi, vuvi; // uv vertex -> position / uv value id
  vector<char> vbnd;       // uv vertex fan open
  vector<int> vc_start, vc_list;  // CSR corner lists per uv vertex
  vector<char> pint3d;     // position has closed manifold 3D fan
  vector<double> asum3d, asumuv, cang;
  long interior_edges = 0, seam_edges = 0, nonmanifold_edges = 0, boundary_edges = 0,
       inconsistent_edges = 0;
  int uv_pairs = 0, charts = 0, uvvals = 0;
  // quantised data
  vector<array<i64, 3>> P;  // per position
  vector<array<float, 2>> uvf;  // per uv value id (float)
};

static void build(const Obj &o, Geo &g) {
  g.F = (int)o.fv.size();
  int C = 3 * g.F;
  g.NP = (int)o.v.size();
  g.cpos.resize(C); g.cuv.resize(C);
  // uv value dedup by float bits (with -0 == 0)
  unordered_map<u64, int> uvmap;
  auto fbits = [](float x) { if (x == 0.0f) x = 0.0f; uint32_t b; memcpy(&b, &x, 4); return b; };
  for (int f = 0; f < g.F; ++f)
    for (int k = 0; k < 3; ++k) {
      int c = 3 * f + k;
      g.cpos[c] = o.fv[f][k];
      const auto &t = o.vt[o.ft[f][k]];
      u64 key = ((u64)fbits(t[0]) << 32) | fbits(t[1]);
      auto it = uvmap.find(key);
      int id;
      if (it == uvmap.end()) { id = (int)g.uvf.size(); uvmap[key] = id; g.uvf.push_back(t); }
      else id = it->second;
      g.cuv[c] = id;
    }
  g.uvvals = (int)g.uvf.size();
  {  // distinct (pos, uv) pairs
    vector<u64> pr(C);
    for (int c = 0; c < C; ++c) pr[c] = ((u64)g.cpos[c] << 32) | (u64)g.cuv[c];
    sort(pr.begin(), pr.end());
    g.uv_pairs = (int)(unique(pr.begin(), pr.end()) - pr.begin());
  }
  // edges: corner c is opposite edge (pos[nx c] -> pos[pv c])
  vector<pair<u64, int>> ek(C);
  for (int c = 0; c < C; ++c) {
    u64 a = g.cpos[nx(c)], b = g.cpos[pv(c)];
    ek[c] = {(min(a, b) << 32) | max(a, b), c};
  }
  sort(ek.begin(), ek.end());
  g.opp.assign(C, -1);
  g.pint3d.assign(g.NP, 1);
  vector<char> used(g.NP, 0);
  for (int c = 0; c < C; ++c) used[g.cpos[c]] = 1;
  UF uf(C);
  UF fuf(g.F);
  for (size_t i = 0; i < ek.size();) {
    size_t j = i;
    while (j < ek.size() && ek[j].first == ek[i].first) ++j;
    size_t n = j - i;
    bool manifold = false;
    if (n == 2) {
      int c1 = ek[i].second, c2 = ek[i + 1].second;
      if (g.cpos[nx(c1)] == g.cpos[pv(c2)] && g.cpos[pv(c1)] == g.cpos[nx(c2)]) {
        manifold = true;
        g.interior_edges++;
        bool same = g.cuv[nx(c1)] == g.cuv[pv(c2)] && g.cuv[pv(c1)] == g.cuv[nx(c2)];
        if (same) {
          g.opp[c1] = c2; g.opp[c2] = c1;
          uf.u(nx(c1), pv(c2));
          uf.u(pv(c1), nx(c2));
          fuf.u(c1 / 3, c2 / 3);
        } else g.seam_edges++;
      } else g.inconsistent_edges++;
    } else if (n == 1) g.boundary_edges++;
    else g.nonmanifold_edges++;
    if (!manifold) {
      int c = ek[i].second;
      g.pint3d[g.cpos[nx(c)]] = 0;
      g.pint3d[g.cpos[pv(c)]] = 0;
    }
    i = j;
  }
  for (int p = 0; p < g.NP; ++p) if (!used[p]) g.pint3d[p] = 0;
  // uv vertices = union-find classes (fans), numbered by first corner
  g.vert.assign(C, -1);
  vector<int> rootid(C, -1);
  for (int c = 0; c < C; ++c) {
    int r = uf.f(c);
    if (rootid[r] < 0) { rootid[r] = g.NV++; g.vposi.push_back(g.cpos[c]); g.vuvi.push_back(g.cuv[c]); }
    g.vert[c] = rootid[r];
  }
  g.vc_start.assign(g.NV + 1, 0);
  for (int c = 0; c < C; ++c) g.vc_start[g.vert[c] + 1]++;
  for (int v = 0; v < g.NV; ++v) g.vc_start[v + 1] += g.vc_start[v];
  g.vc_list.resize(C);
  {
    vector<int> fill(g.vc_start.begin(), g.vc_start.end() - 1);
    for (int c = 0; c < C; ++c) g.vc_list[fill[g.vert[c]]++] = c;
  }
  g.vbnd.assign(g.NV, 0);
  for (int c = 0; c < C; ++c)
    if (g.opp[nx(c)] < 0 || g.opp[pv(c)] < 0) g.vbnd[g.vert[c]] = 1;
  {
    vector<char> seen(g.F, 0);
    for (int f = 0; f < g.F; ++f) { int r = fuf.f(f); if (!seen[r]) { seen[r] = 1; g.charts++; } }
  }
}

// Draco-exact quantisation: one range over all components.
template <int N>
static vector<array<i64, N>> quantise(const vector<array<float, N>> &vals, const vector<char> *used,
                                      int bits) {
  float mn[N], mx[N];
  bool first = true;
  for (size_t i = 0; i < vals.size(); ++i) {
    if (used && !(*used)[i]) continue;
    for (int k = 0; k < N; ++k) {
      if (first) { mn[k] = mx[k] = vals[i][k]; }
      else { mn[k] = min(mn[k], vals[i][k]); mx[k] = max(mx[k], vals[i][k]); }
    }
    first = false;
  }
  float range = 0.f;
  for (int k = 0; k < N; ++k) { float d = mx[k] - mn[k]; if (d > range) range = d; }
  if (range == 0.f) range = 1.f;
  const int32_t maxq = (1 << bits) - 1;
  const float inv = (float)maxq / range;
  vector<array<i64, N>> out(vals.size());
  for (size_t i = 0; i < vals.size(); ++i)
    for (int k = 0; k < N; ++k) {
      float val = vals[i][k] - mn[k];
      val *= inv;
      out[i][k] = (int32_t)floor(val + 0.5f);
    }
  return out;
}

// ---------------------------------------------------------------- traversals
struct Order {
  vector<int> order, reach, rank;
};

static void dfs_order(const Geo &g, Order &o) {
  vector<char> fvis(g.F, 0), vvis(g.NV, 0);
  o.order.clear(); o.reach.assign(g.NV, -1);
  auto visitV = [&](int v, int c) { if (!vvis[v]) { vvis[v] = 1; o.reach[v] = c; o.order.push_back(v); } };
  auto fv = [&](int c) { return c < 0 || fvis[c / 3]; };
  vector<int> st;
  for (int f = 0; f < g.F; ++f) {
    if (fvis[f]) continue;
    int c0 = 3 * f;
    st.clear();
    // Deviation from Draco: also traverse across the start face's third edge
    // (Draco never follows opp[c0], which splits a chart when face c0 is not
    // on its border; the rest of the chart then restarts without predictors).
    if (g.opp[c0] >= 0) st.push_back(g.opp[c0]);
    st.push_back(c0);
    visitV(g.vert[nx(c0)], nx(c0));
    visitV(g.vert[pv(c0)], pv(c0));
    while (!st.empty()) {
      int c = st.back();
      if (c < 0 || fvis[c / 3]) { st.pop_back(); continue; }
      while (true) {
        fvis[c / 3] = 1;
        int v = g.vert[c];
        if (!vvis[v]) {
          bool onb = g.vbnd[v];
          visitV(v, c);
          if (!onb) { c = g.opp[nx(c)]; continue; }
        }
        int rc = g.opp[nx(c)], lc = g.opp[pv(c)];
        if (fv(rc)) {
          if (fv(lc)) { st.pop_back(); break; }
          c = lc;
        } else {
          if (fv(lc)) c = rc;
          else { st.back() = lc; st.push_back(rc); break; }
        }
      }
    }
  }
  o.rank.assign(g.NV, 0);
  for (size_t i = 0; i < o.order.size(); ++i) o.rank[o.order[i]] = (int)i;
}

// kmax = 3 reproduces Draco's MaxPredictionDegreeTraverser (priority 1 for
// degree > 1, 2 for degree 1); kmax = 5 is a finer variant ("mpd5"):
// priority = max(1, 5 - degree), i.e. degree >= 4 first, then 3, 2, 1.
static void mpd_order(const Geo &g, Order &o, int kmax = 3) {
  vector<char> fvis(g.F, 0), vvis(g.NV, 0);
  vector<int> deg(g.NV, 0);
  o.order.clear(); o.reach.assign(g.NV, -1);
  auto visitV = [&](int v, int c) { if (!vvis[v]) { vvis[v] = 1; o.reach[v] = c; o.order.push_back(v); } };
  auto fv = [&](int c) { return c < 0 || fvis[c / 3]; };
  vector<int> stacks[8];
  int best = 0;
  auto prio = [&](int c) {
    int v = g.vert[c], p = 0;
    if (!vvis[v]) {
      int d = ++deg[v];
      p = kmax == 3 ? (d > 1 ? 1 : 2) : max(1, kmax - d);
    }
    return min(p, kmax - 1);
  };
  auto pop = [&]() {
    for (int i = best; i < kmax; ++i)
      if (!stacks[i].empty()) { int r = stacks[i].back(); stacks[i].pop_back(); best = i; return r; }
    return -1;
  };
  auto push = [&](int c, int p) { stacks[p].push_back(c); if (p < best) best = p; };
  for (int f = 0; f < g.F; ++f) {
    if (fvis[f]) continue;
    int c0 = 3 * f;
    stacks[0].push_back(c0);
    best = 0;
    visitV(g.vert[nx(c0)], nx(c0));
    visitV(g.vert[pv(c0)], pv(c0));
    visitV(g.vert[c0], c0);
    if (g.opp[c0] >= 0) { int oc = g.opp[c0]; push(oc, prio(oc)); }  // deviation, see dfs_order
    int c;
    while ((c = pop()) != -1) {
      if (fvis[c / 3]) continue;
      while (true) {
        fvis[c / 3] = 1;
        visitV(g.vert[c], c);
        int rc = g.opp[nx(c)], lc = g.opp[pv(c)];
        bool rvis = fv(rc), lvis = fv(lc);
        if (!lvis) {
          int pr = prio(lc);
          if (rvis && pr <= best) { c = lc; continue; }
          push(lc, pr);
        }
        if (!rvis) {
          int pr = prio(rc);
          if (pr <= best) { c = rc; continue; }
          push(rc, pr);
        }
        break;
      }
    }
  }
  o.rank.assign(g.NV, 0);
  for (size_t i = 0; i < o.order.size(); ++i) o.rank[o.order[i]] = (int)i;
}

// ---------------------------------------------------------------- variants
enum {
  A_DRACO, A_FIRST, A_AVG, B_PORT, B_ORACLE, C_ONE, D_ONE, C_AVG, D_AVG, F_AVG,
  G0_ONE, G3D_ONE, GUV_ONE, G3D_AVG, GUV_AVG, G3D_DAVG, GUV_DAVG,
  H_MED, H_W, H_ADAPT, H_CD_ONE, H_ADAPT2, H_BLEND, H_QW, H_ADAPT3, NVAR
};
static const char *VNAME[NVAR] = {
  "a_draco", "a_first", "a_avg", "b_portable", "b_oracle", "c_one", "d_one", "c_avg", "d_avg",
  "f_avg", "g0_one", "g3d_one", "guv_one", "g3d_avg", "guv_avg", "g3d_davg", "guv_davg",
  "h_med", "h_wavg", "h_adapt", "h_cd_one", "h_adapt2", "h_blend", "h_qw", "h_adapt3"};

struct Stencil { int c, L, R, B; };

// sum over contexts of n_ctx*H_ctx (bits) and table overhead 16 bits/distinct symbol/context
static Ent entropy(const vector<int> &ru, const vector<int> &rv, const vector<uint8_t> *ctx, bool sep) {
  unordered_map<u64, int> cnt;
  cnt.reserve(ru.size() * 2);
  unordered_map<int, long> tot;
  for (size_t i = 0; i < ru.size(); ++i) {
    int cx = ctx ? (*ctx)[i] : 0;
    for (int k = 0; k < 2; ++k) {
      int s = k ? rv[i] : ru[i];
      int cc = sep ? cx * 2 + k : cx;
      cnt[((u64)(uint32_t)cc << 32) | (uint32_t)s]++;
      tot[cc]++;
    }
  }
  Ent e;
  for (auto &kv : cnt) {
    int cc = (int)(kv.first >> 32);
    double n = kv.second, N = (double)tot[cc];
    e.bits += -n * log2(n / N);
    e.tab += 16;
  }
  return e;
}
// Cost of sequential adaptive coding (no tables): per context an adaptive
// frequency model with PPM method-C escapes; a symbol not yet seen in its
// context costs the escape plus an Elias-gamma code of its zig-zag value.
// u and v go through the same model (u first).
static double adaptive_cost(const vector<int> &ru, const vector<int> &rv, const vector<uint8_t> *ctx) {
  unordered_map<u64, int> cnt;
  unordered_map<int, long> tot, distinct;
  double bits = 0;
  for (size_t i = 0; i < ru.size(); ++i) {
    int cx = ctx ? (*ctx)[i] : 0;
    for (int k = 0; k < 2; ++k) {
      int s = k ? rv[i] : ru[i];
      u64 key = ((u64)(uint32_t)cx << 32) | (uint32_t)s;
      long n = tot[cx], E = distinct[cx];
      auto it = cnt.find(key);
      if (it != cnt.end()) {
        bits += -log2((double)it->second / (double)(n + E));
        it->second++;
      } else {
        u64 z = s >= 0 ? 2 * (u64)s : 2 * (u64)(-(i64)s) - 1;
        double esc = n ? -log2((double)E / (double)(n + E)) : 0.0;
        bits += esc + 2 * (bitlen(z + 1) - 1) + 1;
        cnt[key] = 1;
        distinct[cx]++;
      }
      tot[cx]++;
    }
  }
  return bits;
}
// Hybrid-uint ("tagged") coding with static per-context tables: z = zigzag(r);
// z < 16 -> token z; else n = bitlen(z)-1, token = 16 + 2(n-4) + next bit, n-1 raw bits.
// Cost = sum over contexts n_ctx*H(token|ctx) + raw bits + 16 bits per distinct token per context.
static Ent hybrid_cost(const vector<int> &ru, const vector<int> &rv, const vector<uint8_t> *ctx) {
  unordered_map<u64, int> cnt;
  unordered_map<int, long> tot;
  double raw = 0;
  for (size_t i = 0; i < ru.size(); ++i) {
    int cx = ctx ? (*ctx)[i] : 0;
    for (int k = 0; k < 2; ++k) {
      int s = k ? rv[i] : ru[i];
      u64 z = s >= 0 ? 2 * (u64)s : 2 * (u64)(-(i64)s) - 1;
      int tok;
      if (z < 16) tok = (int)z;
      else { int n = bitlen(z) - 1; tok = 16 + 2 * (n - 4) + (int)((z >> (n - 1)) & 1); raw += n - 1; }
      cnt[((u64)(uint32_t)cx << 32) | (uint32_t)tok]++;
      tot[cx]++;
    }
  }
  Ent e;
  for (auto &kv : cnt) {
    double n = kv.second, N = (double)tot[(int)(kv.first >> 32)];
    e.bits += -n * log2(n / N);
    e.tab += 16;
  }
  e.bits += raw;
  return e;
}
// Cost of a bit sequence coded like Draco's RAnsBitEncoder (static 8-bit probability).
static double rans_bit_cost(long n0, long n1) {
  long total = n0 + n1;
  if (total == 0) return 0;
  uint32_t zp_raw = (uint32_t)(((double)n0 / total) * 256.0 + 0.5);
  int zp = zp_raw < 255 ? (int)zp_raw : 255;
  if (zp == 0) zp = 1;
  return n0 * log2(256.0 / zp) + n1 * log2(256.0 / (256 - zp)) + 8;  // +1 byte probability
}

struct Runner {
  const Geo &g;
  const Order &o;
  const vector<array<i64, 3>> &P;   // per position
  const vector<array<i64, 2>> &U;   // per uv value id
  i64 minv, maxv, maxdif, maxcorr, mincorr;
  int p = 0;  // current step

  Runner(const Geo &g_, const Order &o_, const vector<array<i64, 3>> &P_,
         const vector<array<i64, 2>> &U_) : g(g_), o(o_), P(P_), U(U_) {
    minv = LLONG_MAX; maxv = LLONG_MIN;
    for (int v = 0; v < g.NV; ++v) for (int k = 0; k < 2; ++k) { minv = min(minv, U[g.vuvi[v]][k]); maxv = max(maxv, U[g.vuvi[v]][k]); }
    maxdif = 1 + (maxv - minv);
    maxcorr = maxdif / 2; mincorr = -maxcorr;
    if ((maxdif & 1) == 0) maxcorr -= 1;
  }
  inline bool dec(int v) const { return o.rank[v] < p; }
  inline const array<i64, 3> &pos(int v) const { return P[g.vposi[v]]; }
  // Causality check: a prediction may only read UVs of vertices decoded before step p
  // (rank < p); rank == p (the vertex itself) is read only by the residual, by the
  // encoder-side orientation choice of b_portable (paid with bits) and by statistics.
  inline const array<i64, 2> &uv(int v) const {
    if (o.rank[v] > p) { fprintf(stderr, "causality violation: read vertex rank %d at step %d\n", o.rank[v], p); abort(); }
    return U[g.vuvi[v]];
  }
  // Draco wrap transform: clamp prediction, wrap residual.
  inline void residual(int v, const i64 pred[2], int out[2]) const {
    for (int k = 0; k < 2; ++k) {
      i64 pr = min(max(pred[k], minv), maxv);
      i64 r = uv(v)[k] - pr;
      if (r < mincorr) r += maxdif; else if (r > maxcorr) r -= maxdif;
      out[k] = (int)r;
    }
  }
  int face_orient(int f) const {
    const auto &a = uv(g.vert[3 * f]), &b = uv(g.vert[3 * f + 1]), &c = uv(g.vert[3 * f + 2]);
    i64 cr = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    return cr > 0 ? 1 : (cr < 0 ? -1 : 0);
  }
};

struct Acc {  // per variant accumulators
  vector<int> ru, rv;
  vector<uint8_t> c2;
  vector<int> mag;  // per uv vertex |ru|+|rv|
  long n_geo = 0;   // predictions from a geometric stencil
};

static const double TWO_PI = 6.283185307179586;

struct Result { double H0, T0, H1, T1, H2, T2, Hs, Ts, H1s, T1s, extra; long ngeo; };

// Runs all predictors in the given order.  Returns per-variant results.
static void run_all(const Geo &g, const Order &o, const vector<array<i64, 3>> &P,
                    const vector<array<i64, 2>> &U, const char *mesh, const char *oname,
                    int qt, FILE *out, bool verbose) {
  Runner R(g, o, P, U);
  const int N = g.NV;
  vector<Acc> acc(NVAR);
  for (auto &a : acc) { a.ru.reserve(N); a.rv.reserve(N); a.c2.reserve(N); a.mag.assign(N, 0); }
  vector<uint8_t> c1, c3, fbc; c1.reserve(N); c3.reserve(N); fbc.reserve(N);
  vector<int> fbnbr; fbnbr.reserve(N);
  long cat_stB = 0, cat_st = 0, cat_nbr = 0, cat_prev = 0, cat_zero = 0, nst_total = 0, nst_hist[4] = {0, 0, 0, 0};
  long b_n0 = 0, b_n1 = 0;
  vector<char> b_orient;  // orientation per portable prediction, in decoding order
  long sign_from[3] = {0, 0, 0}, sign_wrong[3] = {0, 0, 0};
  long g0_mismatch = 0, g0_cmp = 0, c_fallback_d = 0, c_ref_cmp = 0, c_ref_mismatch = 0;
  long orient_pos = 0, orient_neg = 0;
  const int NK = 6;  // h_adapt uses the first 4, h_adapt2 / h_blend the first 5, h_adapt3 all 6
  const int KCAND[NK] = {F_AVG, C_AVG, D_AVG, A_AVG, H_W, H_QW};
  vector<array<int, NK>> kcost(N);
  long adapt_pick[NK] = {0, 0, 0, 0, 0, 0};

  vector<Stencil> stl;
  vector<int> nbrs;
  struct SP { i64 c[2], d[2], gc, gd; bool hasB, cok; double gc3[2], gcu[2], gd3[2], gdu[2]; i64 par[2]; int sign; };
  vector<SP> sp;

  auto sim_pred = [&](int L, int Rv, int O, int sign, int frac, i64 out[2], i64 *coef = nullptr) -> bool {
    const auto &pl = R.pos(L), &pr = R.pos(Rv), &po = R.pos(O);
    i64 e[3], d[3];
    for (int k = 0; k < 3; ++k) { e[k] = pr[k] - pl[k]; d[k] = po[k] - pl[k]; }
    i64 ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    if (!ee) return false;
    i64 de = d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
    i64 x0 = e[1] * d[2] - e[2] * d[1], x1 = e[2] * d[0] - e[0] * d[2], x2 = e[0] * d[1] - e[1] * d[0];
    u64 cd2 = (u64)(x0 * x0) + (u64)(x1 * x1) + (u64)(x2 * x2);
    int s = min(20, (62 - bitlen(cd2)) / 2);
    i64 td = (i64)isqrt64(cd2 << (2 * s));
    const auto &ul = R.uv(L), &ur = R.uv(Rv);
    i64 f[2] = {ur[0] - ul[0], ur[1] - ul[1]};
    i64 rf[2] = {-f[1], f[0]};
    i64 base[2] = {ul[0], ul[1]};
    return lin2(base, f, de * ((i64)1 << s), rf, sign * td, ee * ((i64)1 << s), frac, out, coef);
  };
  auto aff_pred = [&](int L, int Rv, int B, int O, int frac, i64 out[2], i64 *coef = nullptr) -> bool {
    const auto &pl = R.pos(L), &pr = R.pos(Rv), &po = R.pos(O), &pb = R.pos(B);
    i64 e[3], d[3], b[3];
    for (int k = 0; k < 3; ++k) { e[k] = pr[k] - pl[k]; d[k] = po[k] - pl[k]; b[k] = pb[k] - pl[k]; }
    i64 ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    if (!ee) return false;
    i64 de = d[0] * e[0] + d[1] * e[1] + d[2] * e[2];
    i64 be = b[0] * e[0] + b[1] * e[1] + b[2] * e[2];
    i64 x0 = e[1] * d[2] - e[2] * d[1], x1 = e[2] * d[0] - e[0] * d[2], x2 = e[0] * d[1] - e[1] * d[0];
    i64 y0 = e[1] * b[2] - e[2] * b[1], y1 = e[2] * b[0] - e[0] * b[2], y2 = e[0] * b[1] - e[1] * b[0];
    u64 cd2 = (u64)(x0 * x0) + (u64)(x1 * x1) + (u64)(x2 * x2);
    u64 cb2 = (u64)(y0 * y0) + (u64)(y1 * y1) + (u64)(y2 * y2);
    if (!cb2) return false;
    int s = (62 - bitlen(max(cd2, cb2))) / 2;
    i64 td = (i64)isqrt64(cd2 << (2 * s)), tb = (i64)isqrt64(cb2 << (2 * s));
    i64 A = de * tb + td * be, Bc = td * ee, D = ee * tb;
    const auto &ul = R.uv(L), &ur = R.uv(Rv), &ub = R.uv(B);
    i64 f[2] = {ur[0] - ul[0], ur[1] - ul[1]};
    i64 gg[2] = {ub[0] - ul[0], ub[1] - ul[1]};
    i64 base[2] = {ul[0], ul[1]};
    return lin2(base, f, A, gg, -Bc, D, frac, out, coef);
  };
  // orientation rule for the similarity predictor (no bits)
  auto sign_rule = [&](const Stencil &s, int *src) -> int {
    if (s.B >= 0) {
      const auto &ul = R.uv(s.L), &ur = R.uv(s.R), &ub = R.uv(s.B);
      i64 cr = (ur[0] - ul[0]) * (ub[1] - ul[1]) - (ur[1] - ul[1]) * (ub[0] - ul[0]);
      if (cr > 0) { *src = 0; return -1; }
      if (cr < 0) { *src = 0; return 1; }
    }
    for (int w : {s.L, s.R})
      for (int i = g.vc_start[w]; i < g.vc_start[w + 1]; ++i) {
        int f = g.vc_list[i] / 3;
        if (R.dec(g.vert[3 * f]) && R.dec(g.vert[3 * f + 1]) && R.dec(g.vert[3 * f + 2])) {
          int or_ = R.face_orient(f);
          if (or_) { *src = 1; return or_; }
        }
      }
    *src = 2;
    return orient_neg > orient_pos ? -1 : 1;
  };
  // angle at a in triangle (a,b,c) from 3D positions
  auto ang = [&](int a, int b, int c) {
    const auto &pa = R.pos(a), &pb = R.pos(b), &pc = R.pos(c);
    double u[3], w[3];
    for (int k = 0; k < 3; ++k) { u[k] = (double)(pb[k] - pa[k]); w[k] = (double)(pc[k] - pa[k]); }
    double cx = u[1] * w[2] - u[2] * w[1], cy = u[2] * w[0] - u[0] * w[2], cz = u[0] * w[1] - u[1] * w[0];
    return atan2(sqrt(cx * cx + cy * cy + cz * cz), u[0] * w[0] + u[1] * w[1] + u[2] * w[2]);
  };
  // eq. 4 / eq. 5. mode 0: raw, 1: normalise at 3D-interior, 2: at UV-interior.
  auto norm_scale = [&](int v, int mode) -> double {
    if (mode == 1) { int pp = g.vposi[v]; return g.pint3d[pp] ? TWO_PI / g.asum3d[pp] : 1.0; }
    if (mode == 2) return !g.vbnd[v] ? TWO_PI / g.asumuv[v] : 1.0;
    return 1.0;
  };
  auto eq4 = [&](const Stencil &s, int O, int mode, double out[2]) -> bool {
    double sl = norm_scale(s.L, mode), sr = norm_scale(s.R, mode);
    double al = ang(s.L, s.R, s.B) * sl, be = ang(s.R, s.L, s.B) * sr;
    double ga = ang(s.L, s.R, O) * sl, de = ang(s.R, s.L, O) * sr;
    if (sin(al) == 0 || sin(be) == 0 || sin(ga) == 0 || sin(de) == 0) return false;
    auto cot = [](double x) { return cos(x) / sin(x); };
    double den = cot(de) + cot(ga);
    if (fabs(den) < 1e-12) return false;
    double w1 = (cot(be) + cot(de)) / den, w2 = (cot(al) + cot(ga)) / den, w3 = 1 - w1 - w2;
    for (int k = 0; k < 2; ++k) out[k] = w1 * R.uv(s.L)[k] + w2 * R.uv(s.R)[k] + w3 * R.uv(s.B)[k];
    return isfinite(out[0]) && isfinite(out[1]) && fabs(out[0]) < 1e9 && fabs(out[1]) < 1e9;
  };
  auto sim_angles = [&](const Stencil &s, int O, int mode, int sign, double out[2]) -> bool {
    double sl = norm_scale(s.L, mode), sr = norm_scale(s.R, mode);
    double ga = ang(s.L, s.R, O) * sl, de = ang(s.R, s.L, O) * sr;
    if (sin(ga) == 0 || sin(de) == 0) return false;
    auto cot = [](double x) { return cos(x) / sin(x); };
    double den = cot(ga) + cot(de);
    if (fabs(den) < 1e-12) return false;
    double ss = cot(ga) / den, t = 1.0 / den;
    const auto &ul = R.uv(s.L), &ur = R.uv(s.R);
    double f0 = (double)(ur[0] - ul[0]), f1 = (double)(ur[1] - ul[1]);
    out[0] = ul[0] + ss * f0 + sign * t * (-f1);
    out[1] = ul[1] + ss * f1 + sign * t * f0;
    return isfinite(out[0]) && isfinite(out[1]) && fabs(out[0]) < 1e9 && fabs(out[1]) < 1e9;
  };

  for (int p = 0; p < N; ++p) {
    R.p = p;
    const int O = o.order[p];
    const int rc = o.reach[O];
    // ---- stencils: reach corner first, then the fan in corner order
    stl.clear();
    auto addSt = [&](int c) {
      int L = g.vert[nx(c)], Rr = g.vert[pv(c)];
      if (R.dec(L) && R.dec(Rr)) {
        int B = -1, oc = g.opp[c];
        if (oc >= 0 && R.dec(g.vert[oc])) B = g.vert[oc];
        stl.push_back({c, L, Rr, B});
      }
    };
    addSt(rc);
    for (int i = g.vc_start[O]; i < g.vc_start[O + 1]; ++i) if (g.vc_list[i] != rc) addSt(g.vc_list[i]);
    // ---- decoded neighbours
    nbrs.clear();
    auto addN = [&](int v) { if (R.dec(v) && find(nbrs.begin(), nbrs.end(), v) == nbrs.end()) nbrs.push_back(v); };
    addN(g.vert[nx(rc)]); addN(g.vert[pv(rc)]);
    for (int i = g.vc_start[O]; i < g.vc_start[O + 1]; ++i) { int c = g.vc_list[i]; addN(g.vert[nx(c)]); addN(g.vert[pv(c)]); }
    // ---- common fallback
    i64 fb[2] = {0, 0};
    int fbcat;
    if (!nbrs.empty()) { fb[0] = R.uv(nbrs[0])[0]; fb[1] = R.uv(nbrs[0])[1]; fbcat = 1; }
    else if (p > 0) { fb[0] = R.uv(o.order[p - 1])[0]; fb[1] = R.uv(o.order[p - 1])[1]; fbcat = 2; }
    else fbcat = 3;
    fbc.push_back(stl.empty() ? (uint8_t)fbcat : (uint8_t)0);
    fbnbr.push_back(!nbrs.empty() ? nbrs[0] : -1);
    if (!stl.empty()) { if (stl[0].B >= 0) cat_stB++; else cat_st++; }
    else if (fbcat == 1) cat_nbr++; else if (fbcat == 2) cat_prev++; else cat_zero++;
    nst_total += stl.size();
    nst_hist[min<size_t>(3, stl.size())]++;
    // context 1: log2 of stencil edge length (inf norm)
    if (!stl.empty()) {
      const auto &ul = R.uv(stl[0].L), &ur = R.uv(stl[0].R);
      u64 m = max(uabs(ur[0] - ul[0]), uabs(ur[1] - ul[1]));
      c1.push_back((uint8_t)min(7, bitlen(m)));
    } else c1.push_back(8);

    // ---- per-stencil predictions (ctx3 set below from c/d disagreement)
    sp.assign(stl.size(), SP());
    for (size_t i = 0; i < stl.size(); ++i) {
      const Stencil &s = stl[i];
      SP &q = sp[i];
      int src;
      q.sign = sign_rule(s, &src);
      // noise gains (sum of squared input weights, 16-bit fixed point), used by h_qw
      i64 cf[2];
      if (!sim_pred(s.L, s.R, O, q.sign, FRAC, q.d, cf)) {
        for (int k = 0; k < 2; ++k) q.d[k] = (R.uv(s.L)[k] + R.uv(s.R)[k]) * (1 << (FRAC - 1));
        q.gd = 1 << 15;
      } else {
        i64 w0 = 65536 - cf[0];
        q.gd = (w0 * w0 + cf[0] * cf[0] + 2 * cf[1] * cf[1]) >> 16;   // terms < 2^42
      }
      q.hasB = s.B >= 0;
      q.cok = q.hasB && aff_pred(s.L, s.R, s.B, O, FRAC, q.c, cf);
      if (!q.cok) { q.c[0] = q.d[0]; q.c[1] = q.d[1]; q.gc = q.gd; }
      else {
        i64 w0 = 65536 - cf[0] - cf[1];
        q.gc = (w0 * w0 + cf[0] * cf[0] + cf[1] * cf[1]) >> 16;
      }
      if (q.hasB) for (int k = 0; k < 2; ++k) q.par[k] = (R.uv(s.L)[k] + R.uv(s.R)[k] - R.uv(s.B)[k]) * (1 << FRAC);
      // Clamp per-stencil predictions to the value range (known to the decoder from the
      // wrap transform header): keeps |c_i - d_i| < 2^(qt+8), so the squared distances and
      // weighted sums of h_wavg / h_qw stay far below 2^63.
      for (int k = 0; k < 2; ++k) {
        const i64 lo = R.minv * (1 << FRAC), hi = R.maxv * (1 << FRAC);
        q.c[k] = min(max(q.c[k], lo), hi);
        q.d[k] = min(max(q.d[k], lo), hi);
      }
      double dd[2] = {q.d[0] / 256.0, q.d[1] / 256.0};
      for (int k = 0; k < 2; ++k) { q.gc3[k] = q.gcu[k] = q.gd3[k] = q.gdu[k] = dd[k]; }
      if (q.hasB) {
        double t[2];
        if (eq4(s, O, 1, t)) { q.gc3[0] = t[0]; q.gc3[1] = t[1]; }
        if (eq4(s, O, 2, t)) { q.gcu[0] = t[0]; q.gcu[1] = t[1]; }
      }
      double t[2];
      if (sim_angles(s, O, 1, q.sign, t)) { q.gd3[0] = t[0]; q.gd3[1] = t[1]; }
      if (sim_angles(s, O, 2, q.sign, t)) { q.gdu[0] = t[0]; q.gdu[1] = t[1]; }
    }

    i64 pred[NVAR][2];
    bool geo[NVAR];
    for (int v = 0; v < NVAR; ++v) { pred[v][0] = fb[0]; pred[v][1] = fb[1]; geo[v] = false; }
    auto setfx = [&](int v, const i64 fx[2]) { pred[v][0] = rdiv(fx[0], 1 << FRAC); pred[v][1] = rdiv(fx[1], 1 << FRAC); geo[v] = true; };
    auto setd = [&](int v, const double x[2]) { pred[v][0] = llround(x[0]); pred[v][1] = llround(x[1]); geo[v] = true; };

    // a_draco: Draco MESH_PREDICTION_PARALLELOGRAM (reach corner only, else delta)
    {
      int oc = g.opp[rc];
      bool ok = false;
      if (oc >= 0) {
        int Bv = g.vert[oc], Nn = g.vert[nx(oc)], Pp = g.vert[pv(oc)];
        if (R.dec(Bv) && R.dec(Nn) && R.dec(Pp)) {
          for (int k = 0; k < 2; ++k) pred[A_DRACO][k] = R.uv(Nn)[k] + R.uv(Pp)[k] - R.uv(Bv)[k];
          ok = true; geo[A_DRACO] = true;
        }
      }
      if (!ok) {
        if (p > 0) { pred[A_DRACO][0] = R.uv(o.order[p - 1])[0]; pred[A_DRACO][1] = R.uv(o.order[p - 1])[1]; }
        else { pred[A_DRACO][0] = pred[A_DRACO][1] = 0; }
      }
    }
    // a_first, a_avg
    {
      i64 sum[2] = {0, 0}; int n = 0; bool first = true;
      for (auto &q : sp) if (q.hasB) {
        if (first) { setfx(A_FIRST, q.par); first = false; }
        sum[0] += q.par[0]; sum[1] += q.par[1]; ++n;
      }
      if (n) { i64 m[2] = {rdiv(sum[0], n), rdiv(sum[1], n)}; setfx(A_AVG, m); }
    }
    // b: Draco portable (exact reproduction incl. its fallback), orientation bit paid
    {
      int nid = g.vert[nx(rc)], pid = g.vert[pv(rc)];
      bool done = false;
      if (R.dec(pid) && R.dec(nid)) {
        const auto &n_uv = R.uv(nid), &p_uv = R.uv(pid);
        if (n_uv == p_uv) {
          for (int k = 0; k < 2; ++k) pred[B_PORT][k] = pred[B_ORACLE][k] = p_uv[k];
          done = true;
        } else {
          const auto &tp = R.pos(O), &np = R.pos(nid), &ppos = R.pos(pid);
          i64 pn[3], cn[3];
          for (int k = 0; k < 3; ++k) { pn[k] = ppos[k] - np[k]; cn[k] = tp[k] - np[k]; }
          u64 pn2 = (u64)(pn[0] * pn[0] + pn[1] * pn[1] + pn[2] * pn[2]);
          if (pn2 != 0) {
            i64 cn_dot_pn = pn[0] * cn[0] + pn[1] * cn[1] + pn[2] * cn[2];
            i64 pn_uv[2] = {p_uv[0] - n_uv[0], p_uv[1] - n_uv[1]};
            i64 x_uv[2] = {n_uv[0] * (i64)pn2 + cn_dot_pn * pn_uv[0], n_uv[1] * (i64)pn2 + cn_dot_pn * pn_uv[1]};
            i64 x_pos[3];
            for (int k = 0; k < 3; ++k) x_pos[k] = np[k] + (cn_dot_pn * pn[k]) / (i64)pn2;
            u64 cx2 = 0;
            for (int k = 0; k < 3; ++k) { i64 t = tp[k] - x_pos[k]; cx2 += (u64)(t * t); }
            i64 cx_uv[2] = {pn_uv[1], -pn_uv[0]};
            u64 nsq = DracoIntSqrt(cx2 * pn2);
            cx_uv[0] *= (i64)nsq; cx_uv[1] *= (i64)nsq;
            i64 p0[2], p1[2];
            for (int k = 0; k < 2; ++k) { p0[k] = (x_uv[k] + cx_uv[k]) / (i64)pn2; p1[k] = (x_uv[k] - cx_uv[k]) / (i64)pn2; }
            const auto &c_uv = R.uv(O);
            i64 e0 = (c_uv[0] - p0[0]) * (c_uv[0] - p0[0]) + (c_uv[1] - p0[1]) * (c_uv[1] - p0[1]);
            i64 e1 = (c_uv[0] - p1[0]) * (c_uv[0] - p1[0]) + (c_uv[1] - p1[1]) * (c_uv[1] - p1[1]);
            const i64 *pp = e0 < e1 ? p0 : p1;
            if (e0 < e1) b_n1++; else b_n0++;
            b_orient.push_back(e0 < e1);
            for (int k = 0; k < 2; ++k) pred[B_PORT][k] = pred[B_ORACLE][k] = (int32_t)pp[k];
            done = true;
          }
        }
        if (done) geo[B_PORT] = geo[B_ORACLE] = true;
      }
      if (!done) {
        int src = -1;  // Draco's fallback (google/draco#1117 quirk included)
        if (R.dec(pid)) src = pid;
        if (R.dec(nid)) src = nid;
        else src = p > 0 ? o.order[p - 1] : -1;
        for (int k = 0; k < 2; ++k) pred[B_PORT][k] = pred[B_ORACLE][k] = src >= 0 ? R.uv(src)[k] : 0;
      }
    }
    if (!stl.empty()) {
      const Stencil &s0 = stl[0];
      const SP &q0 = sp[0];
      // c_one / d_one : single stencil, rounded directly (frac 0)
      {
        i64 d1[2];
        if (!sim_pred(s0.L, s0.R, O, q0.sign, 0, d1)) for (int k = 0; k < 2; ++k) d1[k] = rdiv(R.uv(s0.L)[k] + R.uv(s0.R)[k], 2);
        pred[D_ONE][0] = d1[0]; pred[D_ONE][1] = d1[1]; geo[D_ONE] = true;
        i64 c1v[2];
        if (s0.B >= 0 && aff_pred(s0.L, s0.R, s0.B, O, 0, c1v)) {
          pred[C_ONE][0] = c1v[0]; pred[C_ONE][1] = c1v[1];
          // reference: same formula in long double with libm sqrt
          const auto &pl = R.pos(s0.L), &pr = R.pos(s0.R), &po = R.pos(O), &pb = R.pos(s0.B);
          long double e[3], d[3], b[3];
          for (int k = 0; k < 3; ++k) { e[k] = pr[k] - pl[k]; d[k] = po[k] - pl[k]; b[k] = pb[k] - pl[k]; }
          auto dot = [](const long double *x, const long double *y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
          auto crn = [](const long double *x, const long double *y) {
            long double c0 = x[1] * y[2] - x[2] * y[1], c1 = x[2] * y[0] - x[0] * y[2], c2 = x[0] * y[1] - x[1] * y[0];
            return sqrtl(c0 * c0 + c1 * c1 + c2 * c2); };
          long double ee = dot(e, e), sO = dot(d, e) / ee, tO = crn(e, d) / ee, sB = dot(b, e) / ee, tB = crn(e, b) / ee;
          const auto &ul = R.uv(s0.L), &ur = R.uv(s0.R), &ub = R.uv(s0.B);
          for (int k = 0; k < 2; ++k) {
            long double fk = ur[k] - ul[k], gk = ub[k] - ul[k];
            long double ref = ul[k] + sO * fk - (tO / tB) * (gk - sB * fk);
            i64 rr = (i64)llroundl(ref);
            c_ref_cmp++;
            if (rr != c1v[k]) c_ref_mismatch++;
          }
        }
        else { pred[C_ONE][0] = d1[0]; pred[C_ONE][1] = d1[1]; c_fallback_d++; }
        geo[C_ONE] = true;
        // sign statistics (oracle = orientation giving the smaller error)
        int src; int sg = sign_rule(s0, &src);
        i64 alt[2];
        if (sim_pred(s0.L, s0.R, O, -sg, 0, alt)) {
          const auto &cu = R.uv(O);
          i64 e0 = (cu[0] - d1[0]) * (cu[0] - d1[0]) + (cu[1] - d1[1]) * (cu[1] - d1[1]);
          i64 e1 = (cu[0] - alt[0]) * (cu[0] - alt[0]) + (cu[1] - alt[1]) * (cu[1] - alt[1]);
          sign_from[src]++;
          if (e1 < e0) sign_wrong[src]++;
        }
      }
      // h_cd_one: mean of c_one and d_one (single stencil)
      {
        i64 m[2] = {rdiv(q0.c[0] + q0.d[0], 2), rdiv(q0.c[1] + q0.d[1], 2)};
        setfx(H_CD_ONE, m);
      }
      // g family single stencil
      {
        double t[2];
        if (s0.B >= 0 && eq4(s0, O, 0, t)) {
          setd(G0_ONE, t);
          g0_cmp++;
          if (pred[G0_ONE][0] != pred[C_ONE][0] || pred[G0_ONE][1] != pred[C_ONE][1]) g0_mismatch++;
        } else { pred[G0_ONE][0] = pred[D_ONE][0]; pred[G0_ONE][1] = pred[D_ONE][1]; geo[G0_ONE] = true; }
        setd(G3D_ONE, q0.gc3);
        setd(GUV_ONE, q0.gcu);
      }
      // averages
      i64 sc[2] = {0, 0}, sd[2] = {0, 0};
      double s3[2] = {0, 0}, su[2] = {0, 0}, s3d[2] = {0, 0}, sud[2] = {0, 0};
      int n = (int)sp.size();
      for (auto &q : sp)
        for (int k = 0; k < 2; ++k) {
          sc[k] += q.c[k]; sd[k] += q.d[k];
          s3[k] += q.gc3[k]; su[k] += q.gcu[k]; s3d[k] += q.gd3[k]; sud[k] += q.gdu[k];
        }
      i64 ca[2] = {rdiv(sc[0], n), rdiv(sc[1], n)}, da[2] = {rdiv(sd[0], n), rdiv(sd[1], n)};
      setfx(C_AVG, ca);
      setfx(D_AVG, da);
      {  // ctx3: disagreement between the c- and d-averages, grid units, log2 buckets
        u64 dis = (uabs(ca[0] - da[0]) + uabs(ca[1] - da[1]) + (1 << (FRAC - 1))) >> FRAC;
        c3.push_back((uint8_t)min(7, bitlen(dis)));
      }
      i64 fa[2] = {rdiv(ca[0] + da[0], 2), rdiv(ca[1] + da[1], 2)};
      setfx(F_AVG, fa);
      { double t[2] = {s3[0] / n, s3[1] / n}; setd(G3D_AVG, t); }
      { double t[2] = {su[0] / n, su[1] / n}; setd(GUV_AVG, t); }
      { double t[2] = {s3d[0] / n, s3d[1] / n}; setd(G3D_DAVG, t); }
      { double t[2] = {sud[0] / n, sud[1] / n}; setd(GUV_DAVG, t); }
      // median of c over stencils (per component)
      {
        i64 m[2];
        for (int k = 0; k < 2; ++k) {
          vector<i64> v; for (auto &q : sp) v.push_back(q.c[k]);
          sort(v.begin(), v.end());
          m[k] = (v.size() & 1) ? v[v.size() / 2] : rdiv(v[v.size() / 2 - 1] + v[v.size() / 2], 2);
        }
        setfx(H_MED, m);
      }
      // weighted: p_i = (c_i+d_i)/2, w_i = 2^30 / (2^16 + |c_i-d_i|^2)  (fx units)
      {
        i64 sw = 0, swp[2] = {0, 0};
        for (auto &q : sp) {
          i64 dx = q.c[0] - q.d[0], dy = q.c[1] - q.d[1];
          u64 d2 = (u64)(dx * dx) + (u64)(dy * dy);  // |dx| <= 2^(qt+8) after clamping -> < 2^41
          i64 w = (i64)(((u64)1 << 30) / (((u64)1 << 16) + d2));
          sw += w;
          for (int k = 0; k < 2; ++k) swp[k] += w * ((q.c[k] + q.d[k]) / 2);
        }
        if (sw > 0) { i64 m[2] = {rdiv(swp[0], sw), rdiv(swp[1], sw)}; setfx(H_W, m); }
        else { pred[H_W][0] = pred[F_AVG][0]; pred[H_W][1] = pred[F_AVG][1]; geo[H_W] = true; }
      }
      // h_qw: p_i = (c_i+d_i)/2 weighted by 1 / (expected quantisation noise + c/d disagreement):
      // den_i = (G_c+G_d)/2 * 2^16/12 + |c_i-d_i|^2 (fx units), w_i = 2^36 / den_i
      {
        i64 sw = 0, swp[2] = {0, 0};
        for (auto &q : sp) {
          i64 dx = q.c[0] - q.d[0], dy = q.c[1] - q.d[1];
          u64 d2 = (u64)(dx * dx) + (u64)(dy * dy);
          u64 noise = (u64)((q.gc + q.gd) / 2) * 65536 / 12 / 65536;   // gains are 16-bit fx
          u64 den = noise + d2 + 1;
          i64 w = (i64)(((u64)1 << 36) / den);
          sw += w;
          for (int k = 0; k < 2; ++k) swp[k] += w * ((q.c[k] + q.d[k]) / 2);
        }
        if (sw > 0) { i64 m[2] = {rdiv(swp[0], sw), rdiv(swp[1], sw)}; setfx(H_QW, m); }
        else { pred[H_QW][0] = pred[F_AVG][0]; pred[H_QW][1] = pred[F_AVG][1]; geo[H_QW] = true; }
      }
    }
    if (stl.empty()) c3.push_back(8);
    // backward adaptive choice among KCAND using decoded neighbours' costs
    for (int variant : {H_ADAPT2, H_BLEND, H_ADAPT3}) {
      const int nk = variant == H_ADAPT3 ? 6 : 5;
      // h_adapt2: argmin over 5 candidates of the summed |residual| of decoded neighbours.
      // h_blend: candidates weighted by 2^20 / (1 + cost)^2 (soft choice), in fixed point.
      long cst[NK];
      for (int k = 0; k < nk; ++k) { cst[k] = 0; for (int v : nbrs) cst[k] += kcost[v][k]; }
      if (variant != H_BLEND) {
        int bk = 0;
        for (int k = 1; k < nk; ++k) if (cst[k] < cst[bk]) bk = k;
        if (nbrs.empty()) bk = 0;
        pred[variant][0] = pred[KCAND[bk]][0]; pred[variant][1] = pred[KCAND[bk]][1];
        geo[variant] = geo[KCAND[bk]];
      } else {
        i64 sw = 0, sp_[2] = {0, 0};
        for (int k = 0; k < nk; ++k) {
          i64 c = 1 + (nbrs.empty() ? 0 : (i64)(cst[k] * 4 / (long)nbrs.size()));  // quarter units per neighbour
          i64 w = ((i64)1 << 40) / (c * c) >> 20;
          if (w < 1) w = 1;
          sw += w;
          for (int j = 0; j < 2; ++j) sp_[j] += w * pred[KCAND[k]][j];
        }
        pred[variant][0] = rdiv(sp_[0], sw); pred[variant][1] = rdiv(sp_[1], sw);
        geo[variant] = geo[KCAND[0]];
      }
    }
    {
      long best = -1; int bk = 0;
      if (!nbrs.empty()) {
        for (int k = 0; k < 4; ++k) {
          long s = 0;
          for (int v : nbrs) s += kcost[v][k];
          if (best < 0 || s < best) { best = s; bk = k; }
        }
      }
      adapt_pick[bk]++;
      pred[H_ADAPT][0] = pred[KCAND[bk]][0]; pred[H_ADAPT][1] = pred[KCAND[bk]][1];
      geo[H_ADAPT] = geo[KCAND[bk]];
    }
    // residuals, contexts
    for (int v = 0; v < NVAR; ++v) {
      int r[2];
      R.residual(O, pred[v], r);
      Acc &a = acc[v];
      a.ru.push_back(r[0]); a.rv.push_back(r[1]);
      if (geo[v]) a.n_geo++;
      // ctx2: mean residual magnitude of decoded neighbours (for this variant)
      if (nbrs.empty()) a.c2.push_back(8);
      else {
        long s = 0;
        for (int w : nbrs) s += a.mag[w];
        long m = (s + (long)nbrs.size() / 2) / (long)nbrs.size();
        a.c2.push_back((uint8_t)min(7, bitlen((u64)m)));
      }
      a.mag[O] = abs(r[0]) + abs(r[1]);
    }
    for (int k = 0; k < NK; ++k) kcost[O][k] = acc[KCAND[k]].mag[O];
    // faces completed by O -> orientation majority
    for (int i = g.vc_start[O]; i < g.vc_start[O + 1]; ++i) {
      int f = g.vc_list[i] / 3;
      int a = g.vert[3 * f], b = g.vert[3 * f + 1], c = g.vert[3 * f + 2];
      if (o.rank[a] <= p && o.rank[b] <= p && o.rank[c] <= p) {
        int or_ = R.face_orient(f);
        if (or_ > 0) orient_pos++; else if (or_ < 0) orient_neg++;
      }
    }
  }
  // Draco delta-codes the orientations (bit = orientation == previous one, starting
  // from 'true'), in reverse decoding order, with one static-probability rANS bit coder.
  long bd1 = 0, bd0 = 0;
  {
    bool last = true;
    for (size_t i = b_orient.size(); i-- > 0;) { bool o_ = b_orient[i]; if (o_ == last) bd1++; else bd0++; last = o_; }
  }
  double bbits = rans_bit_cost(bd0, bd1) + 32;  // + int32 count
  for (int v = 0; v < NVAR; ++v) {
    Acc &a = acc[v];
    Ent e0 = entropy(a.ru, a.rv, nullptr, false);
    Ent e1 = entropy(a.ru, a.rv, &c1, false);
    Ent e2 = entropy(a.ru, a.rv, &a.c2, false);
    Ent e3 = entropy(a.ru, a.rv, &c3, false);
    Ent es = entropy(a.ru, a.rv, nullptr, true);
    Ent e1s = entropy(a.ru, a.rv, &c1, true);
    double a0 = adaptive_cost(a.ru, a.rv, nullptr), a1 = adaptive_cost(a.ru, a.rv, &c1);
    double a2 = adaptive_cost(a.ru, a.rv, &a.c2), a3 = adaptive_cost(a.ru, a.rv, &c3);
    Ent z0 = hybrid_cost(a.ru, a.rv, nullptr), z1 = hybrid_cost(a.ru, a.rv, &c1);
    Ent z2 = hybrid_cost(a.ru, a.rv, &a.c2), z3 = hybrid_cost(a.ru, a.rv, &c3);
    double extra = (v == B_PORT) ? bbits : 0.0;
    fprintf(out, "%s\t%d\t%s\t%s\t%d\t%d\t%.1f\t%.0f\t%.1f\t%.1f\t%.0f\t%.1f\t%.1f\t%.0f\t%.1f\t%.1f\t%.0f\t%.1f"
            "\t%.1f\t%.0f\t%.1f\t%.0f\t%.1f\t%ld\t%.1f\t%.0f\t%.1f\t%.0f\t%.1f\t%.0f\t%.1f\t%.0f\n",
            mesh, qt, oname, VNAME[v], g.NV, g.uv_pairs, e0.bits, e0.tab, a0, e1.bits, e1.tab, a1, e2.bits, e2.tab, a2,
            e3.bits, e3.tab, a3, es.bits, es.tab, e1s.bits, e1s.tab, extra, a.n_geo,
            z0.bits, z0.tab, z1.bits, z1.tab, z2.bits, z2.tab, z3.bits, z3.tab);
  }
  // Order-0 cost share of vertices without any stencil (h_adapt2), split into chart-first
  // vertices (delta from the previous vertex) and chart-second vertices (delta from the first),
  // plus an estimate for coding the second vertex in polar form with a global texel density
  // rho (header): radial error Elias-gamma coded, angle uniform over 2*pi*r grid steps.
  double nost_bits = 0, first_bits = 0, second_bits = 0, second_polar = 0;
  {
    Acc &a = acc[H_ADAPT2];
    unordered_map<int, long> cnt;
    for (size_t i = 0; i < a.ru.size(); ++i) { cnt[a.ru[i]]++; cnt[a.rv[i]]++; }
    double tot = 2.0 * a.ru.size();
    // global texel density from all stencil edges (sum |duv| / sum |dp|)
    double suv = 0, sp3 = 0;
    for (int c = 0; c < 3 * g.F; ++c) {
      int v0 = g.vert[c], v1 = g.vert[nx(c)];
      const auto &a0 = U[g.vuvi[v0]], &a1 = U[g.vuvi[v1]];
      const auto &p0 = P[g.vposi[v0]], &p1 = P[g.vposi[v1]];
      suv += hypot((double)(a1[0] - a0[0]), (double)(a1[1] - a0[1]));
      sp3 += sqrt((double)((p1[0] - p0[0]) * (p1[0] - p0[0]) + (p1[1] - p0[1]) * (p1[1] - p0[1]) + (p1[2] - p0[2]) * (p1[2] - p0[2])));
    }
    double rho = sp3 > 0 ? suv / sp3 : 0;
    for (size_t i = 0; i < a.ru.size(); ++i) {
      if (c1[i] != 8) continue;
      double b = -log2(cnt[a.ru[i]] / tot) - log2(cnt[a.rv[i]] / tot);
      nost_bits += b;
      if (fbc[i] == 1) {
        second_bits += b;
        int O = o.order[i], Nb = fbnbr[i];
        const auto &uo = U[g.vuvi[O]], &un = U[g.vuvi[Nb]];
        const auto &po = P[g.vposi[O]], &pn = P[g.vposi[Nb]];
        double r = hypot((double)(uo[0] - un[0]), (double)(uo[1] - un[1]));
        double dp = sqrt((double)((po[0] - pn[0]) * (po[0] - pn[0]) + (po[1] - pn[1]) * (po[1] - pn[1]) + (po[2] - pn[2]) * (po[2] - pn[2])));
        double dr = fabs(llround(r) - llround(rho * dp));
        second_polar += 2 * floor(log2(1 + dr)) + 1 + 1 + log2(max(1.0, 2 * M_PI * max(r, 0.5)));
      } else first_bits += b;
    }
  }
  fprintf(out, "#stats\t%s\t%d\t%s\th_adapt2_R0_bits_on_vertices_without_stencil=%.0f\tchart_first_bits=%.0f\tchart_second_bits=%.0f\tchart_second_polar_est=%.0f\tstencil_with_B=%ld\tstencil_noB=%ld\tnbr=%ld\tprev=%ld\tzero=%ld\tmean_stencils=%.3f\tn_stencils(0,1,2,3+)=%ld,%ld,%ld,%ld"
          "\tb_bits0=%ld\tb_bits1=%ld\tb_bitcost=%.1f\tsign_src(B,face,major)=%ld,%ld,%ld\tsign_wrong=%ld,%ld,%ld"
          "\tc_one_fallback_d=%ld\tc_int_vs_longdouble_mismatch=%ld/%ld\tg0_vs_c_mismatch=%ld/%ld\tadapt_pick(f,c,d,a,w)=%ld,%ld,%ld,%ld,%ld\n",
          mesh, qt, oname, nost_bits, first_bits, second_bits, second_polar, cat_stB, cat_st, cat_nbr, cat_prev, cat_zero, (double)nst_total / max(1, N), nst_hist[0], nst_hist[1], nst_hist[2], nst_hist[3],
          b_n0, b_n1, bbits, sign_from[0], sign_from[1], sign_from[2], sign_wrong[0], sign_wrong[1], sign_wrong[2],
          c_fallback_d, c_ref_mismatch, c_ref_cmp, g0_mismatch, g0_cmp, adapt_pick[0], adapt_pick[1], adapt_pick[2], adapt_pick[3], adapt_pick[4]);
  fflush(out);
  (void)verbose;
}

static void angles(Geo &g) {
  int C = 3 * g.F;
  g.cang.assign(C, 0);
  g.asum3d.assign(g.NP, 0);
  g.asumuv.assign(g.NV, 0);
  for (int c = 0; c < C; ++c) {
    const auto &pa = g.P[g.cpos[c]], &pb = g.P[g.cpos[nx(c)]], &pc = g.P[g.cpos[pv(c)]];
    double u[3], w[3];
    for (int k = 0; k < 3; ++k) { u[k] = (double)(pb[k] - pa[k]); w[k] = (double)(pc[k] - pa[k]); }
    double cx = u[1] * w[2] - u[2] * w[1], cy = u[2] * w[0] - u[0] * w[2], cz = u[0] * w[1] - u[1] * w[0];
    double a = atan2(sqrt(cx * cx + cy * cy + cz * cz), u[0] * w[0] + u[1] * w[1] + u[2] * w[2]);
    g.cang[c] = a;
    g.asum3d[g.cpos[c]] += a;
    g.asumuv[g.vert[c]] += a;
  }
}

static int process(const char *name, const char *file, int qp, const vector<int> &qts, FILE *out) {
  Obj o;
  if (!load_obj(file, o)) { fprintf(stderr, "cannot load %s\n", file); return 1; }
  Geo g;
  build(o, g);
  vector<char> used(o.v.size(), 0);
  for (auto &f : o.fv) for (int k = 0; k < 3; ++k) used[f[k]] = 1;
  g.P = quantise<3>(o.v, &used, qp);
  angles(g);
  // seam bits as Draco codes them: one bit per interior edge, static 8-bit probability
  double seam_bits = rans_bit_cost(g.interior_edges - g.seam_edges, g.seam_edges);
  double pfrac = g.interior_edges ? (double)g.seam_edges / g.interior_edges : 0;
  double h2 = (pfrac > 0 && pfrac < 1) ? -(pfrac * log2(pfrac) + (1 - pfrac) * log2(1 - pfrac)) : 0;
  long bvert = 0; for (int v = 0; v < g.NV; ++v) bvert += g.vbnd[v];
  fprintf(out, "#info\t%s\tfaces=%d\tdropped_degenerate=%d\tpositions=%d\tuv_values=%d\tuv_pairs=%d\tuv_fans=%d"
          "\tcharts=%d\tinterior_edges=%ld\tseam_edges=%ld\tboundary_edges=%ld\tnonmanifold_edges=%ld"
          "\tinconsistent_edges=%ld\tuv_boundary_vertices=%ld\tseam_bits_rans=%.1f\tseam_bits_H2=%.1f\n",
          name, g.F, o.dropped_degenerate, g.NP, g.uvvals, g.uv_pairs, g.NV, g.charts, g.interior_edges,
          g.seam_edges, g.boundary_edges, g.nonmanifold_edges, g.inconsistent_edges, bvert, seam_bits,
          g.interior_edges * h2);
  Order od, om, o5;
  dfs_order(g, od);
  mpd_order(g, om);
  mpd_order(g, o5, 5);
  if ((int)od.order.size() != g.NV || (int)om.order.size() != g.NV || (int)o5.order.size() != g.NV) {
    fprintf(stderr, "%s: traversal did not reach all vertices (%zu %zu %d)\n", name, od.order.size(),
            om.order.size(), g.NV);
    return 1;
  }
  for (int qt : qts) {
    g_qt = qt;
    vector<array<i64, 2>> U = quantise<2>(g.uvf, nullptr, qt);
    run_all(g, od, g.P, U, name, "dfs", qt, out, false);
    run_all(g, om, g.P, U, name, "mpd", qt, out, false);
    run_all(g, o5, g.P, U, name, "mpd5", qt, out, false);
  }
  return 0;
}

// ---------------------------------------------------------------- self test
// A flat grid with an affine / similarity UV map: c must be at the rounding floor.
static void selftest() {
  // integer helpers
  for (u64 x : {0ull, 1ull, 2ull, 3ull, 4ull, 15ull, 16ull, 17ull, (1ull << 62) - 1, (1ull << 62), ~0ull})
    { u64 r = isqrt64(x); assert((r * r <= x && (r + 1) * (r + 1) > x) || r == 4294967295ull); }
  for (u64 x = 0; x < 100000; ++x) { u64 r = isqrt64(x); if (!(r * r <= x && (r + 1) * (r + 1) > x)) { printf("isqrt fail %llu\n", (unsigned long long)x); exit(1); } if (r != DracoIntSqrt(x)) { printf("isqrt != draco %llu\n", (unsigned long long)x); exit(1); } }
  assert(rdiv(5, 2) == 3 && rdiv(-5, 2) == -3 && rdiv(4, 3) == 1 && rdiv(-4, 3) == -1);
  const char *path = "/tmp/uvlab_selftest.obj";
  FILE *f = fopen(path, "w");
  int n = 40;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = i + 0.3 * sin(j * 0.7), y = j, z = 0.0;
      fprintf(f, "v %g %g %g\n", x + 0.5 * y, 0.8 * y, z);
    }
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double x = i + 0.3 * sin(j * 0.7), y = j;  // uv = affine (shear+scale) of the planar position
      fprintf(f, "vt %g %g\n", 0.01 * (x + 0.5 * y) + 0.003 * y, 0.02 * (0.8 * y));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 1, d = c + 1;
      fprintf(f, "f %d/%d %d/%d %d/%d\n", a, a, b, b, d, d);
      fprintf(f, "f %d/%d %d/%d %d/%d\n", a, a, d, d, c, c);
    }
  fclose(f);
  process("selftest_affine", path, 14, {12}, stdout);
  // developable (cylinder patch) with an isometric, rotated+scaled UV map: c and d exact up to rounding
  f = fopen(path, "w");
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double a = i * 0.04 + 0.01 * sin(j * 0.9);
      fprintf(f, "v %.9g %.9g %.9g\n", 10 * cos(a), 10 * sin(a), j * 0.4 + 0.05 * cos(i * 1.3));
    }
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      double a = i * 0.04 + 0.01 * sin(j * 0.9), u = 10 * a, v = j * 0.4 + 0.05 * cos(i * 1.3);
      fprintf(f, "vt %.9g %.9g\n", 0.02 * (0.8 * u - 0.6 * v), 0.02 * (0.6 * u + 0.8 * v));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 1, d = c + 1;
      fprintf(f, "f %d/%d %d/%d %d/%d\n", a, a, b, b, d, d);
      fprintf(f, "f %d/%d %d/%d %d/%d\n", a, a, d, d, c, c);
    }
  fclose(f);
  process("selftest_isometric", path, 14, {12}, stdout);
}

int main(int argc, char **argv) {
  int qp = 14;
  vector<int> qts = {10, 12};
  vector<pair<string, string>> meshes;
  for (int i = 1; i < argc; ++i) {
    string a = argv[i];
    if (a == "--qp" && i + 1 < argc) qp = atoi(argv[++i]);
    else if (a == "--qt" && i + 1 < argc) {
      qts.clear();
      string s = argv[++i];
      size_t pos = 0;
      while (pos < s.size()) { size_t e = s.find(',', pos); if (e == string::npos) e = s.size(); qts.push_back(atoi(s.substr(pos, e - pos).c_str())); pos = e + 1; }
    } else if (a == "--selftest") { selftest(); return 0; }
    else {
      size_t eq = a.find('=');
      if (eq == string::npos) meshes.push_back({a, a});
      else meshes.push_back({a.substr(0, eq), a.substr(eq + 1)});
    }
  }
  printf("mesh\tqt\torder\tvariant\tuv_fans\tuv_pairs\tH0\tT0\tA0\tH1\tT1\tA1\tH2\tT2\tA2\tH3\tT3\tA3\tHsep\tTsep\tH1sep\tT1sep\textra\tn_geo\tZ0\tZT0\tZ1\tZT1\tZ2\tZT2\tZ3\tZT3\n");
  for (auto &m : meshes)
    if (process(m.first.c_str(), m.second.c_str(), qp, qts, stdout)) return 1;
  return 0;
}
