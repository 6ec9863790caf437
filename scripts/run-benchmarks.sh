#!/usr/bin/env bash
# Regenerates BENCHMARKS.md and benchmarks/ from the real-mesh corpus.
#
#   scripts/run-benchmarks.sh [CORPUS_DIR] [BUILD_DIR]
#
# CORPUS_DIR defaults to ../shared/corpus (MANIFEST.tsv and meshes/*.obj),
# BUILD_DIR to build (after ./draco-uv.sh test or demo). Runs draco_uv_eval
# at -qp 14 -cl 10 and qt 8, 10, 12 with every UV coder, times with the
# minimum of 5 runs, and renders the tables with scripts/render_benchmarks.py.
# Timings need an otherwise idle machine. Takes about 20 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."

corpus=${1:-../shared/corpus}
build=${2:-build}
out=benchmarks
schemes=draco,parallelogram,portable,multi_parallelogram,weighted,weighted_multi,auto,auto+context,weighted_multi+context
mkdir -p "${out}"

"${build}/draco/draco_uv_eval" "${corpus}/meshes" --qt 8,10,12 --qp 14 --cl 10 \
  --schemes "${schemes}" --repeat 5 --csv "${out}/corpus.csv" \
  >"${out}/corpus.txt"

# Rate-distortion charts of three representative meshes.
python=/usr/bin/python3
[[ -x ${python} ]] || python=python3
for mesh in crane_spot khr_scifihelmet param_bunny_abf; do
  "${python}" - "${out}/corpus.csv" "${out}/${mesh}.csv" "${mesh}" <<'EOF'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["mesh"] == sys.argv[3]]
with open(sys.argv[2], "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=rows[0].keys())
    writer.writeheader()
    writer.writerows(rows)
EOF
  "${python}" draco_ext/tools/draco_uv_plot.py "${out}/${mesh}.csv" \
    "${out}/${mesh}_rd.png"
  rm "${out}/${mesh}.csv"
done

"${build}/draco/draco_uv_gltf_eval" "${build}/draco-patched/testdata" \
  --schemes auto,weighted_multi --csv "${out}/gltf.csv" --quiet >"${out}/gltf.txt"

"${python}" scripts/render_benchmarks.py "${out}/corpus.csv" \
  "${corpus}/MANIFEST.tsv" "${out}/gltf.csv" >BENCHMARKS.md
echo "wrote BENCHMARKS.md and ${out}/"
