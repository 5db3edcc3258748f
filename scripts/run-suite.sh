#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Quick start, command 1: installs what is missing, builds demwb, runs the canonical suite on
# every engine its cases name, and writes the report to ${1:-out/canonical}/report.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/canonical}
"$root/scripts/setup.sh"
"$root/scripts/build.sh" demwb
"${BUILD_DIR:-$root/build}/app/demwb" suite canonical -o "$out"
