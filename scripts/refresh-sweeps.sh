#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs every committed sweep (cases/sweeps/*.toml, or the ones named) outside CI and stores what
# it produced under cases/baselines/sweeps/<name>/: sweep.csv, sweep.json (the fingerprint: the
# SHA-256 of the sweep, its case and sweep.csv, the core revision, engine versions), report.md and
# its figures. tests/sweeps/committed_sweeps_test.cpp fails when a sweep or its case changed
# since its results were stored. Needs a build (scripts/build.sh); takes minutes per sweep.
# Usage: scripts/refresh-sweeps.sh [-j N] [SWEEP.toml ...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=2
if [ "${1:-}" = "-j" ]; then jobs=$2; shift 2; fi
sweeps=("$@")
[ ${#sweeps[@]} -eq 0 ] && sweeps=(cases/sweeps/*.toml)
demwb=${DEMWB:-build/app/demwb}
for sweep in "${sweeps[@]}"; do
  name=$(basename "$sweep" .toml)
  out=out/sweeps/$name
  echo "== $name"
  rm -rf "$out"
  "$demwb" sweep "$sweep" -j "$jobs" -o "$out"
  dest=cases/baselines/sweeps/$name
  rm -rf "$dest"
  mkdir -p "$dest"
  cp "$out/sweep.csv" "$out/sweep.json" "$out/report.md" "$dest/"
  cp -r "$out/plots" "$dest/"
done
