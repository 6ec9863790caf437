#!/usr/bin/env bash
# Cross-build determinism: every golden bitstream (testdata/golden/) decodes
# to the same values, and every golden input encodes to the same bytes, with
# draco_encoder and draco_uv_digest built by other compilers and flags as
# with the reference build (the test build: gcc -O3).
#
#   scripts/check-determinism.sh [REFERENCE_BUILD_DIR]   (default: build)
#
# Builds only the tools it needs (draco_encoder, draco_decoder,
# draco_uv_digest; no tests) in build-det-NAME/ for each row of BUILDS
# below, sharing ccache; exits 77 (skipped) when clang is missing. Checks,
# per build:
#   1. draco_uv_digest of every golden file equals the reference build's,
#      for the quantized values the bitstream codes and, in builds without
#      FMA contraction, for the dequantized values a normal decode returns;
#   2. its draco_decoder decodes the lossy Laplacian golden files
#      (testdata/golden/lossy/) without error; their floats may differ;
#   3. its draco_encoder writes every golden file byte for byte
#      (scripts/make-golden.sh --check-encode), in builds with FMA
#      contraction only those of the exact schemes (--check-encode-exact):
#      the lossy Laplacian coder picks its anchors by comparing float
#      reconstruction errors, which contracted products and Eigen's FMA
#      kernels change, so a near tie can go the other way (2 of its 12
#      golden files on 2026-12-02). Compiling just the Laplacian sources
#      without FMA and AVX in such a build is no way out: they share
#      Eigen's inline functions with the rest of the program, which then
#      disagree on alignment (a -march=native decoder crashed).
# Dequantization (q * delta + min) is stock Draco's float arithmetic: with
# -mfma -ffp-contract=fast it becomes a fused multiply-add and the last bit
# of the floats changes, for stock files as much as for draco-uv's. Every
# value draco-uv decodes is integer, so the quantized values must match in
# every build. (The gcc -O3 reference build is -ffp-contract=fast already,
# GCC's default, but targets x86-64 without FMA.)
# New schemes and variants need nothing here: they come in as rows of
# testdata/golden/variants.tsv. A new build flavour is one row of BUILDS.
set -euo pipefail
cd "$(dirname "$0")/.."

reference=${1:-build}
# NAME|C compiler|C++ compiler|compile flags|values compared|encodes compared
fma_flags="-ffp-contract=fast"
grep -qw fma /proc/cpuinfo 2>/dev/null && fma_flags="-mfma ${fma_flags}"
BUILDS=(
  "clang-O0|clang|clang++|-O0|--quantized --dequantized|--check-encode"
  "clang-O2-fpcontract|clang|clang++|-O2 ${fma_flags}|--quantized|--check-encode-exact"
)
readonly TOOLS=(draco_encoder draco_decoder draco_uv_digest)

die() { echo "check-determinism.sh: $*" >&2; exit 1; }
command -v clang++ >/dev/null || { echo "clang++ not found; skipped"; exit 77; }
[[ -x "${reference}/draco/draco_uv_digest" ]] ||
  die "no reference build in ${reference} (ninja -C ${reference})"

build_flavour() {  # build_flavour DIR CC CXX FLAGS
  local launcher=()
  mkdir -p "$1"
  command -v ccache >/dev/null &&
    launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD} cmake -S . -B "$1" -G Ninja \
    -DCMAKE_BUILD_TYPE=None -DCMAKE_C_COMPILER="$2" -DCMAKE_CXX_COMPILER="$3" \
    -DCMAKE_C_FLAGS="$4" -DCMAKE_CXX_FLAGS="$4" -DDRACO_UV_TESTS=OFF \
    "${launcher[@]}" >"$1/configure.log" 2>&1 ||
    die "configuring $1 failed (see $1/configure.log)"
  cmake --build "$1" --target "${TOOLS[@]}" --parallel "$(nproc)" \
    >"$1/build.log" 2>&1 || die "building $1 failed (see $1/build.log)"
}

# decode_all DIR FILE...: DIR's draco_decoder decodes every FILE (exit 0).
decode_all() {
  local dir=$1 file ok=0
  shift
  for file in "$@"; do
    if ! "${dir}/draco/draco_decoder" -i "${file}" -o "${work}/decoded.ply" \
        >/dev/null 2>&1; then
      echo "FAIL: ${dir}/draco/draco_decoder cannot decode ${file}"
      ok=1
    fi
  done
  return "${ok}"
}

golden=(testdata/golden/*.drc)
lossy=(testdata/golden/lossy/*.drc)
[[ -e "${golden[0]}" && -e "${lossy[0]}" ]] ||
  die "no golden files; run scripts/make-golden.sh"
work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
for mode in --quantized --dequantized; do
  flag=$([[ ${mode} == --dequantized ]] && echo --dequantized || true)
  # shellcheck disable=SC2086
  "${reference}/draco/draco_uv_digest" ${flag} "${golden[@]}" >"${work}/reference${mode}"
done

failures=0
for row in "${BUILDS[@]}"; do
  IFS='|' read -r name cc cxx flags modes encode_check <<<"${row}"
  dir="build-det-${name}"
  echo "== ${name} (${cxx} ${flags})"
  build_flavour "${dir}" "${cc}" "${cxx}" "${flags}"
  for mode in ${modes}; do
    flag=$([[ ${mode} == --dequantized ]] && echo --dequantized || true)
    # shellcheck disable=SC2086
    if "${dir}/draco/draco_uv_digest" ${flag} "${golden[@]}" >"${work}/${name}${mode}" &&
       diff "${work}/reference${mode}" "${work}/${name}${mode}"; then
      echo "decoded ${#golden[@]} golden files (${mode#--} values): identical"
    else
      echo "FAIL: ${name} decodes ${mode#--} values differently (< ${reference}, > ${name})"
      failures=$((failures + 1))
    fi
  done
  if decode_all "${dir}" "${lossy[@]}"; then
    echo "decoded ${#lossy[@]} lossy golden files without error (values not compared)"
  else
    failures=$((failures + 1))
  fi
  if scripts/make-golden.sh "${encode_check}" "${dir}"; then
    echo "encoded the golden files (${encode_check#--check-}): identical bytes"
  else
    failures=$((failures + 1))
  fi
done
echo "determinism checks failed: ${failures}"
[[ ${failures} -eq 0 ]]
