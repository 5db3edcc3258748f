#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian packages dem-workbench needs, when run as root; otherwise says exactly
# which are missing and how to install them. The reference codes (LAMMPS, YADE) are included:
# the comparisons and the tests labelled `reference` run the real binaries.
# Usage: scripts/setup.sh [--check] [--core-only]
set -euo pipefail

packages=(
  g++ cmake make ninja-build       # toolchain (C++20, g++ 12); Ninja builds faster than Make
  libeigen3-dev                    # Eigen 3.4: vectors and quaternions
  libboost-dev                     # Boost 1.74 headers: Math root finding, Odeint
  libboost-program-options-dev     # Boost.Program_options: the demwb command line
  libtomlplusplus-dev              # toml++: case files
  nlohmann-json3-dev               # results.json
  zlib1g-dev                       # zlib: packed traces in the result cache and baselines
  libfmt-dev                       # formatting
  libgtest-dev                     # GoogleTest
  libbenchmark-dev                 # Google Benchmark: the micro-benchmarks (build/bench/demwb_microbench)
  gnuplot-nox                      # report plots
  pandoc                           # checks that report.md renders
  libopenmpi-dev openmpi-bin       # MPI: `mpirun -np N demwb sweep` shares a sweep between ranks;
                                   # `demwb bench --ranks N` runs LAMMPS on N ranks
)
references=(
  lammps                           # LAMMPS (GRANULAR), Debian 20220106
  yade                             # YADE 2023.02a (driven as a Python module, no servers)
  liggghts                         # LIGGGHTS-PUBLIC 3.8.0 (a granular fork of LAMMPS)
)
check_only=false
for arg in "$@"; do
  case "$arg" in
    --check) check_only=true ;;
    --core-only) references=() ;;
    *) echo "setup: unknown option $arg" >&2; exit 2 ;;
  esac
done
packages+=("${references[@]}")

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
if $check_only; then
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
apt-get install -y -qq "${missing[@]}" >/dev/null
echo "setup: done"
