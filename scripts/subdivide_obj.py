#!/usr/bin/env python3
"""Splits every triangle of a textured OBJ into n^2 (each edge into n parts).

    scripts/subdivide_obj.py in.obj out.obj [--split N]

Makes big benchmark meshes from corpus meshes (the Laplacian UV coder's speed
target is stated for a 300k-vertex mesh). New positions and texture
coordinates are interpolated linearly inside each triangle, so UV seams stay
where they are: a position shared by two texture vertices keeps two. Reads
`v`, `vt` and triangular `f v/vt` records; everything else is dropped.
"""
import argparse


def read_obj(path):
    positions, uvs, faces = [], [], []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == 'v':
                positions.append(tuple(float(x) for x in parts[1:4]))
            elif parts[0] == 'vt':
                uvs.append(tuple(float(x) for x in parts[1:3]))
            elif parts[0] == 'f':
                corners = []
                for token in parts[1:]:
                    fields = token.split('/')
                    corners.append((int(fields[0]) - 1, int(fields[1]) - 1))
                if len(corners) != 3:
                    raise SystemExit('only triangles are supported')
                faces.append(corners)
    return positions, uvs, faces


def subdivide(positions, uvs, faces, n):
    positions, uvs = list(positions), list(uvs)
    pos_ids, uv_ids = {}, {}

    def point(table, values, corners, weights):
        # A lattice point is identified by its integer barycentric weights on
        # the corners it depends on, so neighbouring faces share it.
        key = tuple(sorted((c, w) for c, w in zip(corners, weights) if w))
        if len(key) == 1:
            return key[0][0]
        if key not in table:
            table[key] = len(values)
            values.append(tuple(
                sum(values[c][k] * w for c, w in key) / n
                for k in range(len(values[key[0][0]]))))
        return table[key]

    out = []
    for face in faces:
        p = [c[0] for c in face]
        t = [c[1] for c in face]
        grid = {}
        for i in range(n + 1):
            for j in range(n + 1 - i):
                w = (n - i - j, i, j)
                grid[i, j] = (point(pos_ids, positions, p, w),
                              point(uv_ids, uvs, t, w))
        for i in range(n):
            for j in range(n - i):
                out.append((grid[i, j], grid[i + 1, j], grid[i, j + 1]))
                if i + j + 1 < n:
                    out.append((grid[i + 1, j], grid[i + 1, j + 1],
                                grid[i, j + 1]))
    return positions, uvs, out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('input')
    parser.add_argument('output')
    parser.add_argument('--split', type=int, default=2)
    args = parser.parse_args()
    positions, uvs, faces = subdivide(*read_obj(args.input), args.split)
    with open(args.output, 'w') as f:
        f.write('# %s split %d\n' % (args.input, args.split))
        f.writelines('v %.9g %.9g %.9g\n' % p for p in positions)
        f.writelines('vt %.9g %.9g\n' % t for t in uvs)
        f.writelines('f %d/%d %d/%d %d/%d\n' %
                     tuple(x + 1 for c in face for x in c) for face in faces)


if __name__ == '__main__':
    main()
