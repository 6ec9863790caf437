#!/usr/bin/env python3
"""RMSE (eq. 9 of Vasa & Brunnett 2014) of a decoded OBJ's texture coordinates
against the original OBJ's, computed independently of draco-uv's C++ code.

  uv_rmse.py ORIGINAL.obj DECODED.obj [QP]      (QP default 14)

Faces are matched by their corner positions quantized like Draco does (one
range over all axes, QP bits), in any rotation. Each texture vertex of the
original (a distinct position index / UV index pair) counts once. Prints
"<rmse> <texture vertices>".
"""
import math
import sys


def read_obj(path):
    positions, uvs, faces = [], [], []
    for line in open(path):
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            positions.append(tuple(float(x) for x in parts[1:4]))
        elif parts[0] == "vt":
            uvs.append(tuple(float(x) for x in parts[1:3]))
        elif parts[0] == "f":
            corners = []
            for corner in parts[1:]:
                fields = corner.split("/")
                corners.append((int(fields[0]) - 1, int(fields[1]) - 1))
            for i in range(1, len(corners) - 1):
                faces.append((corners[0], corners[i], corners[i + 1]))
    return positions, uvs, faces


def quantizer(positions, qp):
    lo = [min(p[i] for p in positions) for i in range(3)]
    extent = max(max(p[i] for p in positions) - lo[i] for i in range(3)) or 1.0
    scale = ((1 << qp) - 1) / extent
    return lambda p: tuple(math.floor((p[i] - lo[i]) * scale + 0.5)
                           for i in range(3))


def face_key(face, positions, quantize):
    """Canonical key (smallest rotation) and the rotation it starts at."""
    corners = [quantize(positions[v]) for v, _ in face]
    keys = [(tuple(corners[(s + k) % 3] for k in range(3)), s)
            for s in range(3)]
    return min(keys)


def main():
    original, decoded = read_obj(sys.argv[1]), read_obj(sys.argv[2])
    qp = int(sys.argv[3]) if len(sys.argv) > 3 else 14
    quantize = quantizer(original[0], qp)
    by_key = {}
    for face in original[2]:
        key, rotation = face_key(face, original[0], quantize)
        by_key.setdefault(key, []).append((face, rotation))
    seen, sum2 = set(), 0.0
    for face in decoded[2]:
        key, rotation = face_key(face, decoded[0], quantize)
        original_face, original_rotation = by_key[key].pop()
        for k in range(3):
            vertex = original_face[(original_rotation + k) % 3]
            if vertex in seen:
                continue
            seen.add(vertex)
            a = original[1][vertex[1]]
            b = decoded[1][face[(rotation + k) % 3][1]]
            sum2 += (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2
    print(f"{math.sqrt(sum2 / len(seen)):.12e} {len(seen)}")


if __name__ == "__main__":
    main()
