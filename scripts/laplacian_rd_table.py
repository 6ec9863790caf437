#!/usr/bin/env python3
"""Paper-Table-1 comparison from a draco_uv_eval CSV: bits per UV vertex at a
target RMSE, per mesh and scheme, and which family wins per mesh kind.

    scripts/laplacian_rd_table.py eval.csv CORPUS_DIR [--target 1.5e-3] [--curves]
    scripts/laplacian_rd_table.py eval.csv CORPUS_DIR --anchors LABEL=CSV ...
        [--scheme laplacian_mv]

The target RMSE is a fraction of each mesh's UV range (the larger extent of u
and v in its OBJ). A scheme's bpv at the target is interpolated linearly in
log(RMSE)-log(bpv) between the two qt points that bracket it; a scheme whose
points do not bracket the target gets no value. Laplacian schemes are the
`laplacian_*` names; every other scheme counts as a traversal scheme.
With --curves, also every mesh's rate-distortion points (bpv / RMSE per qt
and scheme). With --anchors, compares one Laplacian scheme (--scheme) of
eval.csv, measured with the default anchors, against the same scheme in
each LABEL=CSV (measured with one fixed -uv_anchors setting each): bpv at
the target per setting, the best of them and the default's ratio to it.
Prints Markdown.
"""
import argparse
import csv
import math
import os
from collections import defaultdict


def uv_range(path):
    lo, hi = [math.inf, math.inf], [-math.inf, -math.inf]
    with open(path) as f:
        for line in f:
            if line.startswith('vt '):
                parts = line.split()
                for k in range(2):
                    value = float(parts[1 + k])
                    lo[k] = min(lo[k], value)
                    hi[k] = max(hi[k], value)
    return max(hi[0] - lo[0], hi[1] - lo[1])


def bpv_at(points, target):
    """points: [(rmse, bpv)]; log-log interpolation at rmse == target."""
    points = sorted(p for p in points if p[0] > 0 and p[1] > 0)
    for (r0, b0), (r1, b1) in zip(points, points[1:]):
        if r0 <= target <= r1 and r1 > r0:
            t = (math.log(target) - math.log(r0)) / (math.log(r1) - math.log(r0))
            return math.exp(math.log(b0) + t * (math.log(b1) - math.log(b0)))
    return None


def read_manifest(corpus):
    kinds, files, sizes = {}, {}, {}
    with open(os.path.join(corpus, 'MANIFEST.tsv')) as f:
        for row in csv.DictReader(f, delimiter='\t'):
            kinds[row['name']] = row['kind']
            files[row['name']] = os.path.join(corpus, row['file'])
            sizes[row['name']] = (int(row['uv_vertices']),
                                  int(row['uv_charts']))
    return kinds, files, sizes


def read_points(path, scheme=None):
    """{mesh: {scheme: [(rmse, bpv)]}} of a draco_uv_eval CSV, and
    {(mesh, qt): {scheme: (bpv, rmse)}}; only |scheme| if given."""
    points = defaultdict(lambda: defaultdict(list))
    by_qt = defaultdict(dict)
    for row in csv.DictReader(open(path)):
        if scheme is not None and row['scheme'] != scheme:
            continue
        points[row['mesh']][row['scheme']].append(
            (float(row['rmse']), float(row['bpv'])))
        by_qt[(row['mesh'], int(row['qt']))][row['scheme']] = (
            float(row['bpv']), float(row['rmse']))
    return points, by_qt


