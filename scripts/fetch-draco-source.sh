#!/usr/bin/env bash
# Fetches Debian's source package of Draco (draco 1.5.5+dfsg-2), verifies it
# and unpacks it (with Debian's own patches) into DEST.
#
#   scripts/fetch-draco-source.sh DEST
#
# The package comes through apt-get source with a private apt configuration
# (own sources, lists and cache folders) derived at run time from this
# machine's apt sources: same URIs, suites and components, type deb-src.
# Nothing here names a package registry; the machine's configuration does.
# The orig tarball, the Debian tarball and the .dsc are checked against the
# sha256 sums pinned below. A second run with DEST already unpacked and
# verified does nothing.
set -euo pipefail

readonly PACKAGE=draco
readonly VERSION=1.5.5+dfsg-2
readonly -A PINNED_SHA256=(
  [draco_1.5.5+dfsg.orig.tar.xz]=0d4ff5b218a2f9d836c6f44202918402591407b5f59a5103ec288c5600ab087f
  [draco_1.5.5+dfsg-2.debian.tar.xz]=f1703de31f3574ff552f0d01123a9a7e94bd5e21f4fa6d78934dd12062d6612d
  [draco_1.5.5+dfsg-2.dsc]=169bca5d8f1e8886266ddad8c2415ab7a7ce10c8ed01607b64ced44a20610a87
)
readonly STAMP_NAME=.draco-uv-source-verified

die() { echo "fetch-draco-source: $*" >&2; exit 1; }

[[ $# -eq 1 ]] || die "usage: $0 DEST"
dest=$1
stamp_value="${PACKAGE} ${VERSION} ${PINNED_SHA256[draco_1.5.5+dfsg.orig.tar.xz]}"
if [[ -f "${dest}/${STAMP_NAME}" && "$(cat "${dest}/${STAMP_NAME}")" == "${stamp_value}" ]]; then
  exit 0
fi

for tool in apt-get dpkg-source sha256sum; do
  command -v "${tool}" >/dev/null || die "${tool} is missing (apt-get install dpkg-dev)"
done

work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
mkdir -p "${work}/sources.list.d" "${work}/lists/partial" \
  "${work}/cache/archives/partial" "${work}/download"

# One-line format (sources.list, *.list): every "deb" line becomes "deb-src".
derive_one_line_sources() {
  local file
  for file in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [[ -f "${file}" ]] || continue
    sed -n -E 's/^[[:space:]]*deb[[:space:]]+/deb-src /p' "${file}"
  done >"${work}/sources.list.d/derived.list"
}

# deb822 format (*.sources): stanzas of type deb get type deb-src.
derive_deb822_sources() {
  local file
  for file in /etc/apt/sources.list.d/*.sources; do
    [[ -f "${file}" ]] || continue
    sed -E 's/^Types:.*$/Types: deb-src/' "${file}" \
      >"${work}/sources.list.d/$(basename "${file}")"
  done
}

derive_one_line_sources
derive_deb822_sources
if ! grep -rqsE '^(deb-src|Types: deb-src)' "${work}/sources.list.d"; then
  die "no apt sources found in /etc/apt to derive deb-src entries from"
fi

apt_opts=(
  -o "Dir::Etc::SourceList=/dev/null"
  -o "Dir::Etc::SourceParts=${work}/sources.list.d"
  -o "Dir::State::Lists=${work}/lists"
  -o "Dir::Cache=${work}/cache"
  -o "APT::Sandbox::User=root"
)

# A source without deb-src indices (third-party repositories often have none)
# makes apt-get update complain; the package lookup below decides.
apt-get "${apt_opts[@]}" -q update >"${work}/update.log" 2>&1 || true
if ! (cd "${work}/download" &&
      apt-get "${apt_opts[@]}" -q source --download-only \
        "${PACKAGE}=${VERSION}" >"${work}/source.log" 2>&1); then
  cat "${work}/update.log" "${work}/source.log" >&2
  die "apt-get source ${PACKAGE}=${VERSION} failed"
fi

for file in "${!PINNED_SHA256[@]}"; do
  [[ -f "${work}/download/${file}" ]] || die "${file} was not downloaded"
  actual=$(sha256sum "${work}/download/${file}" | cut -d' ' -f1)
  [[ "${actual}" == "${PINNED_SHA256[${file}]}" ]] ||
    die "sha256 mismatch for ${file}: got ${actual}, pinned ${PINNED_SHA256[${file}]}"
done

dpkg-source --no-check -x "${work}/download/draco_${VERSION}.dsc" \
  "${work}/unpacked" >"${work}/unpack.log" 2>&1 ||
  { cat "${work}/unpack.log" >&2; die "dpkg-source -x failed"; }
echo "${stamp_value}" >"${work}/unpacked/${STAMP_NAME}"

rm -rf "${dest}"
mkdir -p "$(dirname "${dest}")"
mv "${work}/unpacked" "${dest}"
echo "fetch-draco-source: ${PACKAGE} ${VERSION} verified and unpacked in ${dest}"
