#!/usr/bin/env python3
# Copyright 2026 The draco-uv Authors.
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#      http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.
"""The per-asset tangent table of benchmarks/tangents.md.

Joins draco_uv_gltf_eval's --csv (sizes with and without -tangent_pred auto
at each -qtg) with scripts/tangent-costs.sh's Markdown table (decode
instructions, encode CPU time), per asset:

  scripts/tangent_table.py TANGENTS.csv MANIFEST.tsv [COSTS.md]

Prints a Markdown table and the medians of every ratio over all assets and
over the assets whose tangents are MikkTSpace tangents (MANIFEST.tsv's
"tangents" column), with the worst case.
"""

import csv
import statistics
import sys


def sizes(path):
  """{(asset, qtg): row} of the whole-asset rows with -tangent_pred auto."""
  rows = {}
  for row in csv.DictReader(open(path)):
    if row['primitive'] == '' and row['tangents'] == 'auto':
      rows[(row['asset'], int(row['qtg']))] = row
  return rows


def costs(path):
  """{asset name: (decode instr rec/uv, encode CPU rec/stock)}."""
  result = {}
  if path is None:
    return result
  for line in open(path):
    cells = [c.strip() for c in line.strip().strip('|').split('|')]
    if len(cells) == 11 and cells[0] not in ('asset', '---'):
      try:
        result[cells[0]] = (float(cells[5]), float(cells[10]))
      except ValueError:
        pass
  return result


def ratio(row, part):
  return int(row[part + '_bytes']) / int(row['stock_' + part + '_bytes'])


def bits(row, part):
  return 8 * int(row[part]) / int(row['tangent_values'])


def summary(name, values):
  return (f'| {name} | {statistics.median(values.values()):.3f} | '
          f'{max(values.values()):.3f} ({max(values, key=values.get)}) |')


def main():
  rows = sizes(sys.argv[1])
  manifest = {r['file']: r for r in
              csv.DictReader(open(sys.argv[2]), delimiter='\t')}
  cost = costs(sys.argv[3] if len(sys.argv) > 3 else None)
  assets = sorted({asset for asset, _ in rows})
  print('| asset | tangents | TANGENT values | tangent ratio qtg 8 | '
        'bits/vertex qtg 8 (stock) | Draco ratio qtg 8 | tangent ratio '
        'qtg 12 | bits/vertex qtg 12 (stock) | Draco ratio qtg 12 | '
        'decode instr | encode CPU |')
  print('| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | '
        '---: | ---: |')
  columns = {}
  for asset in assets:
    kind = manifest[asset]['tangents']
    name = manifest[asset]['name']
    cells = [asset, kind, rows[(asset, 8)]['tangent_values']]
    for qtg in (8, 12):
      row = rows[(asset, qtg)]
      values = {f'tangent ratio qtg {qtg}': ratio(row, 'tangent'),
                f'Draco ratio qtg {qtg}': ratio(row, 'draco')}
      for key, value in values.items():
        columns.setdefault(key, {})[(asset, kind)] = value
      cells += [f"{values[f'tangent ratio qtg {qtg}']:.3f}",
                f"{bits(row, 'tangent_bytes'):.2f} "
                f"({bits(row, 'stock_tangent_bytes'):.2f})",
                f"{values[f'Draco ratio qtg {qtg}']:.3f}"]
    decode, encode = cost.get(name, (None, None))
    if decode is not None:
      columns.setdefault('decode instructions (rec / uv)', {})[
          (asset, kind)] = decode
      columns.setdefault('encode CPU (rec / stock)', {})[
          (asset, kind)] = encode
    cells += ['' if decode is None else f'{decode:.3f}',
              '' if encode is None else f'{encode:.2f}']
    print('| ' + ' | '.join(str(c) for c in cells) + ' |')
  print()
  print('| ratio | median, all | median, MikkTSpace tangents | worst |')
  print('| --- | ---: | ---: | --- |')
  for key, values in columns.items():
    mikk = [v for (a, kind), v in values.items() if kind == 'mikktspace']
    worst = max(values, key=values.get)
    print(f'| {key} | {statistics.median(values.values()):.3f} | '
          f'{statistics.median(mikk):.3f} | {values[worst]:.3f} '
          f'({worst[0]}) |')


if __name__ == '__main__':
  main()
