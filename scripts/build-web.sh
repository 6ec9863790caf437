#!/usr/bin/env bash
# The WebAssembly/JavaScript build of draco-uv: Draco's own JS targets
# (draco_decoder, draco_encoder, with the IDL glue of Draco 1.5.5's
# draco_web_decoder.idl and draco_web_encoder.idl, the latter with patch
# 0013's entries for draco-uv's coders) built from the
# patched Draco with Debian's emscripten, laid out as a folder that works
# like npm's draco3d package and like three.js's examples/jsm/libs/draco/.
#
#   scripts/build-web.sh [--stock] [--no-check] [OUT]      (OUT: build-web)
#
# Builds (Release, Draco's release flags: -O3, -sWASM=1, Draco's -s
# settings, and -flto; memory growth capped at 2 GB by our CMakeLists.txt;
# no pthreads):
#   OUT/uv/        draco_decoder (.wasm + glue), its asm.js fallback
#                  (draco_decoder_asmjs: the same objects linked with
#                  -sWASM=0), draco_encoder (.wasm + glue)
#   OUT/uv-gltf/   the glTF-only decoder (DRACO_GLTF_BITSTREAM=ON: mesh
#                  compression with the features of the glTF extension's
#                  bitstream, no point clouds) with every coder, for its
#                  asm.js fallback
#   OUT/uv-gltf-ondemand/  the package's glTF-only decoder: as uv-gltf, its
#                  Laplacian solver in uv-ondemand's part (the same module)
#   OUT/uv-ondemand/  the package's default decoder: every lossless coder,
#                  and the lossy Laplacian coder's solver in a second module,
#                  draco_decoder_laplacian.wasm, which the decoder loads only
#                  for a file that needs it (DRACO_UV_LAPLACIAN_ON_DEMAND;
#                  benchmarks/web.md, "The Laplacian part on demand")
#   OUT/stock/, OUT/stock-gltf/   with --stock only: Debian's unpatched
#                  Draco 1.5.5 built the same way, for size comparisons
#                  (scripts/web-sizes.sh)
# and lays out OUT/draco3d-uv/ (see write_package below), then, unless
# --no-check, decodes every golden file with its three decoders
# (tests/web/check_golden.js; the default one with and without its
# Laplacian part).
#
# Needs emscripten, python3-ply, nodejs, cmake, ninja-build, libeigen3-dev
# and (for minified glue; without it the glue is copied as emscripten wrote
# it) terser: ./draco-uv.sh web and ./draco-uv.sh test install them (test
# runs this script with --no-check before CTest, which runs the golden
# checks as web.golden_*). Each build folder is
# configured once (again when this script's CMake arguments change); later
# runs rebuild what changed. A CMake run regenerates Draco's IDL glue, on
# which every object depends, and so recompiles the whole target.
set -euo pipefail
cd "$(dirname "$0")/.."
readonly ROOT=$PWD

die() { echo "build-web.sh: $*" >&2; exit 1; }

with_stock=0
check=1
while [[ $# -gt 0 ]]; do
  case "$1" in
    --stock) with_stock=1; shift ;;
    --no-check) check=0; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d'; exit 0 ;;
    -*) die "unknown option $1" ;;
    *) break ;;
  esac
done
readonly OUT=$(realpath -m "${1:-build-web}")
readonly PACKAGE_DIR="${OUT}/draco3d-uv"
readonly STOCK_SOURCE="${ROOT}/third_party/debian-draco-1.5.5+dfsg-2"
readonly JOBS=${WEB_JOBS:-$(nproc)}

# Debian's emscripten: Draco's CMake reads $EMSCRIPTEN for the IDL binder;
# the binder needs a Python with ply (python3-ply), named explicitly so that
# CMake does not pick another Python; emscripten's link step and terser load
# Node modules from Debian's folder, which a Node.js from elsewhere (e.g.
# NodeSource's) does not search by itself.
export EMSCRIPTEN=/usr/share/emscripten
export NODE_PATH="/usr/share/nodejs${NODE_PATH:+:${NODE_PATH}}"
readonly PYTHON=/usr/bin/python3

for tool in emcmake em++ cmake ninja node "${PYTHON}"; do
  command -v "${tool}" >/dev/null || die "${tool} is missing (./draco-uv.sh web installs it)"
