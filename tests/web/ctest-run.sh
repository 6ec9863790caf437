#!/usr/bin/env bash
# How CTest runs the web tests (tests/web/CMakeLists.txt), skipping (exit 77
# with "SKIP: why") when a prerequisite is absent rather than failing:
#
#   ctest-run.sh install          web.install_packages, the fixture of the
#                                 web.<name> tests: tests/web/install-packages.sh
#                                 for $DRACO_UV_WEB_PACKAGE. Skips when there is
#                                 no package, or when the install fails and the
#                                 npm registry does not answer (npm ping).
#   ctest-run.sh test FILE        web.<name>: node tests/web/FILE; skips when
#                                 the package or tests/web/node_modules (as
#                                 install-packages.sh leaves it) is missing.
#   ctest-run.sh golden [--without-laplacian | --without-laplacian-part] MODULE
#                                 web.golden_*: tests/web/check_golden.js on
#                                 $DRACO_UV_WEB_PACKAGE/MODULE; skips when the
#                                 package is missing.
#
# The environment is the web test contract's (DRACO_UV_WEB_PACKAGE,
# DRACO_UV_BUILD_DIR, DRACO_UV_SOURCE_DIR, DRACO_TESTDATA, CHROMIUM), set by
# CTest.
set -euo pipefail
cd "$(dirname "$0")"

skip() { echo "SKIP: $*"; exit 77; }

[[ $# -ge 1 ]] || { echo "usage: $0 install | test FILE | golden MODULE" >&2; exit 2; }
readonly package=${DRACO_UV_WEB_PACKAGE:?DRACO_UV_WEB_PACKAGE is not set}
[[ -f "${package}/package.json" ]] ||
  skip "no web package in ${package} (./draco-uv.sh web or scripts/build-web.sh builds it)"

case "$1" in
  install)
    if ./install-packages.sh "${package}"; then
      exit 0
    fi
    if ! npm ping >/dev/null 2>&1; then
      skip "installing tests/web's npm packages failed and the npm registry does not answer"
    fi
    echo "ctest-run.sh: install-packages.sh failed with the npm registry reachable" >&2
    exit 1
    ;;
  test)
    [[ $# -eq 2 ]] || { echo "usage: $0 test FILE" >&2; exit 2; }
    # install-packages.sh marks a finished npm ci with a copy of the lock file.
    if ! cmp -s package-lock.json node_modules/.draco-uv-lock ||
       [[ ! -f node_modules/draco3d-uv/package.json ]]; then
      skip "tests/web/node_modules is not installed (web.install_packages: npm registry unreachable?)"
    fi
    exec node "$2"
    ;;
  golden)
    # golden [--without-laplacian | --without-laplacian-part] MODULE
    [[ $# -eq 2 || ( $# -eq 3 && $2 == --without-laplacian* ) ]] ||
      { echo "usage: $0 golden [--without-laplacian | --without-laplacian-part] MODULE" >&2; exit 2; }
    exec node check_golden.js "${@:2:$#-2}" "${package}/${!#}"
    ;;
  *) echo "ctest-run.sh: unknown command '$1'" >&2; exit 2 ;;
esac
