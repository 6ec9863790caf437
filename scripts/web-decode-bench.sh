#!/bin/bash
# Copyright 2026 The draco-uv Authors.
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#      http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.
#
# WebAssembly decode times in Node.js, draco-uv's web package against npm
# draco3d 1.5.9, over the shared corpus (benchmarks/web_decode.md reports a
# run). Encodes every corpus mesh with the native draco_encoder at the
# benchmarks' settings (-cl 10 -qp 14 -qt 12) once stock-coded and once per
# UV scheme below, then times the decodes in one Node.js process
# (benchmarks/web_decode_bench.js) and prints its Markdown to stdout.
#
#   scripts/web-decode-bench.sh [--quick] [--tangents] [--rounds N]
#       [--warmup N] [--meshes a,b,...] [--build DIR] [--package DIR]
#       [--corpus DIR] [--clock cpu|wall] [--tsv FILE] [--keep DIR]
#
#   --tangents  the tangent schemes instead: the corpus's glTF assets
#               (CORPUS/gltf/*.gltf, those with TANGENT) and
#               testdata/*_tangents.glb, each stock-coded and with
#               -tangent_pred auto, mikktspace and geometric at -cl 10
#               -qp 14 -qt 12 -qn 10 -qtg 8, UVs stock-coded so that npm
#               draco3d reads the stock file (--meshes: file names without
#               extension)
#   --quick     smoke run: 4 small and medium meshes, 3 rounds, 1 warm-up
#   --rounds N  timed rounds per mesh (default 15); --warmup N (default 3)
#   --meshes    comma-separated corpus names (MANIFEST.tsv's first column)
#   --build     native build folder with draco/draco_encoder (default build)
#   --package   our web package (default build-web/draco3d-uv)
#   --corpus    corpus folder with MANIFEST.tsv (default ../shared/corpus)
#   --clock     clock of the per-mesh tables: cpu (default), the process's
#               CPU time, which preemption does not inflate, or wall; the
#               summary gives both
#   --tsv FILE  also write every file's minimum and median times
#   --keep DIR  encode into DIR and keep it (files already there are reused)
#
# npm draco3d comes from tests/web/node_modules (tests/web/install-packages.sh).
# The full corpus takes about 5 minutes at 25 rounds (the Laplacian files
# take most of it); --quick about 15 seconds.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
build="${root}/build"
package="${root}/build-web/draco3d-uv"
corpus="${root}/../shared/corpus"
rounds=15
warmup=3
meshes=""
tsv=""
clock=cpu
keep=""
tangents=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --tangents) tangents=1 ;;
    --quick) rounds=3; warmup=1
             meshes=khr_waterbottle,crane_spot,khr_scifihelmet
             meshes+=,param_armadillo_xatlas ;;
    --rounds) rounds="$2"; shift ;;
    --warmup) warmup="$2"; shift ;;
    --meshes) meshes="$2"; shift ;;
    --build) build="$(realpath "$2")"; shift ;;
    --package) package="$(realpath "$2")"; shift ;;
    --corpus) corpus="$(realpath "$2")"; shift ;;
    --tsv) tsv="$(realpath "$2")"; shift ;;
    --clock) clock="$2"; shift ;;
    --keep) keep="$2"; shift ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
  shift
done

encoder="${build}/draco/draco_encoder"
draco3d="${root}/tests/web/node_modules/draco3d"
for need in "${encoder}" "${package}/draco3d.js" "${draco3d}/draco3d.js" \
            "${corpus}/MANIFEST.tsv"; do
  [[ -e "${need}" ]] || { echo "missing ${need}" >&2; exit 1; }
done

if [[ -n "${keep}" ]]; then
  mkdir -p "${keep}"
  work="$(realpath "${keep}")"
else
  work="$(mktemp -d)"
  trap 'rm -rf "${work}"' EXIT
fi

