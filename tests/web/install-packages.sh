#!/usr/bin/env bash
# Installs what the web tests import into tests/web/node_modules:
#  * the npm packages pinned by package-lock.json (npm ci, again only when
#    the lock file changed since the last install), from the registry the
#    machine's npm is configured for;
#  * draco3d-uv from the package folder PACKAGE_DIR (default:
#    build-web/draco3d-uv), packed with npm pack and installed as a copy,
#    as a user's `npm install` would, so that its modules resolve
#    @gltf-transform/*, three, ... from the same node_modules.
#
#   tests/web/install-packages.sh [PACKAGE_DIR]
set -euo pipefail
cd "$(dirname "$0")"
readonly PACKAGE_DIR=$(realpath "${1:-../../build-web/draco3d-uv}")
[[ -f "${PACKAGE_DIR}/package.json" ]] ||
  { echo "install-packages.sh: no package in ${PACKAGE_DIR} (run ./draco-uv.sh web)" >&2; exit 1; }

if ! cmp -s package-lock.json node_modules/.draco-uv-lock 2>/dev/null; then
  npm ci --ignore-scripts --no-audit --no-fund --fetch-retries=2
  cp package-lock.json node_modules/.draco-uv-lock
fi
work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
tarball=$(cd "${work}" && npm pack --silent "${PACKAGE_DIR}")
npm install --no-save --no-audit --no-fund --ignore-scripts --offline \
  "${work}/${tarball}" >/dev/null
echo "install-packages.sh: draco3d-uv from ${PACKAGE_DIR} in $(pwd)/node_modules"
