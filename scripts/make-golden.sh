#!/usr/bin/env bash
# Golden bitstreams: every mesh below encoded with every row of
# testdata/golden/variants.tsv (NAME<TAB>draco_encoder flags) into
# testdata/golden/MESH.NAME.drc, and what each decodes to in
# testdata/golden/expected.tsv (draco_uv_digest: a hash of the quantized
# values at every corner).
#
#   scripts/make-golden.sh [BUILD_DIR]                 (re)write the files
#   scripts/make-golden.sh --check-encode BUILD_DIR    our encoder still writes
#                                                      exactly these bytes
#   scripts/make-golden.sh --check-decode BUILD_DIR    our decoder still reads
#                                                      exactly these values
#
# A new scheme or setting is one line in variants.tsv; run this script and
# commit the new files. Changing a bitstream on purpose means rewriting the
# goldens in the same commit (and bumping the scheme's format version).
set -euo pipefail
cd "$(dirname "$0")/.."

mode=write
case "${1:-}" in
  --check-encode|--check-decode) mode=${1#--}; shift ;;
esac
build_dir=${1:-build}
golden_dir=testdata/golden
encoder="${build_dir}/draco/draco_encoder"
digest="${build_dir}/draco/draco_uv_digest"
# Two self-made meshes (one chart; six charts) and Draco's tiny seamed cube.
meshes=(
  testdata/torus_uv.obj
  testdata/bumpy_cube_sphere.obj
  "${build_dir}/draco-patched/testdata/cube_att.obj"
)

die() { echo "make-golden.sh: $*" >&2; exit 1; }
for tool in "${encoder}" "${digest}"; do
  [[ -x "${tool}" ]] || die "missing ${tool}; build first (ninja -C ${build_dir})"
done

# Every (mesh, variant) as "MESH.NAME.drc<TAB>mesh path<TAB>flags".
golden_list() {
  local mesh name flags
  for mesh in "${meshes[@]}"; do
    while IFS=$'\t' read -r name flags; do
      [[ -z "${name}" || "${name}" == \#* ]] && continue
      printf '%s.%s.drc\t%s\t%s\n' "$(basename "${mesh}" .obj)" "${name}" \
        "${mesh}" "${flags}"
    done <"${golden_dir}/variants.tsv"
  done
}

encode_all() {  # encode_all OUT_DIR
  local file mesh flags
  while IFS=$'\t' read -r file mesh flags; do
    # shellcheck disable=SC2086  # flags are words
    "${encoder}" -i "${mesh}" -o "$1/${file}" ${flags} >/dev/null ||
      die "encoding ${file} failed: ${encoder} -i ${mesh} ${flags}"
  done < <(golden_list)
}

digest_all() {  # digest_all DIR: expected.tsv lines for the golden files
  local files tool
  mapfile -t files < <(golden_list | cut -f1)
  tool=$(realpath "${digest}")
  (cd "$1" && "${tool}" "${files[@]}")
}

case "${mode}" in
  write)
    rm -f "${golden_dir}"/*.drc
    encode_all "${golden_dir}"
    digest_all "${golden_dir}" >"${golden_dir}/expected.tsv"
    ls -l "${golden_dir}"
    ;;
  check-encode)
    work=$(mktemp -d)
    trap 'rm -rf "${work}"' EXIT
    encode_all "${work}"
    failures=0 count=0
    while IFS=$'\t' read -r file _; do
      count=$((count + 1))
      if [[ ! -f "${golden_dir}/${file}" ]]; then
        echo "FAIL: ${file} is not committed; run scripts/make-golden.sh"
        failures=$((failures + 1))
      elif ! cmp -s "${work}/${file}" "${golden_dir}/${file}"; then
        echo "FAIL: ${file}: the encoder's bytes changed ($(cmp "${work}/${file}" "${golden_dir}/${file}" | head -1))"
        failures=$((failures + 1))
      fi
    done < <(golden_list)
    echo "golden files re-encoded: ${count}, changed or missing: ${failures}"
    [[ ${failures} -eq 0 && ${count} -gt 0 ]]
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
