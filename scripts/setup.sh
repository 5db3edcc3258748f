#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian packages dem-workbench needs, when run as root; otherwise says exactly
# which are missing and how to install them. Usage: scripts/setup.sh [--check]
set -euo pipefail

packages=(
  g++ cmake make                   # toolchain (C++20, g++ 12)
  libeigen3-dev                    # Eigen 3.4: vectors and quaternions
  libboost-dev                     # Boost 1.74 headers: Math root finding, Odeint
  libboost-program-options-dev     # Boost.Program_options: the demwb command line
  libtomlplusplus-dev              # toml++: case files
  nlohmann-json3-dev               # results.json
  libfmt-dev                       # formatting
  libgtest-dev                     # GoogleTest
  gnuplot-nox                      # report plots
)

missing=()
for p in "${packages[@]}"; do
  if [ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" != "install ok installed" ]; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi
if [ "${1:-}" = "--check" ]; then
  echo "setup: missing packages: ${missing[*]}"
  exit 1
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "setup: missing packages: ${missing[*]}" >&2
  echo "setup: run as root, or: sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
