#!/usr/bin/env bash
# Stock Draco decoders from npm (draco3d 1.5.5 and 1.5.7, the WebAssembly
# decoder that three.js's DRACOLoader and other web loaders use) on glTF and
# GLB files of our draco_transcoder:
#  * stock-coded output (no -uv_pred) decodes, every primitive and attribute;
#  * with -uv_pred weighted, every primitive with texture coordinates fails
#    with a decoder error, never decodes.
# Skips (exit 77) when node or npm is missing, or when npm cannot install
# draco3d (no access to the npm registry).
#
#   draco3d_test.sh OUR_TRANSCODER DRACO_TESTDATA NODE_TEST_DIR NPM_PREFIX
set -uo pipefail

our_transcoder=$1 draco_testdata=$2 node_dir=$3 npm_prefix=$4
readonly kSkip=77

for tool in node npm; do
  command -v "${tool}" >/dev/null || { echo "SKIP: ${tool} not installed"; exit ${kSkip}; }
done

# Installs the locked draco3d versions into NPM_PREFIX once per lock file.
mkdir -p "${npm_prefix}"
if ! cmp -s "${node_dir}/package-lock.json" "${npm_prefix}/package-lock.json" ||
   [[ ! -d "${npm_prefix}/node_modules/draco3d" ]]; then
  cp "${node_dir}/package.json" "${node_dir}/package-lock.json" "${npm_prefix}/"
  if ! (cd "${npm_prefix}" && timeout 300 npm ci --no-audit --no-fund \
          --fetch-retries=1 --fetch-timeout=30000 >npm.log 2>&1); then
    echo "SKIP: npm ci failed (registry unreachable?):"
    tail -5 "${npm_prefix}/npm.log"
    rm -f "${npm_prefix}/package-lock.json"
    exit ${kSkip}
  fi
fi
decoders=("${npm_prefix}/node_modules/draco3d-1.5.5" "${npm_prefix}/node_modules/draco3d")

work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
failures=0 decoded=0 rejected=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

assets=(
  CesiumMilkTruck/glTF/CesiumMilkTruck.gltf
  MultiUVTest/glTF/MultiUVTest.gltf
  KhronosSampleModels/TextureTransformTest/glTF/TextureTransformTest.gltf
  CesiumMan/glTF_Binary/CesiumMan.glb
  KhronosSampleModels/Duck/glTF_Binary/Duck.glb
  simple_skin.gltf
  test_pos_color.gltf
)
for asset in "${assets[@]}"; do
  for ext in gltf glb; do
    for variant in stock weighted; do
      dir="${work}/${variant}"
      rm -rf "${dir}" && mkdir -p "${dir}"
      flags=()
      [[ ${variant} == weighted ]] && flags=(-uv_pred weighted)
      "${our_transcoder}" -i "${draco_testdata}/${asset}" -o "${dir}/out.${ext}" \
        "${flags[@]}" >/dev/null 2>&1 || { fail "${asset}: transcoding failed"; continue; }
      for decoder in "${decoders[@]}"; do
        node "$(dirname "$0")/node/decode_gltf_draco.js" "${decoder}" "${dir}/out.${ext}" \
          >"${work}/decode.log" 2>&1 || { fail "${asset}: node script failed"; cat "${work}/decode.log"; continue; }
        version=$(head -1 "${work}/decode.log")
        while read -r _ primitive result attributes detail; do
          expected=ok
          [[ ${variant} == weighted && ${attributes} == *TEXCOORD* ]] && expected=error
          if [[ ${result} != "${expected}" ]]; then
            fail "${asset} .${ext} ${version} ${variant}: primitive ${primitive}" \
              "(${attributes}): ${result} ${detail}"
          elif [[ ${result} == ok ]]; then
            decoded=$((decoded + 1))
          else
            rejected=$((rejected + 1))
          fi
        done < <(grep '^primitive ' "${work}/decode.log")
      done
    done
  done
done

echo "stock-coded primitives decoded: ${decoded}; draco-uv primitives rejected: ${rejected};" \
  "failures: ${failures}"
[[ ${decoded} -ge 20 && ${rejected} -ge 20 && ${failures} -eq 0 ]]
