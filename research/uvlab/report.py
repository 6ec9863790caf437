#!/usr/bin/python3
"""Builds the markdown tables for REPORT.md from out/*.tsv (see common.py for cost models)."""
import os, sys, itertools
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from common import *

P = print
KINDS = ['artist', 'atlas', 'conformal']
MAIN = ['a_draco', 'a_avg', 'b_portable', 'c_one', 'd_one', 'c_avg', 'd_avg', 'f_avg', 'h_wavg', 'h_adapt2']
ALLV = [v for v in VARIANTS]


def ratio(n, qt, o, v, m):
    return cost(n, qt, o, v, m) / stock_value_bits(n, qt)


def fmt(x, d=2):
    return ('%.' + str(d) + 'f') % x


# ---------------------------------------------------------------- stock
P('## T1. Stock Draco 1.5.5 (qp 14), UV cost = size(with UV) - size(--skip TEX_COORD), min over -cl 7/10\n')
P('| mesh | kind | uv vertices | uv fans (ours) | seam edges / interior | qt | cl used | UV bytes | total bpv | seam bits (est.) | stock value bpv |')
P('|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|')
for n in MAN:
    for qt in (10, 12):
        I = INFO[n]
        P('| %s | %s | %d | %d | %d / %d | %d | %d | %d | %.2f | %.0f | %.2f |' % (
            n, kind(n), uvv(n), I['uv_fans'], I['seam_edges'], I['interior_edges'], qt, stock_cl(n, qt),
            min(STOCK[(n, qt)].values()), stock_total_bits(n, qt) / uvv(n), seam_bits(n),
            stock_value_bits(n, qt) / uvv(n)))
P()

# ---------------------------------------------------------------- per-mesh main table
for qt in (10, 12):
    for o, m in (('mpd', 'H0'), ('mpd', 'Z2')):
        P('## T2-qt%d-%s. Per-mesh bits per UV vertex, %s order, cost model %s\n' % (qt, m, o, m))
        P('| mesh | kind | uvv | stock value | ' + ' | '.join(MAIN) + ' | best (all %d variants) |' % len(ALLV))
        P('|---|---|---:|---:|' + '---:|' * len(MAIN) + '---|')
        for n in MAN:
            row = [bpv(n, qt, o, v, m) for v in MAIN]
            best = min(ALLV, key=lambda v: cost(n, qt, o, v, m))
            P('| %s | %s | %d | %.2f | ' % (n, kind(n), uvv(n), stock_value_bits(n, qt) / uvv(n)) +
              ' | '.join(fmt(x) for x in row) + ' | %s %.2f (%.3f) |' % (best, bpv(n, qt, o, best, m), ratio(n, qt, o, best, m)))
        P()

# ---------------------------------------------------------------- ratios per kind
def kind_table(qt, o, m, variants):
    P('| variant | ' + ' | '.join('%s median | %s mean' % (k, k) for k in KINDS) + ' | all-22 median | all-22 max | meshes above stock |')
    P('|---|' + '---:|---:|' * len(KINDS) + '---:|---:|---:|')
    for v in variants:
        cells = []
        for k in KINDS:
            rs = [ratio(n, qt, o, v, m) for n in REAL if kind(n) == k]
            cells += [fmt(med(rs), 3), fmt(mean(rs), 3)]
        rs = [ratio(n, qt, o, v, m) for n in REAL]
        P('| %s | ' % v + ' | '.join(cells) + ' | %.3f | %.3f | %d |' % (med(rs), max(rs), sum(r > 1 for r in rs)))
    P()


for qt in (10, 12):
    P('## T3-qt%d. Ratio variant / stock value bits per kind (mpd order, model H0 = static order-0 tables)\n' % qt)
    kind_table(qt, 'mpd', 'H0', ALLV)
for qt in (10, 12):
    P('## T4-qt%d. Same with the recommended coder model Z2 (hybrid tokens, 9 contexts from neighbours\' residual magnitude, static tables)\n' % qt)
    kind_table(qt, 'mpd', 'Z2', ALLV)

