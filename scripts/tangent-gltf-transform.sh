#!/usr/bin/env bash
# glTF-Transform's `draco` (the CLI's defaults: quantizePosition 14,
# quantizeNormal 10, quantizeTexcoord 12, quantizeGeneric 12, which is what
# TANGENT gets) through the package's CLI config, per asset of a
# scripts/make-tangent-assets.mjs folder: the GLB's bytes with stock coding
# (DRACO_UV_PRED=draco DRACO_UV_SEAMS=draco DRACO_TANGENT_PRED=draco), with
# the config's UV defaults only (DRACO_TANGENT_PRED=draco) and with its
# defaults (UV and tangent prediction auto). Prints a Markdown table and the
# medians.
#
#   scripts/tangent-gltf-transform.sh [ASSET_DIR]
#
# ASSET_DIR defaults to build/tangent-assets. Needs tests/web's npm packages
# with the web package installed (CTest's web.install_packages does it).
set -euo pipefail
cd "$(dirname "$0")/.."

assets=${1:-build/tangent-assets}
cli=tests/web/node_modules/.bin/gltf-transform
config=tests/web/node_modules/draco3d-uv/gltf-transform.config.mjs
[[ -x ${cli} && -f ${config} ]] ||
  { echo "Error: no ${cli} or ${config} (ctest -R web.install_packages)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT

bytes() {  # bytes OUT [VAR=VALUE...]: transcodes $glb, prints the size
  local out=${work}/$1; shift
  env "$@" "${cli}" draco "${glb}" "${out}" --config "${config}" >/dev/null
  stat -c %s "${out}"
}

echo "| asset | stock | UV auto | UV and tangents auto | UV / stock | UV and tangents / stock |"
echo "| --- | ---: | ---: | ---: | ---: | ---: |"
for glb in "${assets}"/*.glb; do
  s=$(bytes s.glb DRACO_UV_PRED=draco DRACO_UV_SEAMS=draco DRACO_TANGENT_PRED=draco)
  u=$(bytes u.glb DRACO_TANGENT_PRED=draco)
  t=$(bytes t.glb)
  awk -v n="$(basename "${glb}" .glb)" -v s="${s}" -v u="${u}" -v t="${t}" \
    'BEGIN { printf "| %s | %d | %d | %d | %.3f | %.3f |\n", n, s, u, t, u / s, t / s }'
done | tee "${work}/table.md"
awk -F'|' '
  function median(a, n,   i, j, x) {
    for (i = 1; i <= n; ++i) for (j = i + 1; j <= n; ++j)
      if (a[j] < a[i]) { x = a[i]; a[i] = a[j]; a[j] = x }
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
  }
  { ++n; u[n] = $6 + 0; t[n] = $7 + 0 }
  END { printf "\nmedians: UV %.3f, UV and tangents %.3f of stock bytes\n", median(u, n), median(t, n) }
' "${work}/table.md"
