#!/usr/bin/env bash
# draco_uv_decode_bench: one table row per mesh with positive times and a
# ratio equal to scheme / stock, a summary per scheme; a clear error and a
# non-zero exit for unknown schemes and unreadable meshes.
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
# | mesh | stock | auto | ratio | weighted | ratio |
awk -F'|' '{
  ok = $3 > 0 && $4 > 0 && $6 > 0;
  ok = ok && ($5 - $4 / $3) ^ 2 < 1e-5 && ($7 - $6 / $3) ^ 2 < 1e-5;
  exit ok ? 0 : 1 }' <<<"${row}" || fail "bad times or ratios: ${row}"
for scheme in auto weighted; do
  grep -q "^${scheme}: median" "${work}/out.txt" || fail "no summary for ${scheme}"
done

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