# ---------------------------------------------------------------- contexts
P('## T5. Effect of the entropy model (median ratio to stock value bits over 22 real meshes, mpd order)\n')
models = [('R0', 'order-0, no table cost'), ('H0', 'order-0 + tables'), ('S', 'u,v separate + tables'),
          ('H1', 'ctx1 edge length + tables'), ('S1', 'ctx1, u,v separate'), ('H2', 'ctx2 nbr residual + tables'),
          ('H3', 'ctx3 c/d disagreement + tables'), ('Z0', 'hybrid tokens, no ctx'), ('Z1', 'hybrid, ctx1'),
          ('Z2', 'hybrid, ctx2'), ('Z3', 'hybrid, ctx3'), ('A0', 'adaptive, no ctx'), ('A2', 'adaptive, ctx2'),
          ('A3', 'adaptive, ctx3')]
P('| variant | qt | ' + ' | '.join(m for m, _ in models) + ' |')
P('|---|---:|' + '---:|' * len(models))
for v in ['b_portable', 'c_avg', 'f_avg', 'h_wavg', 'h_adapt2']:
    for qt in (10, 12):
        P('| %s | %d | ' % (v, qt) + ' | '.join(fmt(med([ratio(n, qt, 'mpd', v, m) for n in REAL]), 3) for m, _ in models) + ' |')
P()
P('Models: ' + '; '.join('%s = %s' % mm for mm in models) + '.\n')
P('### T5b. Small vs large meshes (h_adapt2, qt 12, mpd): ratio to stock for H0 / H2 / Z0 / Z2\n')
P('| mesh | uvv | H0 | H2 | Z0 | Z2 |')
P('|---|---:|---:|---:|---:|---:|')
for n in sorted(REAL, key=uvv):
    P('| %s | %d | ' % (n, uvv(n)) + ' | '.join(fmt(ratio(n, 12, 'mpd', 'h_adapt2', m), 3) for m in ('H0', 'H2', 'Z0', 'Z2')) + ' |')
P()

# ---------------------------------------------------------------- traversal
P('## T6. Traversal order: median ratio to stock (H0 / Z2), 22 real meshes\n')
P('| variant | qt | dfs H0 | mpd H0 | mpd5 H0 | dfs Z2 | mpd Z2 | mpd5 Z2 | meshes where mpd < dfs (Z2) |')
P('|---|---:|---:|---:|---:|---:|---:|---:|---:|')
for v in ['a_draco', 'b_portable', 'c_one', 'd_one', 'c_avg', 'd_avg', 'f_avg', 'h_wavg', 'h_adapt2']:
    for qt in (10, 12):
        c = [fmt(med([ratio(n, qt, o, v, m) for n in REAL]), 3) for m in ('H0', 'Z2') for o in ('dfs', 'mpd', 'mpd5')]
        w = sum(cost(n, qt, 'mpd', v, 'Z2') < cost(n, qt, 'dfs', v, 'Z2') for n in REAL)
        P('| %s | %d | %s | %d/22 |' % (v, qt, ' | '.join(c), w))
P()
P('### T6b. Stencils available per vertex (qt 12): counts of vertices with 0 / 1 / 2 / 3+ decoded stencils\n')
P('| mesh | dfs | mpd | mpd5 |')
P('|---|---|---|---|')
for n in MAN:
    P('| %s | %s |' % (n, ' | '.join(STATS[(n, 12, o)]['n_stencils(0,1,2,3+)'] for o in ('dfs', 'mpd', 'mpd5'))))
P()

# ---------------------------------------------------------------- eq 5
P('## T7. Eq. 5 angle normalisation (mpd order, model H0)\n')
P('| qt | pair | median ratio (base) | median ratio (normalised) | meshes where normalisation helps | worst increase bpv |')
P('|---:|---|---:|---:|---:|---:|')
for qt in (10, 12):
    for base, nv in (('g0_one', 'g3d_one'), ('g0_one', 'guv_one'), ('c_avg', 'g3d_avg'), ('c_avg', 'guv_avg'),
                     ('d_avg', 'g3d_davg'), ('d_avg', 'guv_davg')):
        rb = [ratio(n, qt, 'mpd', base, 'H0') for n in REAL]
        rn = [ratio(n, qt, 'mpd', nv, 'H0') for n in REAL]
        helps = sum(cost(n, qt, 'mpd', nv, 'H0') < cost(n, qt, 'mpd', base, 'H0') for n in REAL)
        worst = max(bpv(n, qt, 'mpd', nv, 'H0') - bpv(n, qt, 'mpd', base, 'H0') for n in REAL)
        P('| %d | %s -> %s | %.3f | %.3f | %d/22 | %+.2f |' % (qt, base, nv, med(rb), med(rn), helps, worst))
