#!/usr/bin/env bash
# libFuzzer campaigns over draco-uv's decoders and encoders, in a separate
# clang build with AddressSanitizer and UndefinedBehaviorSanitizer
# (build-fuzz/, never the test build; ccache is shared).
#
#   scripts/fuzz.sh build            configure and build the sanitizer build
#   scripts/fuzz.sh run [SECONDS]    every target for SECONDS (default 60)
#   scripts/fuzz.sh smoke [SECONDS]  every target but decode:stock for SECONDS
#                                    (default 4); exits 77 (skipped) without
#                                    the build
#   scripts/fuzz.sh deep RUNS [NAME...]
#                                    decode:NAME targets (default: every
#                                    variant, then tangent) for RUNS
#                                    executions each, seeded with the small
#                                    golden meshes only
#                                    (testdata/golden/small_*.NAME.drc and
#                                    cube_att, tens of vertices; for tangent
#                                    every tangent golden file), so ASan
#                                    runs thousands of decodes a second
#
# Targets (tests/fuzz/):
#   decode:NAME  draco_uv_decode_fuzzer, one per row NAME of
#                testdata/golden/variants.tsv, seeded with that row's golden
#                files testdata/golden/*.NAME.drc (and reading the crash
#                regressions of testdata/fuzz/decode/), so every scheme and
#                variant gets its own corpus;
#   decode:tangent  draco_uv_decode_fuzzer seeded with the golden files of
#                every row of testdata/golden/tangent_variants.tsv
#                (testdata/golden/*.tangent_*.drc: the small glTF meshes with
#                tangents, MESH_PREDICTION_GEOMETRIC_TANGENT with every
#                convention, and stock coding of the same tangents), one
#                corpus for the tangent scheme's settings;
#   decode:laplacian  draco_uv_decode_fuzzer seeded with the lossy
#                Laplacian schemes' golden files testdata/golden/lossy/
#                (encoder output only: their decoded floats may differ
#                between builds);
#   roundtrip    draco_uv_roundtrip_fuzzer: encode -> decode of generated
#                degenerate meshes with every -uv_pred name.
# Corpora grow in build-fuzz/corpus/TARGET/ from run to run. The table at the
# end gives executions, corpus size and crashes per target, and apart from
# the crashes the inputs on which stock Draco's own code asks for more than
# the 1 GB malloc limit ("stock", moved to build-fuzz/artifacts/TARGET/stock/;
# see stock_oom()).
#
# Adding a scheme or variant: one line in testdata/golden/variants.tsv, then
# scripts/make-golden.sh; that makes a new decode target with its seeds (and
# the malformed-input tests and scripts/check-determinism.sh cover it). A
# line in tangent_variants.tsv adds its files to decode:tangent's seeds. New
# -uv_pred names reach the round-trip fuzzer by themselves
# (UvPredictionNames()); a new encoder option such as -uv_seams is one line
# in draco_uv_roundtrip_fuzzer.cc that sets its UvEncodeSettings field from
# the fuzz data.
#
# A crash leaves its input in build-fuzz/artifacts/TARGET/. Fix it, then copy
# the input to testdata/fuzz/decode/ or testdata/fuzz/roundtrip/: CTest's
# tools.fuzz_regressions replays those files in every build.
set -euo pipefail
cd "$(dirname "$0")/.."

readonly FUZZ_BUILD_DIR=${FUZZ_BUILD_DIR:-build-fuzz}
# Every UBSan check stops the run, except "enum", which
# tests/fuzz/stock_draco_ubsan.supp suppresses where stock Draco does it
# (suppressions need recoverable checks; halt_on_error stops on the rest).
readonly SANITIZE_FLAGS="-fsanitize=fuzzer-no-link,address,undefined \
-fno-sanitize-recover=all -fsanitize-recover=enum -fno-omit-frame-pointer"
readonly TARGETS=(draco_uv_decode_fuzzer draco_uv_roundtrip_fuzzer)

die() { echo "fuzz.sh: $*" >&2; exit 1; }

