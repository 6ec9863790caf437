#!/usr/bin/env bash
# Stock compatibility of the patched tools with Debian's Draco 1.5.5:
#  1. Without -uv_pred, our draco_encoder writes byte-identical files to
#     /usr/bin/draco_encoder for every OBJ/PLY/glTF/GLB mesh of Draco's
#     testdata at -cl 0, 7 and 10, and /usr/bin/draco_decoder decodes them.
#  2. Files using -uv_pred weighted or laplacian_cotan make
#     /usr/bin/draco_decoder fail with an error (never decode), and our
#     draco_decoder decodes them.
#
#   stock_compatibility_test.sh OUR_ENCODER OUR_DECODER DRACO_TESTDATA UV_TESTDATA
set -uo pipefail

our_encoder=$1 our_decoder=$2 draco_testdata=$3
stock_encoder=/usr/bin/draco_encoder stock_decoder=/usr/bin/draco_decoder
for tool in "${stock_encoder}" "${stock_decoder}"; do
  [[ -x "${tool}" ]] || { echo "missing ${tool} (apt-get install draco)"; exit 1; }
done

work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
failures=0 compared=0 rejected=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

mapfile -t meshes < <(cd "${draco_testdata}" &&
  find . -type f \( -name '*.obj' -o -name '*.ply' -o -name '*.gltf' -o -name '*.glb' \) | sort)

for mesh in "${meshes[@]}"; do
  input="${draco_testdata}/${mesh}"
  for cl in 0 7 10; do
    "${stock_encoder}" -i "${input}" -o "${work}/stock.drc" -cl "${cl}" >"${work}/stock.log" 2>&1
    stock_status=$?
    "${our_encoder}" -i "${input}" -o "${work}/ours.drc" -cl "${cl}" >"${work}/ours.log" 2>&1
    our_status=$?
    if [[ ${stock_status} -ne 0 || ${our_status} -ne 0 ]]; then
      [[ ${stock_status} -eq ${our_status} ]] ||
        fail "${mesh} -cl ${cl}: stock exit ${stock_status}, ours ${our_status}"
      rm -f "${work}/stock.drc" "${work}/ours.drc"
      continue
    fi
    compared=$((compared + 1))
    cmp -s "${work}/stock.drc" "${work}/ours.drc" ||
      fail "${mesh} -cl ${cl}: output differs from stock"
    "${stock_decoder}" -i "${work}/ours.drc" -o "${work}/decoded.obj" >/dev/null 2>&1 ||
      fail "${mesh} -cl ${cl}: stock decoder rejects our stock-compatible output"
  done

  # Files using our schemes: stock must fail, ours must decode.
  for scheme in weighted laplacian_cotan; do
    "${our_encoder}" -i "${input}" -o "${work}/${scheme}.drc" -cl 10 -uv_pred "${scheme}" \
      >"${work}/${scheme}.log" 2>&1 || continue  # No texture coordinates, etc.
    grep -q "TEX_COORD" "${work}/${scheme}.log" || continue
    rejected=$((rejected + 1))
    if "${stock_decoder}" -i "${work}/${scheme}.drc" -o "${work}/stock_decoded.obj" \
         >"${work}/stock_decode.log" 2>&1; then
      fail "${mesh}: stock draco_decoder decoded a -uv_pred ${scheme} file"
    elif ! grep -qi "fail" "${work}/stock_decode.log"; then
      fail "${mesh}: stock draco_decoder failed without an error message"
    fi
    "${our_decoder}" -i "${work}/${scheme}.drc" -o "${work}/our_decoded.obj" >/dev/null 2>&1 ||
      fail "${mesh}: our draco_decoder cannot decode its own -uv_pred ${scheme} file"
  done
done

echo "byte-identical comparisons: ${compared}; draco-uv files rejected by stock: ${rejected}; failures: ${failures}"
[[ ${compared} -ge 60 && ${rejected} -ge 20 && ${failures} -eq 0 ]]
