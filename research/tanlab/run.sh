#!/bin/bash
# Builds tanlab against a draco-uv build and prints its table for the
# corpus's Khronos glTFs and the tangent assets (scripts/make-tangent-assets.mjs).
#   research/tanlab/run.sh [BUILD_DIR] [ASSETS...]
set -euo pipefail
cd "$(dirname "$0")"
build=$(realpath "${1:-../../build}")
shift || true
src="${build}/draco-patched/src"
g++ -O2 -std=c++17 -I"${src}" -I"${build}" -I../.. -o "${build}/tanlab" tanlab.cc \
  "${src}/draco/io/stdio_file_reader.cc" "${src}/draco/io/stdio_file_writer.cc" \
  "${build}/draco/libdraco.a" -lpthread
if [[ $# -eq 0 ]]; then
  set -- ../../../shared/corpus/gltf/*.gltf
fi
"${build}/tanlab" "$@"