# Scheme label and the draco_encoder options that make it.
# draco+context is stock prediction with context seams: the seam coder alone.
schemes=(
  "draco+context|-uv_seams context"
  "auto|-uv_pred auto"
  "weighted|-uv_pred weighted"
  "weighted_multi|-uv_pred weighted_multi"
  "auto+context|-uv_pred auto -uv_seams context"
  "weighted_multi+context|-uv_pred weighted_multi -uv_seams context"
  "laplacian_mv|-uv_pred laplacian_mv"
)
settings=(-cl 10 -qp 14 -qt 12)

encode() {  # OBJ OUT [OPTIONS...]
  local obj="$1" out="$2"
  shift 2
  [[ -s "${out}" ]] && return 0
  "${encoder}" -i "${obj}" -o "${out}.tmp" "${settings[@]}" "$@" >/dev/null
  mv "${out}.tmp" "${out}"
}

index="${work}/index.tsv"
printf 'mesh\tkind\tuv_vertices\tscheme\tfile\tbytes\n' >"${index}"
if [[ ${tangents} -eq 1 ]]; then
  settings=(-cl 10 -qp 14 -qt 12 -qn 10 -qtg 8)
  schemes=("tangent_auto|-tangent_pred auto"
           "tangent_mikktspace|-tangent_pred mikktspace"
           "tangent_geometric|-tangent_pred geometric")
  for file in "${corpus}"/gltf/*.gltf "${root}"/testdata/*_tangents.glb; do
    [[ -e "${file}" ]] || continue
    grep -aq '"TANGENT"' "${file}" || continue
    name="$(basename "${file%.*}")"
    if [[ -n "${meshes}" && ",${meshes}," != *",${name},"* ]]; then continue; fi
    echo "encoding ${name}" >&2
    for entry in "stock|" "${schemes[@]}"; do
      label="${entry%%|*}"
      read -r -a options <<<"${entry#*|}"
      encode "${file}" "${work}/${name}.${label}.drc" "${options[@]}"
      printf '%s\tgltf\t-\t%s\t%s\t%s\n' "${name}" "${label}" \
        "${name}.${label}.drc" \
        "$(stat -c %s "${work}/${name}.${label}.drc")" >>"${index}"
    done
  done
fi
# MANIFEST.tsv columns: name file ... kind(6) triangles positions uv_vertices(9)
while [[ ${tangents} -eq 0 ]] &&
    IFS=$'\t' read -r name file _ _ _ kind _ _ uv_vertices _; do
  [[ "${name}" == name ]] && continue
  if [[ -n "${meshes}" && ",${meshes}," != *",${name},"* ]]; then continue; fi
  obj="${corpus}/${file}"
  echo "encoding ${name}" >&2
  encode "${obj}" "${work}/${name}.stock.drc"
  printf '%s\t%s\t%s\tstock\t%s\t%s\n' "${name}" "${kind}" "${uv_vertices}" \
    "${name}.stock.drc" "$(stat -c %s "${work}/${name}.stock.drc")" >>"${index}"
  for entry in "${schemes[@]}"; do
    label="${entry%%|*}"
    read -r -a options <<<"${entry#*|}"
    encode "${obj}" "${work}/${name}.${label}.drc" "${options[@]}"
    printf '%s\t%s\t%s\t%s\t%s\t%s\n' "${name}" "${kind}" "${uv_vertices}" \
      "${label}" "${name}.${label}.drc" \
      "$(stat -c %s "${work}/${name}.${label}.drc")" >>"${index}"
  done
done <"${corpus}/MANIFEST.tsv"

if [[ $(wc -l <"${index}") -le 1 ]]; then
  echo "no corpus mesh matches ${meshes}" >&2
  exit 1
fi
echo "node $(node --version), $(nproc) CPUs; decoding" >&2
node --expose-gc --single-threaded "${root}/benchmarks/web_decode_bench.js" \
  --ours "${package}" --draco3d "${draco3d}" --rounds "${rounds}" \
  --warmup "${warmup}" --clock "${clock}" ${tsv:+--tsv "${tsv}"} "${index}"
