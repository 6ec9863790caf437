#!/usr/bin/env bash
# Regenerates BENCHMARKS.md and benchmarks/ from the real-mesh corpus.
#
#   scripts/run-benchmarks.sh [CORPUS_DIR] [BUILD_DIR]
#
# CORPUS_DIR defaults to ../shared/corpus (MANIFEST.tsv and meshes/*.obj),
# BUILD_DIR to build (after ./draco-uv.sh test or demo). Runs draco_uv_eval
# at -qp 14 -cl 10 and qt 8, 10, 12 with every UV coder, times with the
# minimum of 5 runs, and at two error targets (-uv_rmse), and renders the
# tables with scripts/render_benchmarks.py.
# Timings need an otherwise idle machine. Takes about 15 minutes.
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

# Encoding to an error target: RMSE 1.5e-3 and half a texel of a 4096
# texture, against the lossless codings that meet them.
"${build}/draco/draco_uv_eval" "${corpus}/meshes" --qt 12 --qp 14 --cl 10 \
  --schemes draco --rmse 0.0015 --texels 0.5 --repeat 1 \
  --csv "${out}/rmse.csv" >"${out}/rmse.txt"

# Rate-distortion charts of three representative meshes, with the lossy
# Laplacian coders next to the lossless ones.
for mesh in crane_spot khr_scifihelmet param_bunny_abf; do
  "${build}/draco/draco_uv_eval" "${corpus}/meshes/${mesh}.obj" --qt 6,8,10,12 \
    --qp 14 --cl 10 --repeat 1 --quiet \
    --schemes draco,weighted,weighted_multi,auto+context,laplacian_tutte,laplacian_cotan,laplacian_mv \
    --csv "${out}/${mesh}_rd.csv" --plot "${out}/${mesh}_rd.png" >/dev/null
done

"${build}/draco/draco_uv_gltf_eval" "${build}/draco-patched/testdata" \
  --schemes auto,weighted_multi --csv "${out}/gltf.csv" --quiet >"${out}/gltf.txt"

# Decoding time against stock Draco, interleaved in one process.
"${build}/draco/draco_uv_decode_bench" "${corpus}/meshes" --qp 14 --qt 12 \
  --cl 10 --schemes auto,weighted_multi --threads 2,1 --rounds 30 \
  >"${out}/decode_time.md"

python=/usr/bin/python3
[[ -x ${python} ]] || python=python3
"${python}" scripts/render_benchmarks.py "${out}/corpus.csv" \
  "${corpus}/MANIFEST.tsv" "${out}/gltf.csv" "${out}/decode_time.md" \
  "${out}/rmse.csv" >BENCHMARKS.md
echo "wrote BENCHMARKS.md and ${out}/"
