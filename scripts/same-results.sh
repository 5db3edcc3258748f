#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# scripts/same-results.sh A B: compares two `demwb suite --reproducible` output directories,
# results.json by results.json, ignoring only the in-house engine's version stamp (it names the
# build's commit). Prints each file as `same` or `DIFF` with the differing lines; exits 1 when any
# file differs or is missing on one side. Used to show that a refactoring left results unchanged
# (docs/architecture.md, "Layers").
set -euo pipefail
if [[ $# -ne 2 || ! -d "$1" || ! -d "$2" ]]; then
  echo "usage: $0 BEFORE_DIR AFTER_DIR (two demwb suite --reproducible -o directories)" >&2
  exit 2
fi
normalise() { sed -E 's/dem-workbench [0-9][0-9.]* \([0-9a-f]+(-dirty)?\)/dem-workbench VERSION/' "$1"; }
status=0
scratch=$(mktemp)
trap 'rm -f "$scratch"' EXIT
files=$( (cd "$1" && find . -name results.json -not -path '*/work/*'; cd "$2" && find . -name results.json -not -path '*/work/*') | sort -u)
for f in $files; do
  if [[ ! -f "$1/$f" || ! -f "$2/$f" ]]; then
    echo "MISSING $f (only in $([[ -f "$1/$f" ]] && echo "$1" || echo "$2"))"
    status=1
  elif diff <(normalise "$1/$f") <(normalise "$2/$f") >"$scratch" 2>&1; then
    echo "same $f"
  else
    echo "DIFF $f"
    head -20 "$scratch"
    status=1
  fi
done
exit $status
