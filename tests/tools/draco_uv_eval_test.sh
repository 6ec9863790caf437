#!/usr/bin/env bash
# draco_uv_eval against an independent computation on a small mesh:
#  1. Its UV bytes are the sizes of draco_encoder's own files (with minus
#     without texture coordinates), its bpv 8 * that / UV vertices, and its
#     ratio the UV bytes over stock's best of -cl 7 and -cl 10.
#  2. Its RMSE equals eq. (9) computed from draco_decoder's OBJ output,
#     matched to the original mesh by position (tests/tools/uv_rmse.py).
#  3. Bad paths and unreadable meshes give a clear error and a non-zero exit;
#     a folder with one broken mesh reports it and evaluates the others.
#  4. --plot writes a chart (when python3 has matplotlib).
#  5. --seams draco,context adds "<scheme>+context" rows whose UV bytes are
#     those of draco_encoder -uv_seams context, and whose seam bytes differ
#     from the stock rows' by what the files' sizes differ (within 2 bytes:
#     stock seam bytes are counted on the position corner table).
#  6. --help prints its text as written (percent signs included).
#
#   draco_uv_eval_test.sh UV_EVAL ENCODER DECODER MESH
set -uo pipefail

uv_eval=$1 encoder=$2 decoder=$3 mesh=$4
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
python=/usr/bin/python3
[[ -x ${python} ]] || python=python3

"${uv_eval}" "${mesh}" --qt 10 --schemes draco,weighted --seams draco,context \
  --repeat 1 --quiet --csv "${work}/eval.csv" >"${work}/eval.txt" 2>&1 ||
  { cat "${work}/eval.txt"; fail "draco_uv_eval failed on ${mesh}"; }

size() { stat -c %s "$1"; }
encode() {  # encode OUT [flags...]
  local out=$1
  shift
  "${encoder}" -i "${mesh}" -o "${out}" -qp 14 "$@" >/dev/null 2>&1 ||
    fail "draco_encoder $*"
}
encode "${work}/none10.drc" -cl 10 --skip TEX_COORD
encode "${work}/none7.drc" -cl 7 --skip TEX_COORD
encode "${work}/stock10.drc" -cl 10 -qt 10
encode "${work}/stock7.drc" -cl 7 -qt 10
encode "${work}/weighted.drc" -cl 10 -qt 10 -uv_pred weighted
encode "${work}/none_context.drc" -cl 10 --skip TEX_COORD -uv_seams context
encode "${work}/context.drc" -cl 10 -qt 10 -uv_seams context
encode "${work}/weighted_context.drc" -cl 10 -qt 10 -uv_pred weighted -uv_seams context
stock10=$(($(size "${work}/stock10.drc") - $(size "${work}/none10.drc")))
stock7=$(($(size "${work}/stock7.drc") - $(size "${work}/none7.drc")))
stock_best=$((stock10 < stock7 ? stock10 : stock7))
weighted=$(($(size "${work}/weighted.drc") - $(size "${work}/none10.drc")))
context=$(($(size "${work}/context.drc") - $(size "${work}/none_context.drc")))
weighted_context=$(($(size "${work}/weighted_context.drc") - $(size "${work}/none_context.drc")))
"${decoder}" -i "${work}/weighted.drc" -o "${work}/weighted.obj" >/dev/null 2>&1 ||
  fail "draco_decoder"

"${python}" - "${work}/eval.csv" "${stock10}" "${weighted}" "${context}" \
  "${weighted_context}" "${stock_best}" "${mesh}" "${work}/weighted.obj" \
  "${here}/uv_rmse.py" <<'EOF' || fail "numbers disagree"
import csv, subprocess, sys
(path, stock10, weighted, context, weighted_context, stock_best, mesh, decoded,
 rmse_tool) = sys.argv[1:]
rows = {r["scheme"]: r for r in csv.DictReader(open(path))}
expected = {"draco": int(stock10), "weighted": int(weighted),
            "draco+context": int(context),
            "weighted+context": int(weighted_context)}
out = subprocess.run([sys.executable, rmse_tool, mesh, decoded], check=True,
                     capture_output=True, text=True).stdout.split()
rmse, uv_vertices = float(out[0]), int(out[1])
ok = True
for scheme, uv_bytes in expected.items():
    row = rows[scheme]
    # (value, independent value, tolerance): the CSV rounds bpv and ratios
    # to 4 decimals; the decoded OBJ holds UVs to about 6 digits.
    checks = {
        "uv_bytes": (int(row["uv_bytes"]), uv_bytes, 0),
        "uv_vertices": (int(row["uv_vertices"]), uv_vertices, 0),
        "bpv": (float(row["bpv"]), 8 * uv_bytes / uv_vertices, 1e-4),
        "ratio": (float(row["ratio_vs_draco"]), uv_bytes / int(stock_best),
                  1e-4),
        "rmse": (float(row["rmse"]) / rmse, 1.0, 1e-3),
    }
    for name, (got, want, tolerance) in checks.items():
        if abs(got - want) > tolerance:
            print(f"{scheme} {name}: draco_uv_eval {got}, independent {want}")
            ok = False
    if row["round_trip"] != "ok":
        print(f"{scheme}: round trip {row['round_trip']}")
        ok = False
for scheme in ("draco", "weighted"):
    stock, ours = rows[scheme], rows[scheme + "+context"]
    saved_file = int(stock["uv_bytes"]) - int(ours["uv_bytes"])
    saved_seams = float(stock["seam_bytes"]) - float(ours["seam_bytes"])
    if saved_file <= 0 or abs(saved_file - saved_seams) > 2:
        print(f"{scheme}+context: saves {saved_file} bytes, seam bytes "
              f"{saved_seams}")
        ok = False
sys.exit(0 if ok else 1)
EOF

# 3. Errors.
if "${uv_eval}" "${work}/missing.obj" >"${work}/out" 2>&1 ||
   ! grep -q "does not exist" "${work}/out"; then
  fail "a missing path is not a clear error"
fi
mkdir -p "${work}/folder"
cp "${mesh}" "${work}/folder/good.obj"
printf 'v 1 2\nf 1 2 x\n' >"${work}/folder/broken.obj"
printf 'not a ply\n' >"${work}/folder/broken.ply"
"${uv_eval}" "${work}/folder" --qt 10 --schemes draco --repeat 1 --quiet \
  >"${work}/folder.txt" 2>&1
status=$?
[[ ${status} -ne 0 ]] || fail "a folder with broken meshes exits 0"
grep -q "broken" "${work}/folder.txt" || fail "broken meshes are not named"
grep -q "^good: " "${work}/folder.txt" || fail "the good mesh was not evaluated"

# 4. Chart.
if "${python}" -c "import matplotlib" 2>/dev/null; then
  "${uv_eval}" "${mesh}" --qt 8,10 --schemes draco,weighted --repeat 1 --quiet \
    --plot "${work}/rd.png" >/dev/null 2>&1 || fail "--plot failed"
  [[ -s "${work}/rd.png" ]] || fail "--plot wrote no chart"
fi

# 6. Help text.
"${uv_eval}" --help >"${work}/help.txt" 2>&1
grep -q "greedy, 0.65% of the" "${work}/help.txt" ||
  fail "--help does not print the default anchors as written"

echo "failures: ${failures}"
[[ ${failures} -eq 0 ]]
