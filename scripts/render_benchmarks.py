#!/usr/bin/env python3
"""Renders BENCHMARKS.md from draco_uv_eval's CSV (scripts/run-benchmarks.sh).

  render_benchmarks.py CORPUS.csv MANIFEST.tsv GLTF.csv DECODE_TIME.md \
      RMSE.csv > BENCHMARKS.md

The hand-written parts live in scripts/benchmarks_template.md; each
{{name}} there is replaced by the table of that name below.
"""
import csv
import os
import platform
import statistics
import subprocess
import sys
from collections import defaultdict

SYNTHETIC = "synthetic-test"


def load(csv_path, manifest_path):
    rows = list(csv.DictReader(open(csv_path)))
    kinds = {}
    with open(manifest_path) as f:
        header = f.readline().rstrip("\n").split("\t")
        for line in f:
            fields = line.rstrip("\n").split("\t")
            kinds[fields[header.index("name")]] = fields[header.index("kind")]
    table = defaultdict(dict)  # (mesh, qt) -> scheme -> row
    for row in rows:
        table[(row["mesh"], int(row["qt"]))][row["scheme"]] = row
    return table, kinds


def real_meshes(table, kinds, qt):
    return sorted(m for (m, q) in table if q == qt and kinds.get(m) != SYNTHETIC)


def ratio(row):
    return float(row["ratio_vs_draco"])


def dec_ratio(cell):
    return float(cell["auto"]["dec_ms"]) / float(cell["draco"]["dec_ms"])


def summary(table, kinds):
    lines = ["| qt | scheme | kind | meshes | median | mean | max | above 1.0 |",
             "| ---: | --- | --- | ---: | ---: | ---: | ---: | ---: |"]
    for qt in (10, 12):
        meshes = real_meshes(table, kinds, qt)
        for scheme in ("weighted", "weighted_multi", "auto", "auto+context",
                       "weighted_multi+context"):
            groups = defaultdict(list)
            for mesh in meshes:
                value = ratio(table[(mesh, qt)][scheme])
                groups["all real meshes"].append(value)
                groups[kinds[mesh]].append(value)
            for group, values in sorted(groups.items(),
                                        key=lambda g: g[0] != "all real meshes"):
                lines.append(
                    f"| {qt} | {scheme} | {group} | {len(values)} | "
                    f"{statistics.median(values):.3f} | "
                    f"{statistics.mean(values):.3f} | {max(values):.3f} | "
                    f"{sum(v > 1.0 for v in values)} |")
    return "\n".join(lines)


def per_mesh(table, kinds, qt):
    lines = [
        "| mesh | kind | UV vertices | stock UV bytes | stock bpv | auto UV bytes"
        " | auto bpv | auto ratio | weighted | weighted_multi | auto+context"
        " | weighted_multi+context | enc ms stock / auto | dec ms stock / auto"
        " | dec ratio |",
        "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: "
        "| ---: | ---: | ---: | ---: |"]
    for mesh in sorted(m for (m, q) in table if q == qt):
        cell = table[(mesh, qt)]
        stock, auto = cell["draco"], cell["auto"]
        lines.append(
            f"| {mesh} | {kinds.get(mesh, '')} | {stock['uv_vertices']} | "
            f"{stock['uv_bytes']} | {float(stock['bpv']):.2f} | "
            f"{auto['uv_bytes']} | {float(auto['bpv']):.2f} | "
            f"{ratio(auto):.3f} | {ratio(cell['weighted']):.3f} | "
            f"{ratio(cell['weighted_multi']):.3f} | "
            f"{ratio(cell['auto+context']):.3f} | "
            f"{ratio(cell['weighted_multi+context']):.3f} | "
            f"{float(stock['enc_ms']):.1f} / {float(auto['enc_ms']):.1f} | "
            f"{float(stock['dec_ms']):.2f} / {float(auto['dec_ms']):.2f} | "
            f"{dec_ratio(cell):.2f} |")
    meshes = real_meshes(table, kinds, qt)
    ratios = [dec_ratio(table[(m, qt)]) for m in meshes]
    lines.append("")
    lines.append(f"Decoding time auto / stock over the {len(meshes)} real "
                 f"meshes: median {statistics.median(ratios):.3f}, "
                 f"max {max(ratios):.3f}.")
    return "\n".join(lines)


