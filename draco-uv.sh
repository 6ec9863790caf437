#!/usr/bin/env bash
# The two commands of draco-uv, each doing all set-up on Debian 12:
#
#   ./draco-uv.sh demo   installs what is missing, builds what it runs
#                        (libdraco and draco_uv_eval), and runs the main
#                        job: draco_uv_eval on a bundled mesh.
#   ./draco-uv.sh test   installs what is missing (also the web build's
#                        packages and Debian's chromium), builds, builds the
#                        web package build-web/draco3d-uv/ as `web` does, and
#                        runs every test with CTest: ours and Draco's own unit
#                        tests, a libFuzzer smoke run and the cross-build
#                        determinism check in extra clang builds, and the web
#                        tests (tests/web/: the pinned npm packages installed
#                        by a CTest fixture, the Node.js and headless-Chromium
#                        tests, the package's decoders on the golden files).
#   ./draco-uv.sh web    installs what is missing (Debian's emscripten and
#                        the tools around it) and builds the WebAssembly/JS
#                        decoder and encoder into build-web/ with
#                        scripts/build-web.sh: the package folder
#                        build-web/draco3d-uv/ (like npm draco3d and three.js's
#                        libs/draco/), checked on the golden files.
#
# BUILD_DIR (default: build) selects the build folder. Extra arguments after
# demo or test go to cmake at configure time (e.g. -DDRACO_SOURCE_DIR=...);
# after web, to scripts/build-web.sh (e.g. --stock, or another folder).
set -euo pipefail
cd "$(dirname "$0")"

readonly BUILD_DIR=${BUILD_DIR:-build}
# Build tools, Draco's dependencies as Debian packages them, Debian's stock
# Draco (for the compatibility tests), Python with matplotlib (charts) and
# clang with its sanitizer and libFuzzer runtimes (the determinism check and
# scripts/fuzz.sh).
readonly PACKAGES=(
  ca-certificates cmake g++ git ninja-build dpkg-dev xz-utils
  libeigen3-dev libtinygltf-dev libstb-dev nlohmann-json3-dev googletest
  draco python3 python3-matplotlib clang libclang-rt-dev
)
# Commands the tests need, each with the Debian package that provides it;
# a command already on PATH (e.g. from another Node.js distribution) is used
# as it is. node and npm run stock Draco's WebAssembly decoder (npm draco3d).
readonly COMMAND_PACKAGES=(node:nodejs npm:npm)
# The web build: the build tools and Eigen (the Laplacian decoder) of the
# native build, Debian's emscripten with the Python module its IDL binder
# needs (python3-ply, only suggested by emscripten), terser to minify the JS
# glue, brotli and wabt to measure and inspect the .wasm files.
readonly WEB_PACKAGES=(
  ca-certificates cmake git ninja-build dpkg-dev xz-utils libeigen3-dev
  emscripten python3-ply terser brotli wabt
)
# The web tests besides the web build: Debian's chromium, which the browser
# test starts headless (puppeteer-core).
readonly WEB_TEST_PACKAGES=(chromium)

die() { echo "draco-uv.sh: $*" >&2; exit 1; }

