#!/usr/bin/env bash
# draco_uv_decode_bench: one table row per mesh with positive times and a
# ratio equal to scheme / stock, a summary per scheme and thread cap; a
# clear error and a non-zero exit for unknown schemes, bad thread caps and
# unreadable meshes.
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
