#!/usr/bin/env bash
# Shows that patches/*.patch apply cleanly to upstream Draco revisions.
#
#   scripts/check-patches.sh GIT_DIR [REV ...]     (default REVs: 1.5.7 HEAD)
#
# GIT_DIR is a clone of github.com/google/draco (or its .git folder). Each
# revision's CMakeLists.txt, cmake/ and src/ are exported to a scratch folder
# and every patch is applied in order with `git apply`. Exits non-zero if any
# patch fails on any revision.
set -euo pipefail

[[ $# -ge 1 ]] || { echo "usage: $0 GIT_DIR [REV ...]" >&2; exit 2; }
git_dir=$1
shift
revisions=("$@")
[[ ${#revisions[@]} -gt 0 ]] || revisions=(1.5.7 HEAD)
patches_dir="$(cd "$(dirname "$0")/../patches" && pwd)"
work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT

status=0
for rev in "${revisions[@]}"; do
  tree="${work}/${rev//\//_}"
  mkdir -p "${tree}"
  # A partial mirror may lack unrelated blobs; git archive warns about them.
  git --git-dir="${git_dir}" archive "${rev}" CMakeLists.txt cmake src \
    2>"${work}/archive.log" | tar -x -C "${tree}"
  git -C "${tree}" init -q
  described=$(git --git-dir="${git_dir}" describe --tags "${rev}" 2>/dev/null || echo "${rev}")
  for patch in "${patches_dir}"/*.patch; do
    if git -C "${tree}" apply "${patch}" 2>"${work}/error"; then
      echo "ok    ${described}  $(basename "${patch}")"
    else
      echo "FAIL  ${described}  $(basename "${patch}")"
      cat "${work}/error"
      status=1
    fi
  done
done
exit "${status}"
