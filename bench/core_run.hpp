// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "bench/chute_scene.hpp"
#include "dem/forces/loop_timing.hpp"
#include "dem/simulation/simulation.hpp"

namespace bench {

/// What timing the core on one scene measured.
struct CoreRun {
  int threads = 1;
  std::size_t particles = 0;
  std::uint64_t steps = 0;
  double wall_s = 0.0;                 ///< the step loop alone (set-up excluded, as LAMMPS's loop time)
  double particle_steps_per_s = 0.0;
  std::size_t bytes = 0;               ///< the run's arrays, lists and history (capacities)
  double peak_rss_bytes = 0.0;         ///< the process's peak resident set, for reference
  dem::LoopTiming timing;              ///< where the force field spent its time
  std::uint64_t list_builds = 0;
  std::size_t list_entries = 0;        ///< pairs in the neighbour list at the end
  std::size_t interacting_pairs = 0;   ///< of those, interacting at the last commit
  std::uint64_t reorders = 0;
  std::vector<std::pair<std::uint64_t, AllKinetic>> energies;  ///< kinetic energies at chosen steps
  /// SHA-256 of every sphere's position, velocity and spin at the end, in setup order: two runs
  /// of one scene ended in the same state, to the last bit, when these are equal.
  std::string state_sha256;
};

/// Builds the simulation of `setup`, runs `steps` steps timing the loop, and records the kinetic
/// energies (all spheres, LAMMPS's way) at `energy_steps`.
CoreRun run_core(const dem::SimulationSetup& setup, std::uint64_t steps,
                 std::span<const std::uint64_t> energy_steps);

/// SHA-256 of the bytes of every sphere's position, velocity and angular velocity, in setup order.
std::string state_sha256(const dem::Simulation& sim);

/// Peak resident set size of this process [bytes] (getrusage).
double peak_rss_bytes();

}  // namespace bench
