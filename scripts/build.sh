#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds dem-workbench in ${BUILD_DIR:-build}. Extra arguments are make targets.
# DEMWB_WERROR=ON turns warnings into errors (CI does); DEMWB_SANITIZE=ON builds with
# AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-RelWithDebInfo} \
      -DDEMWB_WERROR=${DEMWB_WERROR:-OFF} -DDEMWB_SANITIZE=${DEMWB_SANITIZE:-OFF} >/dev/null
cmake --build "$build" -j "$(nproc)" ${1:+--target "$@"}
