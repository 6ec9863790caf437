#!/usr/bin/env python3
"""Rate-distortion charts for draco_uv_eval (like figs. 6-7 of Vasa & Brunnett
2014): bits per UV vertex against RMSE, one curve per scheme, one panel per
mesh.

  draco_uv_plot.py RESULTS.csv OUT.png|OUT.svg
"""
import csv
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    curves = defaultdict(lambda: defaultdict(list))
    with open(sys.argv[1], newline="") as f:
        for row in csv.DictReader(f):
            curves[row["mesh"]][row["scheme"]].append(
                (float(row["bpv"]), float(row["rmse"])))
    meshes = sorted(curves)
    cols = min(3, len(meshes))
    rows = math.ceil(len(meshes) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(5 * cols, 3.8 * rows),
                             squeeze=False)
    for ax, mesh in zip(axes.flat, meshes):
        for scheme, points in sorted(curves[mesh].items()):
            points.sort()
            ax.plot([p[0] for p in points], [p[1] for p in points], marker="o",
                    label=scheme)
        ax.set_title(mesh)
        ax.set_xlabel("data rate [bits per UV vertex]")
        ax.set_ylabel("RMSE [UV units]")
        ax.set_yscale("log")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small")
    for ax in list(axes.flat)[len(meshes):]:
        ax.set_visible(False)
    fig.tight_layout()
    fig.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