done
"${PYTHON}" -c 'import ply' 2>/dev/null ||
  die "Python's ply is missing (apt-get install python3-ply)"

# Every build, ours and stock: Draco's release settings (CMake's Release:
# -O3) with link-time optimisation, which Draco's own DRACO_FAST option also
# asks for (--llvm-lto 1); with -flto the decoder is 4 KB smaller gzipped at
# the same speed (benchmarks/web.md, "Reducing it").
readonly CMAKE_ARGS=(
  -G Ninja -DCMAKE_BUILD_TYPE=Release -DDRACO_WASM=ON
  -DPYTHON_EXECUTABLE="${PYTHON}" -DCMAKE_CXX_FLAGS=-flto -DCMAKE_C_FLAGS=-flto
)

# configure NAME SOURCE_DIR CMAKE_ARGS...: an Emscripten build folder
# OUT/NAME, configured again only when its arguments changed.
configure() {
  local name=$1 source=$2
  shift 2
  local args="${source} ${CMAKE_ARGS[*]} $*"
  local stamp="${OUT}/${name}.configure-args"
  if [[ -f "${OUT}/${name}/build.ninja" && -f "${stamp}" &&
        "$(cat "${stamp}")" == "${args}" ]]; then
    return
  fi
  echo "build-web.sh: configuring ${OUT}/${name}"
  nice emcmake cmake -S "${source}" -B "${OUT}/${name}" "${CMAKE_ARGS[@]}" \
    "$@" >"${OUT}/${name}.configure.log" 2>&1 ||
    die "configuring ${name} failed; see ${OUT}/${name}.configure.log"
  echo "${args}" >"${stamp}"
}

# build NAME TARGETS...
build() {
  local name=$1
  shift
  echo "build-web.sh: building $* in ${OUT}/${name}"
  nice ninja -C "${OUT}/${name}" -j "${JOBS}" "$@" >"${OUT}/${name}.build.log" 2>&1 ||
    { tail -n 30 "${OUT}/${name}.build.log" >&2; die "building ${name} failed; see ${OUT}/${name}.build.log"; }
}

# minify SOURCE DEST: the glue through terser (Draco's releases run it
# through Closure, which Debian does not package in a usable version).
minify() {
  if command -v terser >/dev/null; then
    nice terser "$1" --compress --mangle --output "$2" ||
      die "terser failed on $1"
  else
    echo "build-web.sh: terser is missing; $2 is not minified" >&2
    cp "$1" "$2"
  fi
}