build() {
  command -v clang++ >/dev/null || die "clang++ is missing (apt-get install clang)"
  CCACHE_BASEDIR=${CCACHE_BASEDIR:-$PWD} cmake -S . -B "${FUZZ_BUILD_DIR}" -G Ninja \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_C_FLAGS="${SANITIZE_FLAGS}" -DCMAKE_CXX_FLAGS="${SANITIZE_FLAGS}" \
    -DDRACO_UV_TESTS=OFF -DDRACO_UV_FUZZERS=ON \
    $(command -v ccache >/dev/null && echo -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
      -DCMAKE_C_COMPILER_LAUNCHER=ccache) >/dev/null
  cmake --build "${FUZZ_BUILD_DIR}" --target "${TARGETS[@]}" --parallel "$(nproc)"
}

# Names from testdata/golden/variants.tsv.
variant_names() {
  grep -v -e '^#' -e '^$' testdata/golden/variants.tsv | cut -f1
}

# copy_seeds NAME PATTERN DIR: the golden files of decode:NAME whose mesh
# matches PATTERN ('*': all; the rows of tangent_variants.tsv for tangent)
# into DIR; false when there are none.
copy_seeds() {
  local files=()
  rm -rf "$3" && mkdir -p "$3"
  if [[ $1 == tangent ]]; then
    # shellcheck disable=SC2206  # the pattern is a glob
    files=(testdata/golden/$2.tangent_*.drc)
  else
    # shellcheck disable=SC2206
    files=(testdata/golden/$2."$1".drc)
  fi
  [[ -e "${files[0]}" ]] && cp "${files[@]}" "$3/"
}

