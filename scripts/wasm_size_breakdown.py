#!/usr/bin/env python3
# Where a WebAssembly build's code grows: compares the function bodies of two
# .wasm files that carry a "name" section (linked with --profiling-funcs,
# which keeps the names and changes no code; scripts/web-sizes.sh
# --breakdown links them) and prints, as Markdown, the code section sizes,
# the bytes of functions only in the first file grouped by what they belong
# to, and the functions whose size changed most.
#
#   scripts/wasm_size_breakdown.py OURS.wasm STOCK.wasm [--list CATEGORY]
#
# Sizes are raw bytes of function bodies (code section), before gzip.
# Identical function bodies are folded by binaryen at -O2 and above, so
# template instances that compile to the same code count once, under one of
# their names.
import argparse
import collections
import re

# What a function belongs to, by the first pattern its name matches.
CATEGORIES = [
    ('Laplacian coder, its solver and Eigen',
     r'Laplacian|Cholesky|Eigen|DenseFront|DenseDiagonal|DenseColumns|'
     r'DenseRows|MatrixGraph|Dissect|UvCharts|UseFixedCacheSizes'),
    ('seam coder and its Edgebreaker traversals',
     r'UvSeam|DecodeUvSeams|EncodeUvSeams|SeamBit|Opposites'),
    ('weighted prediction',
     r'Weighted|UvStencil|UvComputedFrame|UvLookahead|UvProcessingOrder|'
     r'uv_order_internal|uv_prediction_internal|UvMeanOfQ16|'
     r'BuildMaxDegreeOrder'),
    ('residual coder', r'UvResidual'),
    ('Draco Edgebreaker instances', r'Edgebreaker'),
    ('Draco prediction scheme factories', r'PredictionScheme'),
    ('libc++ and runtime', r'^std::|^void std::|^bool std::|^unsigned int std::|'
                           r'^__|^dl|^operator|^round'),
]


def leb128(data, pos):
    result = shift = 0
    while True:
        byte = data[pos]
        pos += 1
        result |= (byte & 0x7f) << shift
        shift += 7
        if not byte & 0x80:
            return result, pos


def skip_limits(data, pos):
    flags, pos = leb128(data, pos)
    _, pos = leb128(data, pos)
    if flags & 1:
        _, pos = leb128(data, pos)
    return pos


def function_sizes(path):
    """{name: body bytes} of the defined functions of a .wasm file."""
    data = open(path, 'rb').read()
    pos = 8
    imported_functions = 0
    bodies = []
    names = {}
    while pos < len(data):
        section = data[pos]
        size, pos = leb128(data, pos + 1)
        end = pos + size
        if section == 2:  # imports: function indices start after them
            count, p = leb128(data, pos)
            for _ in range(count):
                for _ in range(2):  # module and field names
                    length, p = leb128(data, p)
                    p += length
                kind = data[p]
                p += 1
                if kind == 0:
                    _, p = leb128(data, p)
                    imported_functions += 1
                elif kind == 1:
                    p = skip_limits(data, p + 1)
                elif kind == 2:
                    p = skip_limits(data, p)
                elif kind == 3:
                    p += 2
        elif section == 10:  # code
            count, p = leb128(data, pos)
            for _ in range(count):
                length, q = leb128(data, p)
                bodies.append(q - p + length)
                p = q + length
        elif section == 0:  # custom: the "name" section's function names
            length, p = leb128(data, pos)
            if data[p:p + length] == b'name':
                p += length
                while p < end:
                    kind = data[p]
                    sub_size, p = leb128(data, p + 1)
                    sub_end = p + sub_size
                    if kind == 1:
                        count, p = leb128(data, p)
                        for _ in range(count):
                            index, p = leb128(data, p)
                            length, p = leb128(data, p)
                            names[index] = data[p:p + length].decode(
                                'utf-8', 'replace')
                            p += length
                    p = sub_end
        pos = end
    sizes = collections.Counter()
    for i, size in enumerate(bodies):
        sizes[names.get(imported_functions + i, f'func{i}')] += size
    return sizes


def category(name):
    for label, pattern in CATEGORIES:
        if re.search(pattern, name):
            return label
    return 'other'


def short(name, width=110):
    return name if len(name) <= width else name[:width - 1] + '…'


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument('ours')
    parser.add_argument('stock')
    parser.add_argument('--list', metavar='CATEGORY',
                        help='also list the new functions of this category')
    parser.add_argument('--top', type=int, default=12)
    args = parser.parse_args()
    ours = function_sizes(args.ours)
    stock = function_sizes(args.stock)
    new = {n: s for n, s in ours.items() if n not in stock}
    gone = {n: s for n, s in stock.items() if n not in ours}
    changed = {n: ours[n] - stock[n] for n in ours if n in stock}

    print('| | functions | code bytes |')
    print('| --- | ---: | ---: |')
    print(f'| ours | {len(ours):,} | {sum(ours.values()):,} |')
    print(f'| stock | {len(stock):,} | {sum(stock.values()):,} |')
    print(f'| difference | {len(ours) - len(stock):+,} | '
          f'{sum(ours.values()) - sum(stock.values()):+,} |')
    print()
    by_category = collections.Counter()
    count = collections.Counter()
    for name, size in new.items():
        by_category[category(name)] += size
        count[category(name)] += 1
    print('| functions only in ours, by what they belong to | functions | '
          'code bytes |')
    print('| --- | ---: | ---: |')
    for label, size in by_category.most_common():
        print(f'| {label} | {count[label]} | {size:,} |')
    print(f'| functions of stock that ours no longer has | {len(gone)} | '
          f'{-sum(gone.values()):+,} |')
    print(f'| functions of both, size change | {len(changed)} | '
          f'{sum(changed.values()):+,} |')
    print()
    print(f'Largest functions only in ours (top {args.top}):')
    print()
    print('| code bytes | function |')
    print('| ---: | --- |')
    for name, size in sorted(new.items(), key=lambda x: -x[1])[:args.top]:
        print(f'| {size:,} | `{short(name)}` |')
    print()
    print('Functions of both whose size changed most:')
    print()
    print('| stock | ours | function |')
    print('| ---: | ---: | --- |')
    for name in sorted(changed, key=lambda n: -abs(changed[n]))[:args.top]:
        if changed[name]:
            print(f'| {stock[name]:,} | {ours[name]:,} | `{short(name)}` |')
    if args.list:
        print()
        print(f'New functions in "{args.list}":')
        print()
        for name, size in sorted(new.items(), key=lambda x: -x[1]):
            if category(name) == args.list:
                print(f'    {size:7,}  {name}')


if __name__ == '__main__':
    main()
