#!/usr/bin/env bash
# The AVX2 build of the dense front kernel (draco_ext/linalg/dense_front_avx2.cc)
# shares no symbol with other objects but Eigen's, renamed: a weak symbol
# (template or inline function) that other objects also define would let the
# linker keep this object's AVX2 code for the whole program, which fails on
# CPUs without AVX2. Fails when the object is missing from the arguments,
# has no renamed Eigen symbol (the rename did not apply) or shares another.
#
#   dense_front_avx2_symbols_test.sh OBJECT... (or OBJECT;OBJECT;...)
set -uo pipefail

# CMake passes $<TARGET_OBJECTS:...> as one ';'-separated argument.
IFS=';' read -r -a files <<<"$*"
object=
for file in "${files[@]}"; do
  [[ ${file} == *dense_front_avx2.cc.o ]] && object=${file}
done
[[ -n ${object} ]] || { echo "FAIL: no dense_front_avx2 object given"; exit 1; }

# Weak (W, V) and unique (u) global definitions, mangled; the exception
# personality reference is data, the same in every object.
shared=$(nm --defined-only "${object}" | awk '$2 ~ /^[WVu]$/ {print $3}')
renamed=$(grep -c DracoUvEigenAvx2 <<<"${shared}")
others=$(grep -v -e DracoUvEigenAvx2 -e '^DW\.ref\.__gxx_personality_v0$' -e '^$' <<<"${shared}")
if [[ ${renamed} -eq 0 ]]; then
  echo "FAIL: no renamed Eigen symbol in ${object}"
  exit 1
fi
if [[ -n ${others} ]]; then
  echo "FAIL: ${object} shares symbols that other objects may define:"
  c++filt <<<"${others}"
  exit 1
fi
echo "OK: ${renamed} shared symbols, all in the renamed Eigen namespace"
