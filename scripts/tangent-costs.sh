#!/usr/bin/env bash
# What draco-uv's tangent prediction costs to decode and to encode, as issue
# #36's targets measure it, per asset of a scripts/make-tangent-assets.mjs
# folder:
#
#   scripts/tangent-costs.sh [ASSET_DIR] [BUILD_DIR] [QTG] [ROUNDS]
#
# ASSET_DIR defaults to build/tangent-assets (its MANIFEST.tsv names the
# assets and where their tangents come from), BUILD_DIR to build, QTG to 8,
# ROUNDS (interleaved wall-time rounds, minimum kept) to 5.
#
# Decode: draco_encoder writes each asset at -qp 14 -qt 12 -qn 10 -qtg QTG
# -cl 7 three times: stock (no draco-uv option), "uv" (-uv_pred auto
# -uv_seams context) and "rec" (the recommended flags: uv plus -tangent_pred
# auto). The decode cost of the tangent prediction is rec against uv: the
# same file but for the tangents' coding. Instructions are counted inside
# draco::Decoder::DecodeMeshFromBuffer (valgrind callgrind, CPU 1) of
# draco_uv_decode_bench --decode-file (one thread); wall times are that
# process's, start to exit, the minimum over ROUNDS interleaved rounds on
# CPU 1, so their ratios are diluted by the process's fixed costs.
#
# Encode: CPU time (user + system) of draco_transcoder on the GLB at -qp 14
# -qt 12 -qn 10 -qtg QTG -cl 7, stock against the recommended flags, the
# minimum over ROUNDS interleaved rounds.
#
# Prints a Markdown table and the medians; about 10 minutes for 31 assets.
set -euo pipefail
cd "$(dirname "$0")/.."

assets=${1:-build/tangent-assets}
build=${2:-build}
qtg=${3:-8}
rounds=${4:-5}
encoder=${build}/draco/draco_encoder
decoder=${build}/draco/draco_uv_decode_bench
transcoder=${build}/draco/draco_transcoder

command -v valgrind >/dev/null || { echo "Error: needs valgrind" >&2; exit 1; }
[[ -f ${assets}/MANIFEST.tsv ]] ||
  { echo "Error: no ${assets}/MANIFEST.tsv (scripts/make-tangent-assets.mjs)" >&2; exit 1; }
work=$(mktemp -d /dev/shm/tangent-costs.XXXXXX)
trap 'rm -rf "${work}"' EXIT

base=(-qp 14 -qt 12 -qn 10 -qtg "${qtg}" -cl 7)
uv=(-uv_pred auto -uv_seams context)
rec=("${uv[@]}" -tangent_pred auto)

instructions() {
  taskset -c 1 valgrind --tool=callgrind --callgrind-out-file=/dev/null \
    --collect-atstart=no \
    --toggle-collect='draco::Decoder::DecodeMeshFromBuffer*' \
    "${decoder}" --decode-file "$1" 2>&1 |
    sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}

# Prints the minimum over ROUNDS of "$@"'s CPU (encode) or wall (decode)
# seconds, each round running every command of the list once.
cpu_seconds() {
  local TIMEFORMAT='%3U %3S'
  { time taskset -c 1 "$@" >/dev/null 2>&1; } 2>&1 | awk '{print $1 + $2}'
}
wall_seconds() {
  local TIMEFORMAT='%3R'
  { time taskset -c 1 "$@" >/dev/null 2>&1; } 2>&1
}
min() { sort -g | head -1; }

echo "| asset | tangents | stock B | uv B | rec B | instr rec/uv | instr rec/stock | wall rec/uv | encode CPU s stock | rec | rec/stock |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
while IFS=$'\t' read -r -u 3 name file _ _ tangents _ _; do
  [[ ${name} == name ]] && continue
  glb=${assets}/${file}
  "${encoder}" -i "${glb}" -o "${work}/stock.drc" "${base[@]}" >/dev/null
  "${encoder}" -i "${glb}" -o "${work}/uv.drc" "${base[@]}" "${uv[@]}" >/dev/null
  "${encoder}" -i "${glb}" -o "${work}/rec.drc" "${base[@]}" "${rec[@]}" >/dev/null
  declare -A n=()
  for v in stock uv rec; do n[$v]=$(instructions "${work}/${v}.drc"); done
  : >"${work}/wall_uv"; : >"${work}/wall_rec"; : >"${work}/enc_stock"; : >"${work}/enc_rec"
  for ((r = 0; r < rounds; ++r)); do
    for v in uv rec; do
      wall_seconds "${decoder}" --decode-file "${work}/${v}.drc" >>"${work}/wall_${v}"
    done
    cpu_seconds "${transcoder}" -i "${glb}" -o "${work}/out.glb" "${base[@]}" >>"${work}/enc_stock"
    cpu_seconds "${transcoder}" -i "${glb}" -o "${work}/out.glb" "${base[@]}" "${rec[@]}" >>"${work}/enc_rec"
  done
  wall_uv=$(min <"${work}/wall_uv"); wall_rec=$(min <"${work}/wall_rec")
  enc_stock=$(min <"${work}/enc_stock"); enc_rec=$(min <"${work}/enc_rec")
  awk -v name="${name}" -v tangents="${tangents}" \
    -v s="$(stat -c %s "${work}/stock.drc")" -v u="$(stat -c %s "${work}/uv.drc")" \
    -v r="$(stat -c %s "${work}/rec.drc")" -v ns="${n[stock]}" -v nu="${n[uv]}" \
    -v nr="${n[rec]}" -v wu="${wall_uv}" -v wr="${wall_rec}" \
    -v es="${enc_stock}" -v er="${enc_rec}" 'BEGIN {
      printf "| %s | %s | %d | %d | %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f |\n",
        name, tangents, s, u, r, nr / nu, nr / ns, (wu > 0 ? wr / wu : 0),
        es, er, (es > 0 ? er / es : 0) }'
done 3<"${assets}/MANIFEST.tsv" | tee "${work}/table.md"
echo
awk -F'|' '
  function median(a, n,   i, j, t) {
    for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j)
      if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
  }
  { ++n; d[n] = $7 + 0; e[n] = $12 + 0
    if ($7 + 0 > dmax) { dmax = $7 + 0; dname = $2 }
    if ($12 + 0 > emax) { emax = $12 + 0; ename = $2 } }
  END {
    printf "decode instructions rec/uv: median %.3f, worst %.3f (%s)\n", median(d, n), dmax, dname
    printf "encode CPU rec/stock: median %.2f, worst %.2f (%s)\n", median(e, n), emax, ename
  }' "${work}/table.md"
