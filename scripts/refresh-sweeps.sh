#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs every committed sweep (cases/sweeps/*.toml, or the ones named) outside CI with
# `demwb refresh --sweep`, which stores what each produced under cases/baselines/sweeps/<name>/:
# sweep.csv, sweep.json (the fingerprint: the SHA-256 of the sweep, its case and sweep.csv, the
# core revision, engine versions), report.md and its figures. The gate fails while a stored sweep
# no longer fits its sweep or case file. Needs a build (scripts/build.sh); takes minutes per sweep.
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
  echo "== $(basename "$sweep" .toml)"
  "$demwb" refresh --sweep "$sweep" -j "$jobs" -o out/sweeps
done
