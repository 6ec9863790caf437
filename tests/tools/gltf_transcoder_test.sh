#!/usr/bin/env bash
# glTF pipelines with the patched draco_transcoder, against Debian's stock
# Draco 1.5.5 tools, on every glTF/GLB asset of Draco's testdata:
#  1. Without -uv_pred, our draco_transcoder writes byte-identical .gltf/.bin
#     and .glb files to /usr/bin/draco_transcoder (and fails where it fails).
#  2. With -uv_pred weighted, an asset with texture coordinates comes out
#     requiring the draco-uv glTF extension, and no other does. Stock
#     draco_transcoder and draco_encoder fail on it with an error (their
#     glTF reader decodes the Draco buffers before it checks extensions),
#     also with the extension deleted from the JSON. Our draco_encoder and
#     draco_uv_eval read it (where Draco reads the stock-coded output: not a
#     point cloud primitive).
#  3. Apart from the extension and buffer sizes, its JSON is the stock
#     output's: materials, KHR_texture_transform, skins and animations are
#     untouched.
#  4. With -uv_pred auto, no .gltf (with its .bin) or .glb output is bigger
#     than the stock transcoder's, the draco-uv extension's JSON included.
#  5. A stock-coded file that requires the extension is refused by the stock
#     reader naming it ("... is unsupported.") and read by ours.
#
#   gltf_transcoder_test.sh OUR_TRANSCODER OUR_ENCODER OUR_UV_EVAL DRACO_TESTDATA
set -uo pipefail

our_transcoder=$1 our_encoder=$2 our_uv_eval=$3 draco_testdata=$4
stock_transcoder=/usr/bin/draco_transcoder stock_encoder=/usr/bin/draco_encoder
gltf_json="$(dirname "$0")/gltf_json.py"
extension=DRACOUV_attribute_compression
for tool in "${stock_transcoder}" "${stock_encoder}"; do
  [[ -x "${tool}" ]] || { echo "missing ${tool} (apt-get install draco)"; exit 1; }
done

work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
failures=0 identical=0 refused=0 read_back=0 auto_not_bigger=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# Transcodes $2 into folder $1 as out.$3 with the remaining arguments.
transcode() {
  local tool=$1 dir=$2 input=$3 ext=$4
  shift 4
  rm -rf "${dir}" && mkdir -p "${dir}"
  "${tool}" -i "${input}" -o "${dir}/out.${ext}" "$@" >"${dir}.log" 2>&1
}

mapfile -t assets < <(cd "${draco_testdata}" &&
  find . -type f \( -name '*.gltf' -o -name '*.glb' \) | sort)

