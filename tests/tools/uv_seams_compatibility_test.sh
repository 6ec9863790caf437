#!/usr/bin/env bash
# -uv_seams on the command line, against Debian's stock Draco 1.5.5:
#  1. -uv_seams draco writes byte-identical files to /usr/bin/draco_encoder
#     for every OBJ/PLY/glTF/GLB mesh of Draco's testdata, at -cl 5
#     (standard Edgebreaker) and -cl 10 (valence Edgebreaker from 1000
#     faces).
#  2. Files written with -uv_seams context make /usr/bin/draco_decoder fail
#     with an error (never decode), and our draco_decoder decodes them to
#     exactly what it decodes from the stock file (same OBJ and PLY output).
#  3. draco_transcoder -uv_seams context: every glTF/GLB asset with texture
#     coordinates comes out requiring the draco-uv glTF extension, and
#     /usr/bin/draco_transcoder fails on it with an error, also with the
#     extension deleted from the JSON.
#
#   uv_seams_compatibility_test.sh OUR_ENCODER OUR_DECODER OUR_TRANSCODER \
#       DRACO_TESTDATA
set -uo pipefail

our_encoder=$1 our_decoder=$2 our_transcoder=$3 draco_testdata=$4
stock_encoder=/usr/bin/draco_encoder stock_decoder=/usr/bin/draco_decoder
stock_transcoder=/usr/bin/draco_transcoder
gltf_json="$(dirname "$0")/gltf_json.py"
extension=DRACOUV_attribute_compression
for tool in "${stock_encoder}" "${stock_decoder}" "${stock_transcoder}"; do
  [[ -x "${tool}" ]] || { echo "missing ${tool} (apt-get install draco)"; exit 1; }
done

work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
failures=0 identical=0 rejected=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

mapfile -t meshes < <(cd "${draco_testdata}" &&
  find . -type f \( -name '*.obj' -o -name '*.ply' -o -name '*.gltf' -o -name '*.glb' \) | sort)

for mesh in "${meshes[@]}"; do
  input="${draco_testdata}/${mesh}"
  for cl in 5 10; do
    "${stock_encoder}" -i "${input}" -o "${work}/stock.drc" -cl "${cl}" >/dev/null 2>&1 ||
      continue
    "${our_encoder}" -i "${input}" -o "${work}/draco.drc" -cl "${cl}" -uv_seams draco \
      >/dev/null 2>&1 || { fail "${mesh} -cl ${cl}: -uv_seams draco failed"; continue; }
    cmp -s "${work}/stock.drc" "${work}/draco.drc" ||
      fail "${mesh} -cl ${cl}: -uv_seams draco differs from stock"
    identical=$((identical + 1))

    "${our_encoder}" -i "${input}" -o "${work}/context.drc" -cl "${cl}" -uv_seams context \
      >"${work}/context.log" 2>&1 || continue  # Point clouds.
    grep -q "UV seams: context" "${work}/context.log" || continue  # No seams coded.
    rejected=$((rejected + 1))
    if "${stock_decoder}" -i "${work}/context.drc" -o "${work}/stock_decoded.obj" \
         >"${work}/stock_decode.log" 2>&1; then
      fail "${mesh} -cl ${cl}: stock draco_decoder decoded a -uv_seams context file"
    elif ! grep -qi "fail" "${work}/stock_decode.log"; then
      fail "${mesh} -cl ${cl}: stock draco_decoder failed without an error message"
    fi
    for ext in obj ply; do
      "${our_decoder}" -i "${work}/stock.drc" -o "${work}/from_stock.${ext}" >/dev/null 2>&1
      if ! "${our_decoder}" -i "${work}/context.drc" -o "${work}/from_context.${ext}" \
           >/dev/null 2>&1; then
        fail "${mesh} -cl ${cl}: our draco_decoder cannot decode -uv_seams context"
      elif ! cmp -s "${work}/from_stock.${ext}" "${work}/from_context.${ext}"; then
        fail "${mesh} -cl ${cl}: -uv_seams context decodes differently (${ext})"
      fi
    done
  done
done

gltf_refused=0
mapfile -t assets < <(cd "${draco_testdata}" &&
  find . -type f \( -name '*.gltf' -o -name '*.glb' \) | sort)
for asset in "${assets[@]}"; do
  input="${draco_testdata}/${asset}"
  python3 "${gltf_json}" has-texcoords "${input}" || continue
  rm -rf "${work}/gltf" && mkdir -p "${work}/gltf"
  "${stock_transcoder}" -i "${input}" -o "${work}/gltf/stock.gltf" >/dev/null 2>&1 ||
    continue  # Morph targets etc.
  output="${work}/gltf/out.gltf"
  "${our_transcoder}" -i "${input}" -o "${output}" -uv_seams context \
    >"${work}/gltf.log" 2>&1 ||
    { fail "${asset}: draco_transcoder -uv_seams context failed"; continue; }
  python3 "${gltf_json}" requires "${output}" "${extension}" ||
    { fail "${asset}: -uv_seams context output does not require ${extension}"; continue; }
  gltf_refused=$((gltf_refused + 1))
  python3 "${gltf_json}" strip "${output}" "${extension}" "${work}/gltf/stripped.gltf"
  for file in "${output}" "${work}/gltf/stripped.gltf"; do
    rm -f "${work}/gltf/stock_out.gltf"
    if "${stock_transcoder}" -i "${file}" -o "${work}/gltf/stock_out.gltf" \
         >"${work}/refuse.log" 2>&1 || [[ -e "${work}/gltf/stock_out.gltf" ]]; then
      fail "${asset}: stock draco_transcoder read $(basename "${file}") of -uv_seams context"
    elif ! grep -q "^Failed" "${work}/refuse.log"; then
      fail "${asset}: stock draco_transcoder failed without an error message"
    fi
  done
done

echo "byte-identical -uv_seams draco files: ${identical}; context files rejected by stock:" \
  "${rejected} (.drc), ${gltf_refused} (glTF); failures: ${failures}"
[[ ${identical} -ge 40 && ${rejected} -ge 30 && ${gltf_refused} -ge 20 && ${failures} -eq 0 ]]
