#!/usr/bin/env bash
# Golden bitstreams: every mesh below encoded with every row of
# testdata/golden/variants.tsv (NAME<TAB>draco_encoder flags) into
# testdata/golden/MESH.NAME.drc, every glTF mesh with tangents below with
# every row of testdata/golden/tangent_variants.tsv likewise, and what each
# decodes to in testdata/golden/expected.tsv (draco_uv_digest: a hash of
# the quantized values at every corner, tangents included). The lossy Laplacian coder's rows,
# testdata/golden/lossy/variants.tsv, pin the encoder's bytes only
# (testdata/golden/lossy/MESH.NAME.drc): its decoded floats may differ
# between builds and CPUs.
#
#   scripts/make-golden.sh [BUILD_DIR]                 (re)write the files
#   scripts/make-golden.sh --check-encode BUILD_DIR    our encoder still writes
#                                                      exactly these bytes
#   scripts/make-golden.sh --check-encode-exact BUILD_DIR
#                                                      the same without the
#                                                      lossy files (builds
#                                                      that contract floating
#                                                      point into FMAs)
#   scripts/make-golden.sh --check-decode BUILD_DIR    our decoder still reads
#                                                      exactly these values
#
# A new scheme or setting is one line in variants.tsv (tangent_variants.tsv
# for tangent settings, which need glTF input); run this script and commit
# the new files. Changing a bitstream on purpose means rewriting the
# goldens in the same commit (and bumping the scheme's format version).
set -euo pipefail
cd "$(dirname "$0")/.."

mode=write
case "${1:-}" in
  --check-encode|--check-encode-exact|--check-decode) mode=${1#--}; shift ;;
esac
build_dir=${1:-build}
golden_dir=testdata/golden
lossy_dir=testdata/golden/lossy
encoder="${build_dir}/draco/draco_encoder"
digest="${build_dir}/draco/draco_uv_digest"
# Two self-made meshes (one chart; six charts), the same two with tens of
# vertices (seeds for scripts/fuzz.sh deep) and Draco's tiny seamed cube.
meshes=(
  testdata/torus_uv.obj
  testdata/bumpy_cube_sphere.obj
  testdata/small_torus_uv.obj
  testdata/small_cube_sphere.obj
  "${build_dir}/draco-patched/testdata/cube_att.obj"
)
# The small ones as GLBs with MikkTSpace tangents, for tangent_variants.tsv
# (crane_spot_tangents.glb's files, 16-29 KB, would make the malformed-input
# tests truncate tens of thousands of times more).
tangent_meshes=(
  testdata/small_torus_uv_tangents.glb
  testdata/small_cube_sphere_tangents.glb
)

die() { echo "make-golden.sh: $*" >&2; exit 1; }
for tool in "${encoder}" "${digest}"; do
  [[ -x "${tool}" ]] || die "missing ${tool}; build first (ninja -C ${build_dir})"
done

# Every (mesh, row) of TABLE as "MESH.NAME.drc<TAB>mesh path<TAB>flags".
table_list() {  # table_list TABLE MESH...
  local table=$1 mesh name flags base
  shift
  for mesh in "$@"; do
    base=$(basename "${mesh}")
    while IFS=$'\t' read -r name flags; do
      [[ -z "${name}" || "${name}" == \#* ]] && continue
      printf '%s.%s.drc\t%s\t%s\n' "${base%.*}" "${name}" "${mesh}" "${flags}"
    done <"${table}"
  done
}

# Every golden file of DIR (default: the exact schemes' golden_dir): the
# meshes with DIR/variants.tsv, and in golden_dir the tangent meshes with
# tangent_variants.tsv.
golden_list() {  # golden_list [DIR]
  local dir=${1:-${golden_dir}}
  table_list "${dir}/variants.tsv" "${meshes[@]}"
  if [[ ${dir} == "${golden_dir}" ]]; then
    table_list "${golden_dir}/tangent_variants.tsv" "${tangent_meshes[@]}"
  fi
}

encode_all() {  # encode_all VARIANTS_DIR OUT_DIR
  local file mesh flags
  while IFS=$'\t' read -r file mesh flags; do
    # shellcheck disable=SC2086  # flags are words
    "${encoder}" -i "${mesh}" -o "$2/${file}" ${flags} >/dev/null ||
      die "encoding ${file} failed: ${encoder} -i ${mesh} ${flags}"
  done < <(golden_list "$1")
}

# Re-encodes the golden files of VARIANTS_DIR into WORK_DIR and compares
# them with the committed ones; prints each failure and adds to the counts
# check_count and check_failures.
check_encoded() {  # check_encoded VARIANTS_DIR WORK_DIR
  local file
  encode_all "$1" "$2"
  while IFS=$'\t' read -r file _; do
    check_count=$((check_count + 1))
    if [[ ! -f "$1/${file}" ]]; then
      echo "FAIL: $1/${file} is not committed; run scripts/make-golden.sh"
      check_failures=$((check_failures + 1))
    elif ! cmp -s "$2/${file}" "$1/${file}"; then
      echo "FAIL: $1/${file}: the encoder's bytes changed ($(cmp "$2/${file}" "$1/${file}" | head -1))"
      check_failures=$((check_failures + 1))
    fi
  done < <(golden_list "$1")
}

digest_all() {  # digest_all DIR: expected.tsv lines for the golden files
  local files tool
  mapfile -t files < <(golden_list | cut -f1)
  tool=$(realpath "${digest}")
  (cd "$1" && "${tool}" "${files[@]}")
}

case "${mode}" in
  write)
    rm -f "${golden_dir}"/*.drc "${lossy_dir}"/*.drc
    encode_all "${golden_dir}" "${golden_dir}"
    encode_all "${lossy_dir}" "${lossy_dir}"
    digest_all "${golden_dir}" >"${golden_dir}/expected.tsv"
    ls -l "${golden_dir}" "${lossy_dir}"
    ;;
  check-encode|check-encode-exact)
    work=$(mktemp -d)
    trap 'rm -rf "${work}"' EXIT
    check_failures=0 check_count=0
    check_encoded "${golden_dir}" "${work}"
    [[ ${mode} == check-encode ]] && check_encoded "${lossy_dir}" "${work}"
    echo "golden files re-encoded: ${check_count}, changed or missing: ${check_failures}"
    [[ ${check_failures} -eq 0 && ${check_count} -gt 0 ]]
    ;;
  check-decode)
    if diff <(digest_all "${golden_dir}") "${golden_dir}/expected.tsv"; then
      echo "golden files decoded as expected: $(wc -l <"${golden_dir}/expected.tsv")"
    else
      echo "FAIL: decoded values differ from ${golden_dir}/expected.tsv (< now, > expected)"
      exit 1
    fi
    ;;
esac