install_missing_packages() {  # install_missing_packages PACKAGE...
  local missing=() package
  for package in "$@"; do
    dpkg-query -W -f='${Status}\n' "${package}" 2>/dev/null |
      grep -q '^install ok installed$' || missing+=("${package}")
  done
  local entry
  for entry in "${COMMAND_PACKAGES[@]}"; do
    command -v "${entry%%:*}" >/dev/null || missing+=("${entry#*:}")
  done
  [[ ${#missing[@]} -eq 0 ]] && return
  if [[ $(id -u) -ne 0 ]]; then
    die "missing packages; run as root or install them: apt-get install ${missing[*]}"
  fi
  echo "draco-uv.sh: installing ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive apt-get update -q
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
    "${missing[@]}"
}

# Reads ninja's output and shows its progress: one line rewritten in place on
# a terminal, a line every tenth of the work otherwise.
show_progress() {
  local line done total percent shown=-1
  while IFS= read -r line; do
    [[ ${line} =~ ^\[([0-9]+)/([0-9]+)\] ]] || continue
    done=${BASH_REMATCH[1]} total=${BASH_REMATCH[2]}
    ((done > 0)) || continue
    percent=$((100 * done / total))
    if [[ -t 1 ]]; then
      printf '\rdraco-uv.sh: building %3d%% (%d/%d)' "${percent}" "${done}" "${total}"
    elif ((percent / 10 > shown)); then
      shown=$((percent / 10))
      echo "draco-uv.sh: building ${percent}% (${done}/${total})"
    fi
  done
  [[ -t 1 ]] && echo
  return 0
}

# build TARGETS [cmake arguments]: configures BUILD_DIR and builds the
# space-separated TARGETS (empty: all of them). cmake's and the compiler's
# output, pages of warnings from Draco's sources among it, go to
# BUILD_DIR/build.log; on failure the log's tail is shown.
build() {
  local targets=$1
  shift
  mkdir -p "${BUILD_DIR}"
  local log="${BUILD_DIR}/build.log" target_args=() target
  for target in ${targets}; do target_args+=(--target "${target}"); done
  echo "draco-uv.sh: building ${targets:-everything} in ${BUILD_DIR}/ (output in ${log})"
  local status=0
  {
    cmake -S . -B "${BUILD_DIR}" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" &&
      cmake --build "${BUILD_DIR}" --parallel "$(nproc)" "${target_args[@]}"
  } </dev/null 2>&1 | tee "${log}" | show_progress || status=${PIPESTATUS[0]}
  if [[ ${status} -ne 0 ]]; then
    tail -n 40 "${log}" >&2
    die "the build failed; above are the last lines of ${log}"
  fi
}

main() {
  [[ $# -ge 1 ]] || die "usage: $0 demo|test [cmake arguments] | web [build-web.sh arguments]"
  local command=$1
  shift
  case "${command}" in
    demo)
      install_missing_packages "${PACKAGES[@]}"
      build draco_uv_eval "$@"
      # A real textured mesh (Keenan Crane's spot, CC0; testdata/README.md):
      # stock Draco, the default auto, the smallest lossless coder, and the
      # recommended setting with context-coded seams.
      "${BUILD_DIR}/draco/draco_uv_eval" testdata/crane_spot.obj --qt 10,12 \
        --schemes draco,auto,weighted_multi,auto+context,weighted_multi+context \
        --plot "${BUILD_DIR}/crane_spot_rd.png"
      echo "UV bytes are what the texture coordinates cost in the .drc file;"
      echo "ratio is that against stock Draco's best of -cl 7 and -cl 10 (lower"
      echo "is smaller); RMSE is the same for every lossless coder: all decode"
      echo "the -qt grid exactly. Rate-distortion chart: ${BUILD_DIR}/crane_spot_rd.png"
      ;;
    test)
      install_missing_packages "${PACKAGES[@]}" "${WEB_PACKAGES[@]}" \
        "${WEB_TEST_PACKAGES[@]}"
      build "" "$@"
      # The sanitizer build for the fuzz smoke run (tools.fuzz_smoke); the
      # determinism check (tools.determinism) builds its own flavours. Both
      # tests skip with a message without clang.
      if command -v clang++ >/dev/null; then
        scripts/fuzz.sh build
      fi
      # The web package the web.* tests run against (tests/web/CMakeLists.txt);
      # its golden checks run as CTests (web.golden_*).
      scripts/build-web.sh --no-check
      ctest --test-dir "${BUILD_DIR}" --output-on-failure --parallel "$(nproc)"
      ;;
    web)
      install_missing_packages "${WEB_PACKAGES[@]}"
      scripts/build-web.sh "$@"
      ;;
    *) die "unknown command '${command}'; use demo, test or web" ;;
  esac
}

main "$@"
