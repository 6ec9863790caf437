#!/usr/bin/env bash
# Unknown flags in the patched draco_encoder and draco_transcoder
# (draco_ext/options/draco_uv_flags.h):
#  1. A flag that looks like draco-uv's but is not one of this build's
#     (-uv_prd, -uvpred, --uv_pred, -uv_pred=auto, -tangent_prd, ...) exits
#     non-zero with "Error: unknown flag ..." naming the closest flag, and
#     writes no output file.
#  2. Any other unknown flag (-foo, and the other tool's stock flags) prints
#     "Warning: ignoring unknown flag ..." to stderr, once, not for its
#     value, and the output is byte-identical to the run without it.
#  3. Every stock flag of the tool, with its value, prints no warning, and
#     the output is byte-identical to Debian's stock tool's; draco-uv's own
#     flags print no warning either (-qtg is draco_transcoder's own flag and
#     draco_encoder's of draco-uv; the stock -q flags near it stay stock's).
#
#   unknown_flags_test.sh OUR_ENCODER OUR_TRANSCODER OBJ_MESH GLTF_ASSET
set -uo pipefail

our_encoder=$1 our_transcoder=$2 mesh=$3 asset=$4
stock_encoder=/usr/bin/draco_encoder stock_transcoder=/usr/bin/draco_transcoder
for tool in "${stock_encoder}" "${stock_transcoder}"; do
  [[ -x "${tool}" ]] || { echo "missing ${tool} (apt-get install draco)"; exit 1; }
done

work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
failures=0 checks=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# run NAME TOOL INPUT OUTPUT ARGS...: runs TOOL -i INPUT -o OUTPUT ARGS...
# with a fresh OUTPUT; its stdout, stderr and exit status go to
# ${work}/NAME.{out,err,status}.
run() {
  local name=$1 tool=$2 input=$3 output=$4
  shift 4
  rm -f "${output}"
  "${tool}" -i "${input}" -o "${output}" "$@" >"${work}/${name}.out" \
    2>"${work}/${name}.err"
  echo $? >"${work}/${name}.status"
  checks=$((checks + 1))
}
status() { cat "${work}/$1.status"; }

# expect_error NAME TOOL INPUT OUTPUT MESSAGE ARGS...: exits non-zero, stderr
# has the line "Error: MESSAGE", no output file.
expect_error() {
  local name=$1 tool=$2 input=$3 output=$4 message=$5
  shift 5
  run "${name}" "${tool}" "${input}" "${output}" "$@"
  [[ $(status "${name}") -ne 0 ]] || fail "${name} ($*): exit 0"
  grep -qxF "Error: ${message}" "${work}/${name}.err" ||
    fail "${name} ($*): no 'Error: ${message}' on stderr: $(cat "${work}/${name}.err")"
  [[ ! -e "${output}" ]] || fail "${name} ($*): wrote ${output}"
}

# expect_warnings NAME TOOL INPUT OUTPUT REFERENCE WARNINGS ARGS...: exits 0,
# stderr is exactly the lines of WARNINGS ("" for none: stderr empty),
# stdout has no warning, and OUTPUT is byte-identical to REFERENCE.
expect_warnings() {
  local name=$1 tool=$2 input=$3 output=$4 reference=$5 warnings=$6
  shift 6
  run "${name}" "${tool}" "${input}" "${output}" "$@"
  [[ $(status "${name}") -eq 0 ]] ||
    fail "${name} ($*): exit $(status "${name}"): $(cat "${work}/${name}.err")"
  printf '%s' "${warnings}${warnings:+$'\n'}" >"${work}/${name}.expected"
  cmp -s "${work}/${name}.err" "${work}/${name}.expected" ||
    fail "${name} ($*): stderr is '$(cat "${work}/${name}.err")', expected '${warnings}'"
  ! grep -q "Warning\|unknown flag" "${work}/${name}.out" ||
    fail "${name} ($*): warning on stdout"
  cmp -s "${output}" "${reference}" || fail "${name} ($*): output differs from ${reference}"
}

# The tools, each with its input, output and every stock flag of its own
# with a value (the encoder's boolean flags too: -preserve_polygons,
# --metadata; -point_cloud would read the mesh as a point cloud).
tools=(encoder transcoder)
declare -A tool_of=([encoder]="${our_encoder}" [transcoder]="${our_transcoder}")
declare -A stock_of=([encoder]="${stock_encoder}" [transcoder]="${stock_transcoder}")
declare -A input_of=([encoder]="${mesh}" [transcoder]="${asset}")
declare -A ext_of=([encoder]=drc [transcoder]=glb)
declare -A stock_flags_of=(
  [encoder]="-qp 12 -qt 11 -qn 9 -qg 7 -cl 8 --skip GENERIC --metadata -preserve_polygons"
  [transcoder]="-qp 12 -qt 11 -qn 9 -qc 7 -qtg 7 -qw 7 -qg 7")
# Stock flags of the other tool: unknown here.
declare -A other_flags_of=([encoder]="-qw 7" [transcoder]="-cl 7")
# draco-uv flags of this build that the tool takes.
declare -A uv_flags_of=(
  [encoder]="-cl 10 -uv_pred auto -uv_seams context -tangent_pred auto -qtg 10"
  [transcoder]="-uv_pred weighted -uv_seams context -tangent_pred auto")

