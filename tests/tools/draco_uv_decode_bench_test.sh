#!/usr/bin/env bash
# draco_uv_decode_bench: one table row per mesh with positive times and a
# ratio equal to scheme / stock, a summary per scheme and thread cap; every
# -uv_pred x -uv_seams pair as a scheme (auto+context too); with
# --instructions (when valgrind is installed) positive instruction counts,
# ratios equal to scheme / stock, context seams costing more instructions
# than stock seams, and the mesh's interior edges; a clear error and a
# non-zero exit for unknown schemes, bad thread caps and unreadable meshes.
#
#   draco_uv_decode_bench_test.sh DECODE_BENCH MESH
set -uo pipefail

bench=$1 mesh=$2
work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

"${bench}" "${mesh}" --rounds 2 --schemes auto,weighted >"${work}/out.txt" 2>&1 ||
  { cat "${work}/out.txt"; fail "draco_uv_decode_bench failed on ${mesh}"; }
row=$(grep -F "| $(basename "${mesh}") |" "${work}/out.txt")
[[ -n ${row} ]] || fail "no row for ${mesh}"
# | mesh | stock | then a time and its ratio to stock for auto, auto on
# one thread, weighted, weighted on one thread |
awk -F'|' '{
  ok = NF == 12 && $3 > 0;
  for (i = 4; i <= 10; i += 2) {
    ok = ok && $i > 0 && ($(i + 1) * $3 / $i - 1) ^ 2 < 1e-4;
  }
  exit ok ? 0 : 1 }' <<<"${row}" || fail "bad times or ratios: ${row}"
for summary in "auto" "auto 1 thread" "weighted" "weighted 1 thread"; do
  grep -q "^${summary}: median" "${work}/out.txt" || fail "no summary for ${summary}"
done
"${bench}" "${mesh}" --rounds 1 --threads 1 >"${work}/one.txt" 2>&1 ||
  fail "--threads 1 failed"
grep -q "^auto: median" "${work}/one.txt" && ! grep -q "thread" "${work}/one.txt" ||
  fail "--threads 1 does not give one column per scheme"
if "${bench}" "${mesh}" --rounds 1 --threads 0 >/dev/null 2>&1; then
  fail "--threads 0 succeeded"
fi

"${bench}" "${mesh}" --rounds 1 --threads 1 \
  --schemes auto+context,weighted_multi+context,draco+context,weighted+draco \
  >"${work}/seams.txt" 2>&1 || { cat "${work}/seams.txt"; fail "seam schemes failed"; }
for summary in auto+context weighted_multi+context draco+context weighted+draco; do
  grep -q "^${summary}: median" "${work}/seams.txt" || fail "no summary for ${summary}"
done

if command -v valgrind >/dev/null; then
  "${bench}" "${mesh}" --rounds 1 --threads 1 --schemes draco+context,auto \
    --profiles "${work}/profiles" >"${work}/instr.txt" 2>&1 ||
    { cat "${work}/instr.txt"; fail "--instructions failed"; }
  row=$(grep -F "| $(basename "${mesh}") |" "${work}/instr.txt")
  # | mesh | stock ms | 2 x (ms | ratio) | edges | stock instr |
  # 2 x (instr | ratio) |: context seams cost more than stock seams.
  awk -F'|' '{
    ok = NF == 14 && $8 > 0 && $9 > 0;
    for (i = 10; i <= 12; i += 2) {
      ok = ok && $i > 0 && ($(i + 1) * $9 / $i - 1) ^ 2 < 1e-6;
    }
    exit ok && $10 > $9 ? 0 : 1 }' <<<"${row}" || fail "bad instruction counts: ${row}"
  grep -q "^auto instructions: median" "${work}/instr.txt" ||
    fail "no instruction summary"
  name=$(basename "${mesh%.*}")
  for file in draco draco+context auto; do
    grep -q "^totals: " "${work}/profiles/${name}.${file}.callgrind" ||
      fail "no callgrind profile for ${file}"
  done
else
  echo "valgrind not installed: --instructions not checked"
fi

if "${bench}" "${mesh}" --rounds 1 --schemes fastest >"${work}/bad.txt" 2>&1; then
  fail "an unknown scheme succeeded"
fi
grep -q "fastest" "${work}/bad.txt" || fail "the error does not name the scheme"
echo "not a mesh" >"${work}/broken.obj"
if "${bench}" "${work}/broken.obj" --rounds 1 >/dev/null 2>&1; then
  fail "an unreadable mesh succeeded"
fi

[[ ${failures} -eq 0 ]] && echo "draco_uv_decode_bench: all checks passed"
exit $((failures > 0))
