#!/usr/bin/env bash
# Decode cost of the error target's choices (benchmarks/laplacian.md,
# "Decode cost of the error target's choice"): per corpus mesh, what
# draco_encoder -uv_rmse R chooses with the default -uv_decode_limit and with
# -uv_decode_limit none, its estimate of the Laplacian's decode cost, and the
# decode instructions (valgrind callgrind, inside
# Decoder::DecodeMeshFromBuffer, one thread) of those files and of
# -uv_pred laplacian_mv -qt 12 against the stock-coded file (-qt 12), all at
# -cl 10 -qp 14.
#
#   scripts/rmse-decode-cost.sh [--rmse R] [--meshes a,b,...] [--node]
#       [--build DIR] [--package DIR] [--corpus DIR] [--keep DIR]
#
#   --rmse      the target (default 0.0015)
#   --meshes    comma-separated corpus names (MANIFEST.tsv's first column;
#               default: all but the khr_multiuvtest toys)
#   --node      also time the same files in Node.js with our web package
#               against npm draco3d (benchmarks/web_decode_bench.js, 10
#               rounds); prints its tables after this one
#   --build     native build folder (default build), --package our web
#               package (default build-web/draco3d-uv), --corpus the corpus
#               (default ../shared/corpus), --keep DIR keeps the files there
#
# About 25 minutes for the corpus on a quiet 2-core VM, most of it callgrind
# on the Laplacian files.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="${root}/build"
package="${root}/build-web/draco3d-uv"
corpus="${root}/../shared/corpus"
rmse=0.0015
meshes=""
node=0
keep=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --rmse) rmse="$2"; shift ;;
    --meshes) meshes="$2"; shift ;;
    --node) node=1 ;;
    --build) build="$(realpath "$2")"; shift ;;
    --package) package="$(realpath "$2")"; shift ;;
    --corpus) corpus="$(realpath "$2")"; shift ;;
    --keep) keep="$2"; shift ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
  shift
done
encoder="${build}/draco/draco_encoder"
bench="${build}/draco/draco_uv_decode_bench"
command -v valgrind >/dev/null || { echo "needs valgrind" >&2; exit 1; }
if [[ -n "${keep}" ]]; then
  mkdir -p "${keep}"
  work="$(realpath "${keep}")"
else
  work="$(mktemp -d)"
  trap 'rm -rf "${work}"' EXIT
fi

instructions() {  # FILE: instructions of its decode
  taskset -c 0 valgrind --tool=callgrind --collect-atstart=no \
    '--toggle-collect=draco::Decoder::DecodeMeshFromBuffer(*)' \
    "--callgrind-out-file=${work}/profile" "${bench}" --decode-file "$1" \
    >/dev/null 2>"${work}/valgrind.log"
  awk '/^totals:/ {print $2}' "${work}/profile"
}
choice() { sed -E 's/.*-> ([^,]*),.*/\1/' <<<"$1"; }  # SUMMARY LINE
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }

index="${work}/index.tsv"
printf 'mesh\tkind\tuv_vertices\tscheme\tfile\tbytes\n' >"${index}"
echo "| mesh | UV vertices | -uv_rmse ${rmse} | with -uv_decode_limit none |" \
     "estimated Laplacian decode | laplacian_mv -qt 12 | -uv_rmse file |" \
     "-uv_decode_limit none file |"
echo "| --- | ---: | --- | --- | ---: | ---: | ---: | ---: |"
# MANIFEST.tsv columns: name file ... kind(6) triangles positions uv_vertices(9)
while IFS=$'\t' read -r name file _ _ _ kind _ _ uv_vertices _; do
  [[ "${name}" == name ]] && continue
  if [[ -n "${meshes}" ]]; then
    [[ ",${meshes}," == *",${name},"* ]] || continue
  elif [[ "${name}" == khr_multiuvtest* ]]; then
    continue
  fi
  obj="${corpus}/${file}"
  echo "encoding ${name}" >&2
  base=(-i "${obj}" -cl 10 -qp 14)
  "${encoder}" "${base[@]}" -o "${work}/${name}.stock.drc" -qt 12 >/dev/null
  "${encoder}" "${base[@]}" -o "${work}/${name}.laplacian_mv.drc" -qt 12 \
    -uv_pred laplacian_mv >/dev/null
  limited=$("${encoder}" "${base[@]}" -o "${work}/${name}.rmse.drc" \
    -uv_rmse "${rmse}" | grep '^UV error target')
  unlimited=$("${encoder}" "${base[@]}" -o "${work}/${name}.rmse_nolimit.drc" \
    -uv_rmse "${rmse}" -uv_decode_limit none | grep '^UV error target')
  estimate=$(grep -oE 'estimated at [0-9.]+x' <<<"${limited}" |
    sed -E 's/estimated at //' || echo -)
  for scheme in stock laplacian_mv rmse rmse_nolimit; do
    printf '%s\t%s\t%s\t%s\t%s\t%s\n' "${name}" "${kind}" "${uv_vertices}" \
      "${scheme}" "${name}.${scheme}.drc" \
      "$(stat -c %s "${work}/${name}.${scheme}.drc")" >>"${index}"
  done
  stock=$(instructions "${work}/${name}.stock.drc")
  laplacian=$(instructions "${work}/${name}.laplacian_mv.drc")
  limited_instructions=$(instructions "${work}/${name}.rmse.drc")
  if cmp -s "${work}/${name}.rmse.drc" "${work}/${name}.rmse_nolimit.drc"; then
    unlimited_instructions=${limited_instructions}
  else
    unlimited_instructions=$(instructions "${work}/${name}.rmse_nolimit.drc")
  fi
  echo "| ${name} | ${uv_vertices} | $(choice "${limited}") |" \
       "$(choice "${unlimited}") | ${estimate} |" \
       "$(ratio "${laplacian}" "${stock}") |" \
       "$(ratio "${limited_instructions}" "${stock}") |" \
       "$(ratio "${unlimited_instructions}" "${stock}") |"
done <"${corpus}/MANIFEST.tsv"

if [[ ${node} -eq 1 ]]; then
  echo
  node --expose-gc --single-threaded "${root}/benchmarks/web_decode_bench.js" \
    --ours "${package}" --draco3d "${root}/tests/web/node_modules/draco3d" \
    --rounds 10 --warmup 2 "${index}"
fi
