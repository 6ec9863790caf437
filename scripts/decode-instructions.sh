#!/usr/bin/env bash
# Decode cost of draco-uv's coders against stock Draco on the corpus, as the
# decode-speed targets measure it: instructions inside
# Decoder::DecodeMeshFromBuffer (valgrind callgrind, one thread) with
# interleaved wall times beside them.
#
#   scripts/decode-instructions.sh [CORPUS_DIR] [BUILD_DIR] [ROUNDS] [PROFILES]
#
# CORPUS_DIR defaults to ../shared/corpus (MANIFEST.tsv and meshes/*.obj),
# BUILD_DIR to build, ROUNDS (wall-time rounds, minimum kept) to 10. Every
# mesh is encoded at -qp 14 -qt 12 -cl 10 (BENCHMARKS.md's qt 12 tables)
# without our options and with each scheme below; draco+context is stock
# prediction with context seams, which isolates the seam coder. Everything
# runs on CPU 0 with draco-uv's thread cap at 1. PROFILES, when given, keeps
# callgrind's profile of every decode there (callgrind_annotate --inclusive=yes
# reads them). Prints the raw table of draco_uv_decode_bench, then the
# summary of scripts/decode_speed_table.py. About 7 minutes for the corpus.
set -euo pipefail
cd "$(dirname "$0")/.."

corpus=${1:-../shared/corpus}
build=${2:-build}
rounds=${3:-10}
profiles=${4:-}
schemes=draco+context,auto,weighted,weighted_multi,auto+context,weighted_multi+context

command -v valgrind >/dev/null || { echo "Error: needs valgrind" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT

bench=("${build}/draco/draco_uv_decode_bench" "${corpus}/meshes" --qp 14
  --qt 12 --cl 10 --schemes "${schemes}" --threads 1 --rounds "${rounds}"
  --instructions)
[[ -n ${profiles} ]] && bench+=(--profiles "${profiles}")
taskset -c 0 "${bench[@]}" | tee "${work}/bench.md"
echo
python3 scripts/decode_speed_table.py "${work}/bench.md" "${corpus}/MANIFEST.tsv"