P()

# ---------------------------------------------------------------- orientation / fallbacks
P('## T8. Orientation inference for the similarity predictor d (qt 12, mpd, single stencil) and fallbacks\n')
P('| mesh | from B: n / wrong | from decoded face: n / wrong | majority: n / wrong | portable orientation bits (delta-coded) | vertices w/o stencil: nbr / prev / zero | c_one fell back to d |')
P('|---|---|---|---|---:|---|---:|')
for n in MAN:
    S = STATS[(n, 12, 'mpd')]
    src = S['sign_src(B,face,major)'].split(','); wr = S['sign_wrong'].split(',')
    bb = float(RES[(n, 12, 'mpd', 'b_portable')]['extra'])
    P('| %s | %s / %s | %s / %s | %s / %s | %.0f (%.3f bpv) | %s / %s / %s | %s |' % (
        n, src[0], wr[0], src[1], wr[1], src[2], wr[2], bb, bb / uvv(n), S['nbr'], S['prev'], S['zero'], S['c_one_fallback_d']))
P()

# ---------------------------------------------------------------- calibration
P('## T9. Calibration: our estimate of Draco portable (b_portable) vs the real stock value bits\n')
P('| mesh | qt | b_portable dfs R0 | dfs H0 | mpd H0 | stock value bits | ratio dfs H0 / stock |')
P('|---|---:|---:|---:|---:|---:|---:|')
cal = []
for n in REAL:
    for qt in (10, 12):
        r = cost(n, qt, 'dfs', 'b_portable', 'H0') / stock_value_bits(n, qt)
        cal.append(r)
        P('| %s | %d | %.0f | %.0f | %.0f | %.0f | %.3f |' % (n, qt, cost(n, qt, 'dfs', 'b_portable', 'R0'),
                                                           cost(n, qt, 'dfs', 'b_portable', 'H0'),
                                                           cost(n, qt, 'mpd', 'b_portable', 'H0'),
                                                           stock_value_bits(n, qt), r))
P('\nratio dfs-H0 / stock: median %.3f, min %.3f, max %.3f\n' % (med(cal), min(cal), max(cal)))

# ---------------------------------------------------------------- recommendation evaluation
P('## T10. Candidate production configurations (value bits / stock value bits)\n')
HEADER_BITS = 8  # per attribute: predictor id + order + coder flags


def config_cost(n, qt, choices, m):
    return min(cost(n, qt, o, v, m) for o, v in choices) + HEADER_BITS


configs = [
    ('R-A: mpd, h_adapt2, Draco coder (H0)', [('mpd', 'h_adapt2')], 'H0'),
    ('R-B: mpd, h_adapt2, hybrid+ctx2 (Z2)', [('mpd', 'h_adapt2')], 'Z2'),
    ('R-C: header {dfs,mpd} x h_adapt2, Z2', [('mpd', 'h_adapt2'), ('dfs', 'h_adapt2')], 'Z2'),
    ('R-D: header {dfs,mpd} x {h_adapt2, h_wavg}, Z2', [(o, v) for o in ('dfs', 'mpd') for v in ('h_adapt2', 'h_wavg')], 'Z2'),
    ('R-E: header {dfs,mpd} x {h_adapt2, h_wavg, d_avg}, Z2', [(o, v) for o in ('dfs', 'mpd') for v in ('h_adapt2', 'h_wavg', 'd_avg')], 'Z2'),
    ('R-F: header {dfs,mpd} x {h_adapt2, h_wavg}, H0', [(o, v) for o in ('dfs', 'mpd') for v in ('h_adapt2', 'h_wavg')], 'H0'),
    ('R-D2: as R-D, plus 1 header bit: contexts on/off (min of Z0, Z2)', [(o, v) for o in ('dfs', 'mpd') for v in ('h_adapt2', 'h_wavg')], 'Zb'),
    ('R-G: mpd, h_adapt2, adaptive coder ctx2 (A2)', [('mpd', 'h_adapt2')], 'A2'),
    ('ref: mpd, b_portable (our Draco estimate), H0', [('mpd', 'b_portable')], 'H0'),
    ('ref: dfs, b_portable, H0', [('dfs', 'b_portable')], 'H0'),
    ('ref: dfs, b_portable with the new coder Z2', [('dfs', 'b_portable')], 'Z2'),
]
P('| configuration | qt | artist med | atlas med | conformal med | all-22 median | mean | min | max | above stock | ratio to our own b_portable estimate (median) |')
P('|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|')
for name, ch, m in configs:
    for qt in (10, 12):
        rs = {n: config_cost(n, qt, ch, m) / stock_value_bits(n, qt) for n in REAL}
        rb = [config_cost(n, qt, ch, m) / cost(n, qt, 'dfs', 'b_portable', 'H0') for n in REAL]
        km = [fmt(med([rs[n] for n in REAL if kind(n) == k]), 3) for k in KINDS]
        v = list(rs.values())
        P('| %s | %d | %s | %.3f | %.3f | %.3f | %.3f | %d | %.3f |' % (name, qt, ' | '.join(km), med(v), mean(v), min(v), max(v),
                                                                   sum(x > 1 for x in v), med(rb)))