for name in "${tools[@]}"; do
  tool=${tool_of[${name}]} input=${input_of[${name}]} ext=${ext_of[${name}]}
  out="${work}/${name}.${ext}"
  read -r -a stock_flags <<<"${stock_flags_of[${name}]}"
  read -r -a uv_flags <<<"${uv_flags_of[${name}]}"
  read -r -a other_flags <<<"${other_flags_of[${name}]}"

  # 3. Known flags: no warning; stock flags write stock's bytes.
  ref="${work}/${name}_ref.${ext}"
  "${tool}" -i "${input}" -o "${ref}" >/dev/null 2>&1 ||
    { fail "${name}: plain run failed"; continue; }
  expect_warnings "${name}_plain" "${tool}" "${input}" "${out}" "${ref}" ""
  stock_ref="${work}/${name}_stock.${ext}"
  "${stock_of[${name}]}" -i "${input}" -o "${stock_ref}" "${stock_flags[@]}" \
    >/dev/null 2>&1 || fail "${name}: stock tool failed with ${stock_flags[*]}"
  expect_warnings "${name}_stock_flags" "${tool}" "${input}" "${out}" \
    "${stock_ref}" "" "${stock_flags[@]}"
  cmp -s "${stock_ref}" "${ref}" &&
    fail "${name}: ${stock_flags[*]} changed nothing (a weak check)"
  uv_ref="${work}/${name}_uv.${ext}"
  "${tool}" -i "${input}" -o "${uv_ref}" "${uv_flags[@]}" >/dev/null 2>&1 ||
    fail "${name}: ${uv_flags[*]} failed"
  expect_warnings "${name}_uv_flags" "${tool}" "${input}" "${out}" "${uv_ref}" \
    "" "${uv_flags[@]}"

  # 2. Other unknown flags: a warning each, never for a value, same bytes.
  expect_warnings "${name}_foo" "${tool}" "${input}" "${out}" "${ref}" \
    "Warning: ignoring unknown flag -foo" -foo
  expect_warnings "${name}_foo_value" "${tool}" "${input}" "${out}" "${ref}" \
    "Warning: ignoring unknown flag -foo" -foo 3
  # Negative numbers and words are values, not flags.
  expect_warnings "${name}_foo_negative" "${tool}" "${input}" "${out}" "${ref}" \
    "Warning: ignoring unknown flag --verbose" --verbose -2 extra_word
  expect_warnings "${name}_two" "${tool}" "${input}" "${out}" "${ref}" \
    "Warning: ignoring unknown flag -x
Warning: ignoring unknown flag -pred" -x -pred auto
  expect_warnings "${name}_other_tool" "${tool}" "${input}" "${out}" "${ref}" \
    "Warning: ignoring unknown flag ${other_flags[0]}" "${other_flags[@]}"
  expect_warnings "${name}_with_stock" "${tool}" "${input}" "${out}" \
    "${stock_ref}" "Warning: ignoring unknown flag -foo" \
    "${stock_flags[@]:0:2}" -foo "${stock_flags[@]:2}"
  # A stock flag without its value at the end: skipped, as stock does, with
  # a warning.
  expect_warnings "${name}_missing_value" "${tool}" "${input}" "${out}" \
    "${ref}" "Warning: ignoring -qp: no value follows it" -qp
  # -qtg has stock draco_transcoder's name: the same in both tools.
  expect_warnings "${name}_qtg_missing_value" "${tool}" "${input}" "${out}" \
    "${ref}" "Warning: ignoring -qtg: no value follows it" -qtg

  # 1. Misspelt draco-uv flags: an error, no file.
  for case in "-uv_prd|-uv_pred" "-uvpred|-uv_pred" "--uv_pred|-uv_pred" \
              "-UV_PRED|-uv_pred" "-uv_seam|-uv_seams" "-uv-anchors|-uv_anchors" \
              "-uv_texel|-uv_texels" "-uv_texture|-uv_texture_size"; do
    flag=${case%|*} meant=${case#*|}
    expect_error "${name}_typo" "${tool}" "${input}" "${out}" \
      "unknown flag ${flag}; did you mean ${meant}?" "${flag}" auto
  done
  expect_error "${name}_typo_first" "${tool}" "${input}" "${out}" \
    "unknown flag -uv_prd; did you mean -uv_pred?" -uv_prd auto -cl 7
  expect_error "${name}_typo_last" "${tool}" "${input}" "${out}" \
    "unknown flag -uv_prd; did you mean -uv_pred?" -cl 7 -uv_prd
  expect_error "${name}_equals" "${tool}" "${input}" "${out}" \
    "unknown flag -uv_pred=auto; did you mean -uv_pred auto?" -uv_pred=auto
  expect_error "${name}_after_foo" "${tool}" "${input}" "${out}" \
    "unknown flag -uv_prd; did you mean -uv_pred?" -foo -uv_prd auto
  # A flag of a family that this build lacks, or a near miss: an error.
  for flag in -tangent_kinds -tangent_prd --tangent_pred -uv_quality; do
    run "${name}_family" "${tool}" "${input}" "${out}" "${flag}" auto
    [[ $(status "${name}_family") -ne 0 ]] || fail "${name} ${flag}: exit 0"
    grep -q "^Error: unknown flag ${flag}; " "${work}/${name}_family.err" ||
      fail "${name} ${flag}: no error: $(cat "${work}/${name}_family.err")"
    [[ ! -e "${out}" ]] || fail "${name} ${flag}: wrote ${out}"
  done
done

echo "tool runs: ${checks}; failures: ${failures}"
[[ ${checks} -ge 54 && ${failures} -eq 0 ]]