for asset in "${assets[@]}"; do
  input="${draco_testdata}/${asset}"
  for ext in gltf glb; do
    transcode "${stock_transcoder}" "${work}/stock_${ext}" "${input}" "${ext}"
    stock_status=$?
    transcode "${our_transcoder}" "${work}/ours_${ext}" "${input}" "${ext}"
    our_status=$?
    if [[ ${stock_status} -ne 0 || ${our_status} -ne 0 ]]; then
      [[ ${stock_status} -eq ${our_status} ]] ||
        fail "${asset} .${ext}: stock exit ${stock_status}, ours ${our_status}"
      continue
    fi
    if diff -r "${work}/stock_${ext}" "${work}/ours_${ext}" >/dev/null; then
      identical=$((identical + 1))
    else
      fail "${asset} .${ext}: output differs from stock"
    fi
  done
  [[ ${stock_status} -eq 0 ]] || continue

  for ext in gltf glb; do
    transcode "${our_transcoder}" "${work}/auto_${ext}" "${input}" "${ext}" -uv_pred auto ||
      { fail "${asset} .${ext}: -uv_pred auto failed"; continue; }
    auto_bytes=$(du -bc "${work}/auto_${ext}"/* | tail -1 | cut -f1)
    stock_bytes=$(du -bc "${work}/stock_${ext}"/* | tail -1 | cut -f1)
    if [[ ${auto_bytes} -le ${stock_bytes} ]]; then
      auto_not_bigger=$((auto_not_bigger + 1))
    else
      fail "${asset} .${ext}: -uv_pred auto ${auto_bytes} bytes, stock ${stock_bytes}"
    fi
  done

  transcode "${our_transcoder}" "${work}/uv" "${input}" gltf -uv_pred weighted ||
    { fail "${asset}: -uv_pred weighted failed: $(tail -1 "${work}/uv.log")"; continue; }
  uv_file="${work}/uv/out.gltf"
  python3 "${gltf_json}" same-apart-from "${work}/stock_gltf/out.gltf" "${uv_file}" \
    "${extension}" || fail "${asset}: JSON differs from stock beyond the Draco buffers"
  has_uvs=false
  python3 "${gltf_json}" has-texcoords "${input}" && has_uvs=true
  requires=false
  python3 "${gltf_json}" requires "${uv_file}" "${extension}" && requires=true
  [[ ${requires} == "${has_uvs}" ]] ||
    fail "${asset}: texture coordinates ${has_uvs}, requires ${extension} ${requires}"
  [[ ${requires} == true ]] || continue

  refused=$((refused + 1))
  python3 "${gltf_json}" strip "${uv_file}" "${extension}" "${work}/uv/stripped.gltf"
  for file in "${uv_file}" "${work}/uv/stripped.gltf"; do
    rm -f "${work}/stock_out.gltf"
    if "${stock_transcoder}" -i "${file}" -o "${work}/stock_out.gltf" \
         >"${work}/refuse.log" 2>&1 || [[ -e "${work}/stock_out.gltf" ]]; then
      fail "${asset}: stock draco_transcoder read $(basename "${file}") of -uv_pred weighted"
    elif ! grep -q "^Failed" "${work}/refuse.log"; then
      fail "${asset}: stock draco_transcoder failed without an error message"
    fi
  done
  "${stock_encoder}" -i "${uv_file}" -o "${work}/stock.drc" >"${work}/refuse.log" 2>&1 &&
    fail "${asset}: stock draco_encoder read a -uv_pred weighted file"
  # Draco's reader cannot read back a glTF point cloud it wrote, stock or not.
  "${our_encoder}" -i "${work}/stock_gltf/out.gltf" -o "${work}/ours.drc" \
    >/dev/null 2>&1 || continue
  if "${our_encoder}" -i "${uv_file}" -o "${work}/ours.drc" >/dev/null 2>&1 &&
     "${our_uv_eval}" "${uv_file}" --schemes draco --qt 10 --repeat 1 \
       --quiet >/dev/null 2>&1; then
    read_back=$((read_back + 1))
  else
    fail "${asset}: our draco_encoder or draco_uv_eval cannot read the file"
  fi
done

# 5. The extension alone, on stock-coded data.
truck="${draco_testdata}/CesiumMilkTruck/glTF/CesiumMilkTruck.gltf"
transcode "${our_transcoder}" "${work}/marked" "${truck}" gltf
python3 "${gltf_json}" add "${work}/marked/out.gltf" "${extension}" "${work}/marked/marked.gltf"
"${stock_transcoder}" -i "${work}/marked/marked.gltf" -o "${work}/marked_out.gltf" \
  >"${work}/marked.log" 2>&1 && fail "stock draco_transcoder read a file requiring ${extension}"
grep -q "${extension} is unsupported" "${work}/marked.log" ||
  fail "stock draco_transcoder did not name ${extension}: $(tail -1 "${work}/marked.log")"
"${our_transcoder}" -i "${work}/marked/marked.gltf" -o "${work}/marked_out.gltf" \
  >"${work}/marked.log" 2>&1 || fail "our draco_transcoder refused ${extension}"

echo "byte-identical outputs: ${identical}; files refused by stock: ${refused};" \
  "read back by our tools: ${read_back}; auto not bigger than stock:" \
  "${auto_not_bigger}; failures: ${failures}"
[[ ${identical} -ge 100 && ${refused} -ge 40 && ${read_back} -ge 35 &&
   ${auto_not_bigger} -ge 100 && ${failures} -eq 0 ]]