P()
P('### T10b. Per mesh, configuration R-D2 (qt 10 / 12): bpv and ratio to stock value bits\n')
ch = [(o, v) for o in ('dfs', 'mpd') for v in ('h_adapt2', 'h_wavg')]
P('| mesh | kind | qt10 stock | qt10 R-D2 | ratio | choice | qt12 stock | qt12 R-D2 | ratio | choice |')
P('|---|---|---:|---:|---:|---|---:|---:|---:|---|')
for n in MAN:
    cells = []
    for qt in (10, 12):
        c = config_cost(n, qt, ch, 'Zb')
        o, v = min(ch, key=lambda ov: cost(n, qt, ov[0], ov[1], 'Zb'))
        v += '/' + ('Z2' if cost(n, qt, o, v, 'Z2') <= cost(n, qt, o, v, 'Z0') else 'Z0')
        cells += ['%.2f' % (stock_value_bits(n, qt) / uvv(n)), '%.2f' % (c / uvv(n)), '%.3f' % (c / stock_value_bits(n, qt)), '%s/%s' % (o, v)]
    P('| %s | %s | %s |' % (n, kind(n), ' | '.join(cells)))
P()

# ---------------------------------------------------------------- exhaustive subsets
P('## T11. Best header subsets (per-attribute choice, mpd order only, all variants except g*/oracle), worst of qt10/qt12 median\n')
cands = [v for v in ALLV if not v.startswith('g') and v not in ('b_oracle', 'a_first')]
for m in ('H0', 'Z2'):
    out = []
    for k in (1, 2, 3):
        for S in itertools.combinations(cands, k):
            meds = []; mxs = []
            for qt in (10, 12):
                rs = [(min(cost(n, qt, 'mpd', v, m) for v in S) + HEADER_BITS) / stock_value_bits(n, qt) for n in REAL]
                meds.append(med(rs)); mxs.append(max(rs))
            out.append((max(meds), max(mxs), k, S))
    P('model %s:\n' % m)
    P('| k | subset | worst median | worst max |')
    P('|---:|---|---:|---:|')
    for k in (1, 2, 3):
        best = sorted(o for o in out if o[2] == k)[:3]
        for b in best:
            P('| %d | %s | %.3f | %.3f |' % (k, ', '.join(b[3]), b[0], b[1]))
    P()

# ---------------------------------------------------------------- chart starts
P('## T12. Cost of vertices without any stencil (chart starts), h_adapt2, mpd, qt 12, order-0 share\n')
P('| mesh | charts | total R0 bits | no-stencil bits | share | first-vertex bits / chart | second-vertex bits / chart | polar estimate for second / chart |')
P('|---|---:|---:|---:|---:|---:|---:|---:|')
for n in REAL:
    S = STATS[(n, 12, 'mpd')]
    ch = INFO[n]['charts']
    tot = cost(n, 12, 'mpd', 'h_adapt2', 'R0')
    ns = float(S['h_adapt2_R0_bits_on_vertices_without_stencil'])
    P('| %s | %d | %.0f | %.0f | %.1f%% | %.1f | %.1f | %.1f |' % (n, ch, tot, ns, 100 * ns / tot, float(S['chart_first_bits']) / ch,
                                                             float(S['chart_second_bits']) / ch, float(S['chart_second_polar_est']) / ch))
P()
