#!/usr/bin/env bash
# The size tables of benchmarks/web.md: raw, gzip -9 and brotli (-q 11)
# bytes of draco-uv's WebAssembly/JS decoder and encoder against stock
# Draco 1.5.5 built the same way, npm draco3d's and three.js's copies.
#
#   scripts/web-sizes.sh [--breakdown] [OUT]   (OUT: build-web, as build-web.sh)
#
# Runs scripts/build-web.sh --stock OUT (builds what is missing), unpacks
# the pinned npm packages below with `npm pack` into a temporary folder
# (their rows are left out, with a note, when the registry is unreachable)
# and prints Markdown tables on stdout. With --breakdown, also links our and
# stock's WebAssembly decoders once more from their objects with
# --profiling-funcs (function names kept, code unchanged) into
# OUT/profile/{uv,stock}/ and prints scripts/wasm_size_breakdown.py's tables.
set -euo pipefail
cd "$(dirname "$0")/.."

breakdown=0
if [[ "${1:-}" == --breakdown ]]; then
  breakdown=1
  shift
fi
readonly OUT=$(realpath -m "${1:-build-web}")
# The releases compared with: draco3d's newest, and the three.js release
# whose examples/jsm/libs/draco/ the feasibility check measured.
readonly DRACO3D_VERSION=1.5.9
readonly THREE_VERSION=0.187.0

die() { echo "web-sizes.sh: $*" >&2; exit 1; }
for tool in gzip brotli npm; do
  command -v "${tool}" >/dev/null || die "${tool} is missing (./draco-uv.sh web installs it)"
done

scripts/build-web.sh --stock "${OUT}" >&2

work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
have_npm=1
if ! (cd "${work}" &&
      npm pack --silent "draco3d@${DRACO3D_VERSION}" "three@${THREE_VERSION}" \
        >npm-pack.log 2>&1); then
  echo "web-sizes.sh: npm pack failed (registry unreachable?); npm rows left out" >&2
  have_npm=0
else
  mkdir -p "${work}/draco3d" "${work}/three"
  tar -xzf "${work}/draco3d-${DRACO3D_VERSION}.tgz" -C "${work}/draco3d"
  tar -xzf "${work}/three-${THREE_VERSION}.tgz" -C "${work}/three"
fi
readonly draco3d="${work}/draco3d/package"
readonly three="${work}/three/package/examples/jsm/libs/draco"
readonly ours="${OUT}/draco3d-uv"

grouped() { sed ':a;s/\B[0-9]\{3\}\>/,&/;ta' <<<"$1"; }  # 1234567 -> 1,234,567
sizes() {  # sizes FILE: "raw | gzip | brotli" in bytes
  local raw gz br
  raw=$(stat -c %s "$1")
  gz=$(gzip -9 -c "$1" | wc -c)
  br=$(brotli -q 11 -c "$1" | wc -c)
  echo "$(grouped "${raw}") | $(grouped "${gz}") | $(grouped "${br}")"
}
gzip_size() { gzip -9 -c "$1" | wc -c; }
row() {  # row LABEL FILE
  if [[ -f "$2" ]]; then
    echo "| $1 | $(sizes "$2") |"
  fi
}
npm_row() {  # npm_row LABEL FILE: only with the npm packages
  [[ ${have_npm} -eq 1 ]] && row "$@"
  return 0
}
delta() {  # delta OURS STOCK: gzip bytes of OURS minus STOCK, in KB
  local d
  d=$(( $(gzip_size "$1") - $(gzip_size "$2") ))
  awk -v d="${d}" 'BEGIN { printf "%+.1f KB (%+d bytes)", d / 1000, d }'
}

header="| file | raw | gzip -9 | brotli -q 11 |
| --- | ---: | ---: | ---: |"

