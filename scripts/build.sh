#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds dem-workbench in ${BUILD_DIR:-build}. Extra arguments are build targets.
# DEMWB_WERROR=ON turns warnings into errors (CI does); DEMWB_SANITIZE=ON builds with
# AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
# A fresh build tree uses Ninja when it is installed (scripts/setup.sh installs it): it starts a
# target's objects while the libraries it links are still being built, which Make does not, and
# keeps both cores busy (the sanitizer build in CI: 320 s instead of 430 s). An existing tree
# keeps the generator it was made with.
generator=()
if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja >/dev/null; then generator=(-G Ninja); fi
cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-RelWithDebInfo} \
      -DDEMWB_WERROR=${DEMWB_WERROR:-OFF} -DDEMWB_SANITIZE=${DEMWB_SANITIZE:-OFF} >/dev/null
cmake --build "$build" -j "$(nproc)" ${1:+--target "$@"}
