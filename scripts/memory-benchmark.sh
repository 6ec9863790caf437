#!/usr/bin/env bash
# Peak memory (maximum resident set size, /usr/bin/time -v) of encoding and
# decoding with draco-uv's schemes (weighted, auto, weighted_multi) against Debian's stock draco_encoder and
# draco_decoder at the same settings (stock has no -uv_pred: it uses its
# own texture coordinate prediction). Target: within 1.5x of stock.
#
#   scripts/memory-benchmark.sh [BUILD_DIR] [MESH.obj...]
#
# Defaults: build/, and the corpus's largest meshes stk_abyss_track and
# khr_sheencloth (../shared/corpus). Prints a Markdown table; exits 1 if a
# ratio exceeds 1.5.
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=${1:-build}
shift || true
meshes=("$@")
corpus=${DRACO_UV_CORPUS:-../shared/corpus}
if [[ ${#meshes[@]} -eq 0 ]]; then
  meshes=("${corpus}/meshes/stk_abyss_track.obj" "${corpus}/meshes/khr_sheencloth.obj")
fi
readonly SETTINGS="-cl 10 -qp 14 -qt 12"
# "none": our build without -uv_pred (stock coding), to separate the
# schemes' cost from the build's.
readonly SCHEMES=(none weighted auto weighted_multi)
readonly LIMIT=1.5
our_encoder="${build_dir}/draco/draco_encoder"
our_decoder="${build_dir}/draco/draco_decoder"
for tool in "${our_encoder}" "${our_decoder}" /usr/bin/draco_encoder \
            /usr/bin/draco_decoder /usr/bin/time; do
  [[ -x "${tool}" ]] || { echo "missing ${tool}" >&2; exit 1; }
done

work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT

peak_mb() {  # peak_mb COMMAND...: runs it, prints its peak RSS in MB
  /usr/bin/time -v "$@" >/dev/null 2>"${work}/time.log" ||
    { cat "${work}/time.log" >&2; exit 1; }
  awk -F': ' '/Maximum resident set size/ { printf "%.1f", $2 / 1024 }' \
    "${work}/time.log"
}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }

echo "Settings: ${SETTINGS}; peak RSS in MB."
echo
echo "| mesh | scheme | encode ours | encode stock | ratio | decode ours | decode stock | ratio |"
echo "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |"
over=0
for mesh in "${meshes[@]}"; do
  [[ -f "${mesh}" ]] || { echo "missing ${mesh} (corpus absent?)" >&2; exit 1; }
  name=$(basename "${mesh}" .obj)
  # shellcheck disable=SC2086
  stock_enc=$(peak_mb /usr/bin/draco_encoder -i "${mesh}" -o "${work}/stock.drc" ${SETTINGS})
  stock_dec=$(peak_mb /usr/bin/draco_decoder -i "${work}/stock.drc" -o "${work}/stock.obj")
  for scheme in "${SCHEMES[@]}"; do
    uv_pred=()
    [[ ${scheme} == none ]] || uv_pred=(-uv_pred "${scheme}")
    # shellcheck disable=SC2086
    enc=$(peak_mb "${our_encoder}" -i "${mesh}" -o "${work}/ours.drc" ${SETTINGS} "${uv_pred[@]}")
    dec=$(peak_mb "${our_decoder}" -i "${work}/ours.drc" -o "${work}/ours.obj")
    enc_ratio=$(ratio "${enc}" "${stock_enc}")
    dec_ratio=$(ratio "${dec}" "${stock_dec}")
    echo "| ${name} | ${scheme} | ${enc} | ${stock_enc} | ${enc_ratio} | ${dec} | ${stock_dec} | ${dec_ratio} |"
    for r in "${enc_ratio}" "${dec_ratio}"; do
      awk -v r="${r}" -v l="${LIMIT}" 'BEGIN { exit !(r > l) }' && over=$((over + 1))
    done
  done
done
echo
echo "ratios above ${LIMIT}: ${over}"
[[ ${over} -eq 0 ]]