echo "### Decoder (.wasm)"
echo
echo "${header}"
row "draco-uv \`draco_decoder.wasm\` (every lossless coder; Laplacian part on demand)" "${ours}/draco_decoder.wasm"
row "draco-uv \`draco_decoder_laplacian.wasm\` (the Laplacian part, loaded on demand)" "${ours}/draco_decoder_laplacian.wasm"
row "draco-uv, every coder in one module (\`uv/\`, not in the package)" "${OUT}/uv/draco/draco_decoder.wasm"
row "stock Draco 1.5.5, built the same way" "${OUT}/stock/draco_decoder.wasm"
npm_row "npm draco3d ${DRACO3D_VERSION} \`draco_decoder.wasm\`" "${draco3d}/draco_decoder.wasm"
npm_row "three ${THREE_VERSION} \`libs/draco/draco_decoder.wasm\`" "${three}/draco_decoder.wasm"
echo
echo "draco-uv minus stock (gzip -9): $(delta "${ours}/draco_decoder.wasm" "${OUT}/stock/draco_decoder.wasm"); every coder in one module: $(delta "${OUT}/uv/draco/draco_decoder.wasm" "${OUT}/stock/draco_decoder.wasm")"
echo
echo "### Decoder glue and asm.js fallback"
echo
echo "${header}"
row "draco-uv \`draco_wasm_wrapper.js\` (terser)" "${ours}/draco_wasm_wrapper.js"
row "stock 1.5.5 glue as emscripten writes it" "${OUT}/stock/draco_decoder.js"
npm_row "npm draco3d ${DRACO3D_VERSION} \`draco_decoder_nodejs.js\`" "${draco3d}/draco_decoder_nodejs.js"
npm_row "three ${THREE_VERSION} \`draco_wasm_wrapper.js\`" "${three}/draco_wasm_wrapper.js"
row "draco-uv \`draco_decoder.js\` (asm.js, terser)" "${ours}/draco_decoder.js"
npm_row "three ${THREE_VERSION} \`draco_decoder.js\` (asm.js)" "${three}/draco_decoder.js"
echo
echo "### Encoder"
echo
echo "${header}"
row "draco-uv \`draco_encoder.wasm\`" "${ours}/draco_encoder.wasm"
row "stock Draco 1.5.5, built the same way" "${OUT}/stock/draco_encoder.wasm"
npm_row "npm draco3d ${DRACO3D_VERSION} \`draco_encoder.wasm\`" "${draco3d}/draco_encoder.wasm"
row "draco-uv \`draco_encoder_wrapper.js\` (terser)" "${ours}/draco_encoder_wrapper.js"
npm_row "npm draco3d ${DRACO3D_VERSION} \`draco_encoder_nodejs.js\`" "${draco3d}/draco_encoder_nodejs.js"
echo
echo "draco-uv minus stock (gzip -9): $(delta "${ours}/draco_encoder.wasm" "${OUT}/stock/draco_encoder.wasm")"
echo
echo "### glTF-only decoder (\`gltf/\`)"
echo
echo "${header}"
row "draco-uv \`gltf/draco_decoder.wasm\`" "${ours}/gltf/draco_decoder.wasm"
row "draco-uv \`gltf/draco_decoder_laplacian.wasm\` (on demand)" "${ours}/gltf/draco_decoder_laplacian.wasm"
row "stock Draco 1.5.5 (DRACO_GLTF_BITSTREAM), built the same way" "${OUT}/stock-gltf/draco_decoder_gltf.wasm"
npm_row "three ${THREE_VERSION} \`libs/draco/gltf/draco_decoder.wasm\`" "${three}/gltf/draco_decoder.wasm"
row "draco-uv \`gltf/draco_wasm_wrapper.js\` (terser)" "${ours}/gltf/draco_wasm_wrapper.js"
row "draco-uv \`gltf/draco_decoder.js\` (asm.js, terser)" "${ours}/gltf/draco_decoder.js"
echo
echo "draco-uv minus stock (gzip -9): $(delta "${ours}/gltf/draco_decoder.wasm" "${OUT}/stock-gltf/draco_decoder_gltf.wasm")"

# link_with_names BUILD TARGET_JS DEST: BUILD's link command of TARGET_JS
# (as ninja records it) run again with --profiling-funcs, output to DEST.
link_with_names() {
  local command
  command=$(ninja -C "$1" -t commands "$2" | tail -n 1)
  [[ "${command}" == *" -o $2 "* ]] || die "no link command for $2 in $1"
  command=${command#": && "}
  command=${command%" && :"}
  command=${command/" -o $2 "/" -o $3 --profiling-funcs "}
  mkdir -p "$(dirname "$3")"
  (cd "$1" && EMSCRIPTEN=/usr/share/emscripten \
     NODE_PATH="/usr/share/nodejs${NODE_PATH:+:${NODE_PATH}}" eval "nice ${command}")
}

if [[ ${breakdown} -eq 1 ]]; then
  link_with_names "${OUT}/uv" draco/draco_decoder.js "${OUT}/profile/uv/draco_decoder.js"
  link_with_names "${OUT}/stock" draco_decoder.js "${OUT}/profile/stock/draco_decoder.js"
  echo
  echo "### Decoder code by function (raw bytes of the code section)"
  echo
  scripts/wasm_size_breakdown.py "${OUT}/profile/uv/draco_decoder.wasm" \
    "${OUT}/profile/stock/draco_decoder.wasm"
fi