def error_target(csv_path, kinds):
    """Per mesh and error target: the lossless codings that meet it at the
    coarsest -qt whose grid does, against what -uv_rmse chose."""
    rows = [r for r in csv.DictReader(open(csv_path)) if r["scheme"] == "rmse"]
    lines = ["| mesh | kind | RMSE target | -qt meeting it | stock UV bytes"
             " | auto UV bytes | -uv_rmse UV bytes | / best lossless | choice"
             " (trial encodes) | enc ms |",
             "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | --- "
             "| ---: |"]
    ratios = defaultdict(list)
    for row in sorted(rows, key=lambda r: (float(r["target_rmse"]) < 1e-3,
                                           r["mesh"])):
        target = float(row["target_rmse"])
        stock = round(int(row["uv_bytes"]) / ratio(row))
        best = min(stock, int(row["lossless_uv_bytes"]))
        chosen = int(row["uv_bytes"]) / best
        if kinds.get(row["mesh"]) != SYNTHETIC:
            ratios[target].append(chosen)
        lines.append(
            f"| {row['mesh']} | {kinds.get(row['mesh'], '')} | {target:.3g} | "
            f"{row['lossless_qt']} | {stock} | {row['lossless_uv_bytes']} | "
            f"{row['uv_bytes']} | {chosen:.3f} | {row['choice']} | "
            f"{float(row['enc_ms']):.0f} |")
    lines.append("")
    for target, values in sorted(ratios.items(), reverse=True):
        lines.append(f"RMSE {target:.3g}: -uv_rmse / best lossless over the "
                     f"{len(values)} real meshes: median "
                     f"{statistics.median(values):.3f}, max {max(values):.3f}.")
        lines.append("")
    return "\n".join(lines).rstrip()


def paper_table1(table, kinds):
    schemes = [("parallelogram", "Parallelogram (Draco)"),
               ("portable", "Portable (Draco)"), ("weighted", "Weighted (ours)"),
               ("weighted_multi", "Weighted multi (ours)")]
    lines = ["| mesh | kind | qt | RMSE | " +
             " | ".join(label for _, label in schemes) + " |",
             "| --- | --- | ---: | ---: | " + " | ".join("---:" for _ in schemes) +
             " |"]
    for mesh in real_meshes(table, kinds, 8):
        for qt in (8, 12):
            cell = table[(mesh, qt)]
            lines.append(
                f"| {mesh} | {kinds[mesh]} | {qt} | "
                f"{float(cell['draco']['rmse']):.1e} | " +
                " | ".join(f"{float(cell[s]['bpv']) - float(cell[s]['seam_bytes']) * 8 / float(cell[s]['uv_vertices']):.2f}"
                           for s, _ in schemes) + " |")
    return "\n".join(lines)


def paper_table2(table, kinds):
    schemes = ["draco", "parallelogram", "weighted", "weighted_multi", "auto"]
    largest = sorted(real_meshes(table, kinds, 12),
                     key=lambda m: -int(table[(m, 12)]["draco"]["uv_vertices"]))[:6]
    lines = ["| mesh | UV vertices | " +
             " | ".join(f"{s} enc / dec ms" for s in schemes) + " |",
             "| --- | ---: | " + " | ".join("---:" for _ in schemes) + " |"]
    for mesh in largest:
        cell = table[(mesh, 12)]
        lines.append(
            f"| {mesh} | {cell['draco']['uv_vertices']} | " +
            " | ".join(f"{float(cell[s]['enc_ms']):.1f} / "
                       f"{float(cell[s]['dec_ms']):.1f}" for s in schemes) + " |")
    return "\n".join(lines)


def gltf(csv_path):
    rows = list(csv.DictReader(open(csv_path)))
    lines = ["| scheme | assets | with UVs | stock bytes | bytes | ratio | "
             "worst asset ratio | requiring the extension | round trips ok |",
             "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for scheme in sorted({r["scheme"] for r in rows}):
        group = [r for r in rows if r["scheme"] == scheme]
        stock = sum(int(r["stock_bytes"]) for r in group)
        ours = sum(int(r["bytes"]) for r in group)
        worst = max(int(r["bytes"]) / int(r["stock_bytes"]) for r in group)
        lines.append(
            f"| {scheme} | {len(group)} | "
            f"{sum(int(r['textured_primitives']) > 0 for r in group)} | "
            f"{stock} | {ours} | {ours / stock:.3f} | {worst:.3f} | "
            f"{sum(r['requires_extension'] == '1' for r in group)} | "
            f"{sum(r['round_trip_ok'] == '1' for r in group)} |")
    return "\n".join(lines)


def machine():
    cpu = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    compiler = subprocess.run(["c++", "--version"], capture_output=True,
                              text=True).stdout.splitlines()[0]
    return (f"{os.cpu_count()} cores of {cpu}, {platform.system()} "
            f"{platform.release()}, {compiler}, Release build (-O3)")


def main():
    table, kinds = load(sys.argv[1], sys.argv[2])
    parts = {
        "machine": machine(),
        "summary": summary(table, kinds),
        "per_mesh_qt10": per_mesh(table, kinds, 10),
        "per_mesh_qt12": per_mesh(table, kinds, 12),
        "paper_table1": paper_table1(table, kinds),
        "paper_table2": paper_table2(table, kinds),
        "gltf": gltf(sys.argv[3]),
        "decode_time": open(sys.argv[4]).read().strip(),
        "error_target": error_target(sys.argv[5], kinds),
    }
    template = open(os.path.join(os.path.dirname(__file__),
                                 "benchmarks_template.md")).read()
    for name, text in parts.items():
        template = template.replace("{{" + name + "}}", text)
    sys.stdout.write(template)


if __name__ == "__main__":
    main()
