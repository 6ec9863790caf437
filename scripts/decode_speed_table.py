#!/usr/bin/env python3
"""Issue 26's decode-speed tables from draco_uv_decode_bench --instructions.

  decode_speed_table.py BENCH_OUTPUT MANIFEST.tsv

BENCH_OUTPUT is the Markdown table draco_uv_decode_bench prints with
--instructions and one thread cap (times and instruction counts of stock
Draco's file and of every scheme). MANIFEST.tsv gives each mesh's kind.
Prints, as Markdown: instructions inside Decoder::DecodeMeshFromBuffer as a
ratio to the stock file's per mesh (wall-time ratio beside it), the median
per kind and overall and the worst mesh, the seam coder's instructions per
interior edge, and the decode-speed targets with whether they are met.
"""
import csv
import statistics
import sys

# The decode-speed targets, as instruction ratios: (median, every mesh or None).
TARGETS = {
    'weighted': (1.05, None),
    'weighted_multi': (1.10, None),
    'auto+context': (1.15, 1.25),
}
# Seam coding compared on the same prediction: (context file, stock-seam file).
SEAM_PAIRS = [('draco+context', None), ('weighted_multi+context',
                                         'weighted_multi'),
              ('auto+context', 'auto')]


def read_bench(path):
    """Scheme names and rows {mesh, edges, ms{}, instr{}} of the first
    table in |path|."""
    lines = []
    for line in open(path):
        if not line.startswith('|') and lines:
            break
        if line.startswith('|'):
            lines.append(line.strip())
    header = [c.strip() for c in lines[0].strip('|').split('|')]
    schemes = [h[:-len(' instr')] for h in header
               if h.endswith(' instr') and h != 'stock instr']
    rows = []
    for line in lines[2:]:
        cells = dict(zip(header, [c.strip() for c in
                                  line.strip('|').split('|')]))
        row = {'mesh': cells['mesh'].rsplit('.', 1)[0],
               'edges': int(cells['interior edges']),
               'ms': {'draco': float(cells['stock ms'])},
               'instr': {'draco': float(cells['stock instr'])}}
        for scheme in schemes:
            row['ms'][scheme] = float(cells[scheme + ' ms'])
            row['instr'][scheme] = float(cells[scheme + ' instr'])
        rows.append(row)
    return schemes, rows


def ratio(row, scheme, key='instr', base='draco'):
    return row[key][scheme] / row[key][base]


def per_edge(row, context, stock):
    return (row['instr'][context] - row['instr'][stock or 'draco']) / max(
        row['edges'], 1)


def print_mesh_table(schemes, rows, kinds):
    print('| mesh | kind | interior edges | stock M instr | stock ms | ' +
          ' | '.join(schemes) + ' |')
    print('| --- | --- | ---: | ---: | ---: |' + ' ---: |' * len(schemes))
    for row in rows:
        cells = ['%.3f (%.2f)' % (ratio(row, s), ratio(row, s, 'ms'))
                 for s in schemes]
        print('| %s | %s | %d | %.2f | %.2f | %s |' % (
            row['mesh'], kinds.get(row['mesh'], '?'), row['edges'],
            row['instr']['draco'] / 1e6, row['ms']['draco'],
            ' | '.join(cells)))


def print_summary(schemes, rows, kinds):
    groups = sorted(set(kinds.get(r['mesh'], '?') for r in rows))
    print('| median of | meshes | ' + ' | '.join(schemes) + ' |')
    print('| --- | ---: |' + ' ---: |' * len(schemes))
    for group in groups + ['all']:
        members = [r for r in rows
                   if group == 'all' or kinds.get(r['mesh'], '?') == group]
        cells = ['%.3f (%.2f)' % (
            statistics.median(ratio(r, s) for r in members),
            statistics.median(ratio(r, s, 'ms') for r in members))
                 for s in schemes]
        print('| %s | %d | %s |' % (group, len(members), ' | '.join(cells)))
    real = [r for r in rows if kinds.get(r['mesh']) != 'synthetic-test']
    for label, members in (('worst mesh', rows), ('worst real mesh', real)):
        worst = [max(members, key=lambda r, s=s: ratio(r, s)) for s in schemes]
        print('| %s | %d | ' % (label, len(members)) + ' | '.join(
            '%.3f %s' % (ratio(w, s), w['mesh'])
            for w, s in zip(worst, schemes)) + ' |')


def print_seams(schemes, rows):
    pairs = [(c, s) for c, s in SEAM_PAIRS
             if c in schemes and (s is None or s in schemes)]
    print('| instructions per interior edge | median | min | max |')
    print('| --- | ---: | ---: | ---: |')
    for context, stock in pairs:
        values = [per_edge(r, context, stock) for r in rows
                  if r['edges'] >= 1000]
        print('| %s − %s | %.0f | %.0f | %.0f |' % (
            context, stock or 'stock', statistics.median(values),
            min(values), max(values)))


def print_targets(schemes, rows):
    print('| decode-speed target (instructions) | median | worst | met |')
    print('| --- | ---: | ---: | --- |')
    for context, stock in SEAM_PAIRS:
        if context in schemes and (stock is None or stock in schemes):
            values = [ratio(r, context, base=stock or 'draco') for r in rows]
            print('| 1: %s ≤ 1.05 × %s | %.3f | %.3f | %s |' % (
                context, stock or 'stock', statistics.median(values),
                max(values), 'yes' if max(values) <= 1.05 else 'no'))
    for scheme, (median_max, worst_max) in TARGETS.items():
        if scheme not in schemes:
            continue
        values = [ratio(r, scheme) for r in rows]
        median, worst = statistics.median(values), max(values)
        met = median <= median_max and (worst_max is None or
                                        worst <= worst_max)
        print('| %s: %s ≤ %.2f × stock (median)%s | %.3f | %.3f | %s |' % (
            '3' if worst_max else '2', scheme, median_max,
            ', ≤ %.2f (every mesh)' % worst_max if worst_max else '',
            median, worst, 'yes' if met else 'no'))


def main():
    schemes, rows = read_bench(sys.argv[1])
    with open(sys.argv[2]) as manifest:
        kinds = {r['name']: r['kind']
                 for r in csv.DictReader(manifest, delimiter='\t')}
    print('Instructions inside Decoder::DecodeMeshFromBuffer as a ratio to '
          'the stock file (wall-time ratio in brackets):\n')
    print_mesh_table(schemes, rows, kinds)
    print()
    print_summary(schemes, rows, kinds)
    print()
    print_seams(schemes, rows)
    print()
    print_targets(schemes, rows)


if __name__ == '__main__':
    main()
