#!/usr/bin/env python3
"""Writes the small self-made textured meshes of testdata/ (pure Python).

  scripts/make_testdata.py [OUTDIR]   (default: testdata/)

torus_uv.obj             a torus with the analytic (u, v) parameterisation:
                         one chart, seams along two circles, wrapping UVs.
bumpy_cube_sphere.obj    a displaced sphere made of the six faces of a cube,
                         each face its own UV chart in a 3 x 2 atlas:
                         seams along the cube's edges, charts with margins.
small_torus_uv.obj,      the same two meshes with tens of vertices, for
small_cube_sphere.obj    golden files that fuzzers mutate thousands of times
                         per second.
The output is deterministic; the files are committed, this script documents
how they were made.
"""
import math
import os
import sys


def write_obj(path, header, positions, uvs, faces):
    """faces: triangles of (position index, uv index) pairs, 0-based."""
    with open(path, "w") as out:
        for line in header:
            out.write("# %s\n" % line)
        for p in positions:
            out.write("v %.6f %.6f %.6f\n" % p)
        for t in uvs:
            out.write("vt %.6f %.6f\n" % t)
        for tri in faces:
            out.write("f %s\n" % " ".join("%d/%d" % (p + 1, t + 1) for p, t in tri))


def torus(n_major=48, n_minor=24, major=1.0, minor=0.35):
    positions, uvs, faces = [], [], []
    for j in range(n_minor):
        phi = 2 * math.pi * j / n_minor
        for i in range(n_major):
            theta = 2 * math.pi * i / n_major
            ring = major + minor * math.cos(phi)
            positions.append((ring * math.cos(theta), ring * math.sin(theta),
                              minor * math.sin(phi)))
    for j in range(n_minor + 1):
        for i in range(n_major + 1):
            uvs.append((i / n_major, j / n_minor))

    def pos(i, j):
        return (j % n_minor) * n_major + (i % n_major)

    def uv(i, j):
        return j * (n_major + 1) + i

    for j in range(n_minor):
        for i in range(n_major):
            a, b = (pos(i, j), uv(i, j)), (pos(i + 1, j), uv(i + 1, j))
            c, d = (pos(i, j + 1), uv(i, j + 1)), (pos(i + 1, j + 1), uv(i + 1, j + 1))
            faces.append((a, b, d))
            faces.append((a, d, c))
    return positions, uvs, faces


# The six cube faces: (normal axis, sign, u axis, v axis).
CUBE_FACES = [(0, 1, 1, 2), (0, -1, 2, 1), (1, 1, 2, 0),
              (1, -1, 0, 2), (2, 1, 0, 1), (2, -1, 1, 0)]


def bumpy_cube_sphere(n=16, margin=0.02):
    positions, index, uvs, faces = [], {}, [], []

    def cube_point(face, i, j):
        axis, sign, ua, va = CUBE_FACES[face]
        p = [0, 0, 0]
        p[axis] = sign * n
        p[ua] = 2 * i - n
        p[va] = 2 * j - n
        return tuple(p)  # Integer cube coordinates: shared edges weld exactly.

    def position_id(key):
        if key not in index:
            x, y, z = (c / n for c in key)
            length = math.sqrt(x * x + y * y + z * z)
            x, y, z = x / length, y / length, z / length
            bump = 1.0 + 0.08 * math.sin(5 * x) * math.sin(4 * y) * math.cos(3 * z)
            index[key] = len(positions)
            positions.append((bump * x, bump * y, bump * z))
        return index[key]

    for face in range(6):
        col, row = face % 3, face // 3
        first_uv = len(uvs)
        for j in range(n + 1):
            for i in range(n + 1):
                # Equal-angle cube-sphere parameterisation inside the chart.
                s = 0.5 + math.atan(2 * i / n - 1) / (math.pi / 2)
                t = 0.5 + math.atan(2 * j / n - 1) / (math.pi / 2)
                uvs.append(((col + margin + s * (1 - 2 * margin)) / 3,
                            (row + margin + t * (1 - 2 * margin)) / 2))
        for j in range(n):
            for i in range(n):
                corner = [(position_id(cube_point(face, i + di, j + dj)),
                           first_uv + (j + dj) * (n + 1) + i + di)
                          for di, dj in ((0, 0), (1, 0), (0, 1), (1, 1))]
                faces.append((corner[0], corner[1], corner[3]))
                faces.append((corner[0], corner[3], corner[2]))
    return positions, uvs, faces


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "testdata")
    header = ["Made by scripts/make_testdata.py for draco-uv (CC0-1.0)."]
    write_obj(os.path.join(outdir, "torus_uv.obj"),
              header + ["Torus, analytic (u, v) parameterisation, one chart."],
              *torus())
    write_obj(os.path.join(outdir, "bumpy_cube_sphere.obj"),
              header + ["Displaced cube-sphere, one UV chart per cube face."],
              *bumpy_cube_sphere())
    write_obj(os.path.join(outdir, "small_torus_uv.obj"),
              header + ["Torus, 8 x 5 vertices, one chart (fuzz seeds)."],
              *torus(n_major=8, n_minor=5))
    write_obj(os.path.join(outdir, "small_cube_sphere.obj"),
              header + ["Cube-sphere, six 3 x 3 charts (fuzz seeds)."],
              *bumpy_cube_sphere(n=3))


if __name__ == "__main__":
    main()