# stock_oom BINARY FILE: whether the oversized allocation FILE makes (an
# out-of-memory artifact) is stock Draco's: the first frame of its stack in
# our source trees is in Draco's own sources. Draco 1.5.5 sizes some buffers
# from header counts before reading the data they count (benchmarks/
# hostile.md); an out-of-memory in draco-uv's code or the harness, or one
# without a stack (the RSS limit), is not stock.
stock_oom() {
  local frame
  frame=$(ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0} \
    "$1" -rss_limit_mb=2048 -malloc_limit_mb=1024 "$2" 2>&1 |
    grep -m1 -E ' in .* /[^ ]*/(draco-patched/src/draco|draco_ext|prediction_schemes|tests)/' ||
    true)
  [[ ${frame} == */draco-patched/src/draco/* ]]
}

# run_target LABEL BINARY SECONDS SEED_DIR...: prints one table row (the
# seconds it took, executions, corpus size, crashes, stock OOMs). With
# RUNS set, the campaign stops after RUNS executions instead (SECONDS is then
# only a safety limit) and keeps its own corpus, apart from the timed ones.
run_target() {
  local label=$1 binary=$2 seconds=$3
  shift 3
  local dir=${label/:/_}${RUNS:+_deep}
  local corpus="${FUZZ_BUILD_DIR}/corpus/${dir}"
  local artifacts="${FUZZ_BUILD_DIR}/artifacts/${dir}"
  local log="${FUZZ_BUILD_DIR}/logs/${dir}.log"
  mkdir -p "${corpus}" "${artifacts}" "$(dirname "${log}")"
  local seeds=() seed_dir
  for seed_dir in "$@"; do
    [[ -d "${seed_dir}" ]] && seeds+=("${seed_dir}")
  done
  # Fork mode with -ignore_*: the campaign goes on after a crash, timeout
  # or out-of-memory; each leaves its input in ${artifacts}.
  local status=0 start t0=${SECONDS}
  start=$(mktemp)
  ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0} \
  UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1:suppressions=${PWD}/tests/fuzz/stock_draco_ubsan.supp} \
    "${binary}" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
      -max_total_time="${seconds}" ${RUNS:+-runs=${RUNS}} -timeout=20 -rss_limit_mb=2048 \
      -malloc_limit_mb=1024 -artifact_prefix="${artifacts}/" \
      "${corpus}" "${seeds[@]}" >"${log}" 2>&1 || status=$?
  local executions corpus_size crashes stock=0 file
  # Fork mode's progress lines: "#EXECUTIONS: cov: ...".
  executions=$(sed -n 's/^#\([0-9]*\): cov:.*/\1/p' "${log}" | tail -1)
  corpus_size=$(find "${corpus}" -type f | wc -l)
  # Stock Draco's out-of-memory inputs are counted apart, in stock/.
  while IFS= read -r file; do
    if stock_oom "${binary}" "${file}"; then
      mkdir -p "${artifacts}/stock" && mv "${file}" "${artifacts}/stock/"
      stock=$((stock + 1))
    fi
  done < <(find "${artifacts}" -maxdepth 1 -type f -name 'oom-*' -newer "${start}")
  crashes=$(find "${artifacts}" -maxdepth 1 -type f -newer "${start}" | wc -l)
  rm -f "${start}"
  [[ ${crashes} -eq 0 ]] || status=1
  printf '%-34s %6s %12s %8s %8s %6s %s\n' "${label}" "$((SECONDS - t0))" \
    "${executions:-?}" "${corpus_size}" "${crashes}" "${stock}" \
    "$([[ ${status} -eq 0 ]] || echo "FAILED, see ${log} and ${artifacts}")"
  [[ ${status} -eq 0 ]]
}

# run_all SECONDS [SKIPPED_VARIANT]
run_all() {
  local seconds=$1 skipped=${2:-} bin="${FUZZ_BUILD_DIR}/tests/fuzz" failures=0 name
  printf '%-34s %6s %12s %8s %8s %6s\n' target seconds executions corpus crashes \
    stock
  for name in $(variant_names) tangent; do
    [[ "${name}" != "${skipped}" ]] || continue
    local seeds="${FUZZ_BUILD_DIR}/seeds/${name}"
    copy_seeds "${name}" '*' "${seeds}" ||
      echo "fuzz.sh: no golden files for ${name}; run scripts/make-golden.sh" >&2
    run_target "decode:${name}" "${bin}/draco_uv_decode_fuzzer" "${seconds}" \
      "${seeds}" testdata/fuzz/decode || failures=$((failures + 1))
  done
  run_target decode:laplacian "${bin}/draco_uv_decode_fuzzer" "${seconds}" \
    testdata/golden/lossy testdata/fuzz/decode || failures=$((failures + 1))
  run_target roundtrip "${bin}/draco_uv_roundtrip_fuzzer" "${seconds}" \
    testdata/fuzz/roundtrip || failures=$((failures + 1))
  echo "fuzz targets with crashes: ${failures}"
  [[ ${failures} -eq 0 ]]
}

# run_deep RUNS [NAME...]: deep decode campaigns from the small seeds.
run_deep() {
  local runs=$1 bin="${FUZZ_BUILD_DIR}/tests/fuzz" failures=0 name names
  shift
  names=("$@")
  [[ ${#names[@]} -gt 0 ]] || mapfile -t names < <(variant_names; echo tangent)
  printf '%-34s %6s %12s %8s %8s %6s\n' target seconds executions corpus crashes \
    stock
  for name in "${names[@]}"; do
    local seeds="${FUZZ_BUILD_DIR}/seeds-small/${name}"
    copy_seeds "${name}" 'small_*' "${seeds}" ||
      die "no small golden files for ${name}; run scripts/make-golden.sh"
    [[ ${name} == tangent ]] || cp testdata/golden/cube_att."${name}".drc "${seeds}/"
    RUNS=${runs} run_target "decode:${name}" "${bin}/draco_uv_decode_fuzzer" 86400 \
      "${seeds}" || failures=$((failures + 1))
  done
  echo "fuzz targets with crashes: ${failures}"
  [[ ${failures} -eq 0 ]]
}

have_build() {
  local target
  for target in "${TARGETS[@]}"; do
    [[ -x "${FUZZ_BUILD_DIR}/tests/fuzz/${target}" ]] || return 1
  done
}

main() {
  local command=${1:-}
  case "${command}" in
    build) build ;;
    run)
      have_build || build
      run_all "${2:-60}"
      ;;
    smoke)
      if ! have_build; then
        echo "fuzz.sh: no sanitizer build in ${FUZZ_BUILD_DIR} (scripts/fuzz.sh build); skipped"
        exit 77
      fi
      build >/dev/null  # Brings the targets up to date (a no-op if they are).
      # Not stock Draco's own decoder: its known slow input (a 2^31
      # orientation count, benchmarks/hostile.md) times out under ASan
      # within seconds and would make the test command flaky.
      run_all "${2:-4}" stock
      ;;
    deep)
      [[ ${2:-} =~ ^[0-9]+$ ]] || die "usage: $0 deep RUNS [NAME...]"
      have_build || build
      run_deep "${@:2}"
      ;;
    *) die "usage: $0 build | run [SECONDS] | smoke [SECONDS] | deep RUNS [NAME...]" ;;
  esac
}

main "$@"