# The package: one folder that serves as
#  * three.js's decoder path (DRACOLoader.setDecoderPath): draco_wasm_wrapper.js
#    (defines DracoDecoderModule), draco_decoder.wasm and the Laplacian part
#    it loads on demand, draco_decoder_laplacian.wasm; draco_decoder.js
#    (asm.js fallback, every coder in one file), and gltf/ with the same
#    four files of the glTF-only decoder;
#  * the npm package draco3d: package.json whose main draco3d.js exports
#    createDecoderModule and createEncoderModule, and draco3d's file names
#    draco_decoder_nodejs.js / draco_encoder_nodejs.js;
#  * Draco's javascript/ folder's encoder files: draco_encoder_wrapper.js
#    (defines DracoEncoderModule) and draco_encoder.wasm.
write_package() {
  local uv="${OUT}/uv" gltf="${OUT}/uv-gltf"
  local ondemand="${OUT}/uv-ondemand" gltf_ondemand="${OUT}/uv-gltf-ondemand"
  rm -rf "${PACKAGE_DIR}"
  mkdir -p "${PACKAGE_DIR}/gltf"
  cp "${ondemand}/draco/draco_decoder.wasm" \
    "${ondemand}/draco/draco_decoder_laplacian.wasm" \
    "${uv}/draco/draco_encoder.wasm" "${PACKAGE_DIR}/"
  minify "${ondemand}/draco/draco_decoder.js" "${PACKAGE_DIR}/draco_wasm_wrapper.js"
  minify "${uv}/asmjs/draco_decoder.js" "${PACKAGE_DIR}/draco_decoder.js"
  minify "${uv}/draco/draco_encoder.js" "${PACKAGE_DIR}/draco_encoder_wrapper.js"
  # The glTF decoder's glue names its .wasm draco_decoder_gltf.wasm; in gltf/
  # it is draco_decoder.wasm, as in three.js's folder, so that a loader that
  # lets the module find its .wasm itself finds it.
  cp "${gltf_ondemand}/draco/draco_decoder_gltf.wasm" "${PACKAGE_DIR}/gltf/draco_decoder.wasm"
  # The part does not depend on the decoder's features: one build serves
  # both folders.
  cp "${ondemand}/draco/draco_decoder_laplacian.wasm" "${PACKAGE_DIR}/gltf/"
  local file
  for file in "${gltf_ondemand}/draco/draco_decoder_gltf.js" "${gltf}/asmjs/draco_decoder_gltf.js"; do
    grep -q '"draco_decoder_gltf.wasm"' "${file}" ||
      die "${file} does not name draco_decoder_gltf.wasm"
  done
  sed 's/"draco_decoder_gltf\.wasm"/"draco_decoder.wasm"/' \
    "${gltf_ondemand}/draco/draco_decoder_gltf.js" >"${OUT}/draco_wasm_wrapper_gltf.js"
  minify "${OUT}/draco_wasm_wrapper_gltf.js" "${PACKAGE_DIR}/gltf/draco_wasm_wrapper.js"
  minify "${gltf}/asmjs/draco_decoder_gltf.js" "${PACKAGE_DIR}/gltf/draco_decoder.js"
  cp web/package/* "${PACKAGE_DIR}/"
  cp "${uv}/draco-patched/LICENSE" "${PACKAGE_DIR}/LICENSE"
  echo "build-web.sh: wrote ${PACKAGE_DIR}"
  (cd "${PACKAGE_DIR}" && find . -type f | sort | xargs ls -l | awk '{printf "  %9d  %s\n", $5, $9}')
}

mkdir -p "${OUT}"
configure uv "${ROOT}"
build uv draco_decoder draco_encoder draco_decoder_asmjs
configure uv-gltf "${ROOT}" -DDRACO_GLTF_BITSTREAM=ON
build uv-gltf draco_decoder_asmjs
configure uv-gltf-ondemand "${ROOT}" -DDRACO_GLTF_BITSTREAM=ON -DDRACO_UV_LAPLACIAN_ON_DEMAND=ON
build uv-gltf-ondemand draco_decoder
configure uv-ondemand "${ROOT}" -DDRACO_UV_LAPLACIAN_ON_DEMAND=ON
build uv-ondemand draco_decoder draco_decoder_laplacian
write_package

if [[ ${with_stock} -eq 1 ]]; then
  # Debian's Draco source, unpatched (the same tarball our build patches).
  scripts/fetch-draco-source.sh "${STOCK_SOURCE}"
  # C++17 like ours (Draco 1.5.5 itself asks for no standard).
  configure stock "${STOCK_SOURCE}" -DCMAKE_CXX_STANDARD=17
  build stock draco_decoder draco_encoder
  configure stock-gltf "${STOCK_SOURCE}" -DCMAKE_CXX_STANDARD=17 -DDRACO_GLTF_BITSTREAM=ON
  build stock-gltf draco_decoder
fi

if [[ ${check} -eq 1 ]]; then
  # The golden files decode to the native decoder's values with each decoder;
  # without its Laplacian part the default one must refuse the lossy
  # (Laplacian) ones with an error.
  for module in draco_wasm_wrapper.js draco_decoder.js gltf/draco_wasm_wrapper.js \
                "--without-laplacian-part draco_wasm_wrapper.js" \
                "--without-laplacian-part gltf/draco_wasm_wrapper.js"; do
    read -r -a args <<<"${module}"
    args[-1]="${PACKAGE_DIR}/${args[-1]}"
    log="${OUT}/check_golden.$(echo "${module}" | tr "/ " "__").log"
    if node tests/web/check_golden.js "${args[@]}" >"${log}" 2>&1; then
      echo "build-web.sh: ${module}: $(tail -n 1 "${log}")"
    else
      grep -v '^ok ' "${log}" >&2
      die "${module##* } does not decode the golden files to the native values; see ${log}"
    fi
  done
fi