def print_anchor_comparison(args, kinds, files, sizes):
    """The default's bpv at the target against fixed anchor settings."""
    settings = [a.split('=', 1) for a in args.anchors]
    fixed = {label: read_points(path, args.scheme)[0]
             for label, path in settings}
    default = read_points(args.csv, args.scheme)[0]
    labels = [label for label, _ in settings]
    print(f'{args.scheme}: bpv at RMSE = {args.target:g} x UV range per '
          '-uv_anchors setting (- = not bracketed)\n')
    print('| mesh | kind | UV vertices | charts | ' + ' | '.join(labels) +
          ' | best | default | default / best |')
    print('|' + ' --- |' * (len(labels) + 7))
    ratios = []
    for mesh in sorted(default, key=lambda m: (kinds.get(m, '?'), m)):
        target = args.target * uv_range(files[mesh])
        values = [bpv_at(fixed[label][mesh][args.scheme], target)
                  for label in labels]
        ours = bpv_at(default[mesh][args.scheme], target)
        known = [v for v in values if v is not None]
        best = min(known) if known else None
        ratio = ours / best if ours and best else None
        if ratio is not None:
            ratios.append((ratio, mesh))
        cells = ['-' if v is None else f'{v:.2f}' for v in
                 values + [best, ours]]
        vertices, charts = sizes.get(mesh, ('?', '?'))
        print(f'| {mesh} | {kinds.get(mesh, "?")} | {vertices} | {charts} | '
              + ' | '.join(cells) +
              f' | {"-" if ratio is None else f"{ratio:.3f}"} |')
    if ratios:
        worst = max(ratios)
        within = sum(r <= 1.05 for r, _ in ratios)
        print(f'\nWithin 5 % of the best on {within} of {len(ratios)} '
              f'meshes; worst {worst[0]:.3f} ({worst[1]}).')


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('csv')
    parser.add_argument('corpus')
    parser.add_argument('--target', type=float, default=1.5e-3)
    parser.add_argument('--curves', action='store_true')
    parser.add_argument('--anchors', nargs='+', metavar='LABEL=CSV')
    parser.add_argument('--scheme', default='laplacian_mv')
    args = parser.parse_args()
    kinds, files, sizes = read_manifest(args.corpus)
    if args.anchors:
        print_anchor_comparison(args, kinds, files, sizes)
        return
    points, by_qt = read_points(args.csv)
    schemes = sorted({s for m in points.values() for s in m},
                     key=lambda s: (s.startswith('laplacian'), s))
    print(f'bpv at RMSE = {args.target:g} x UV range '
          '(log-log interpolation between qt points; - = not bracketed)\n')
    print('| mesh | kind | ' + ' | '.join(schemes) +
          ' | best Laplacian / best traversal |')
    print('|' + ' --- |' * (len(schemes) + 3))
    by_kind = defaultdict(list)
    for mesh in sorted(points, key=lambda m: (kinds.get(m, '?'), m)):
        target = args.target * uv_range(files[mesh]) if mesh in files else None
        values = {s: bpv_at(points[mesh][s], target) if target else None
                  for s in schemes}
        lap = [v for s, v in values.items() if s.startswith('laplacian') and v]
        trav = [v for s, v in values.items()
                if not s.startswith('laplacian') and v]
        ratio = min(lap) / min(trav) if lap and trav else None
        if ratio is not None:
            by_kind[kinds.get(mesh, '?')].append(ratio)
        cells = ['-' if values[s] is None else f'{values[s]:.2f}'
                 for s in schemes]
        print(f'| {mesh} | {kinds.get(mesh, "?")} | ' + ' | '.join(cells) +
              f' | {"-" if ratio is None else f"{ratio:.3f}"} |')
    print('\n| kind | meshes compared | Laplacian wins | median ratio |')
    print('| --- | --- | --- | --- |')
    for kind, ratios in sorted(by_kind.items()):
        ratios.sort()
        median = ratios[len(ratios) // 2] if len(ratios) % 2 else \
            0.5 * (ratios[len(ratios) // 2 - 1] + ratios[len(ratios) // 2])
        wins = sum(r < 1 for r in ratios)
        print(f'| {kind} | {len(ratios)} | {wins} | {median:.3f} |')
    if args.curves:
        print_curves(points, by_qt, schemes, kinds)


def print_curves(points, by_qt, schemes, kinds):
    print('\nRate-distortion points: bpv / RMSE (UV units) per qt\n')
    for mesh in sorted(points, key=lambda m: (kinds.get(m, '?'), m)):
        print(f'{mesh} ({kinds.get(mesh, "?")})\n')
        print('| qt | ' + ' | '.join(schemes) + ' |')
        print('|' + ' --- |' * (len(schemes) + 1))
        for qt in sorted(q for m, q in by_qt if m == mesh):
            cells = []
            for s in schemes:
                value = by_qt[(mesh, qt)].get(s)
                cells.append('-' if value is None
                             else f'{value[0]:.2f} / {value[1]:.2e}')
            print(f'| {qt} | ' + ' | '.join(cells) + ' |')
        print()


if __name__ == '__main__':
    main()
