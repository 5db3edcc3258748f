#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start, command 2: installs what is missing, builds, and runs every test with ctest.
# Select by label with e.g. `scripts/run-tests.sh -L unit` (labels: unit, e2e, study, reference = runs the real lmp / YADE).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
cd "${BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "$(nproc)" "$@"
