// SPDX-License-Identifier: MIT
#include "bench/core_run.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>

#include "support/sha256.hpp"

namespace bench {

double peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;
}

std::string state_sha256(const dem::Simulation& sim) {
  const auto& state = sim.state();
  const std::size_t n = sim.particles().size();
  std::string bytes;
  bytes.reserve(n * 9 * sizeof(double));
  for (std::uint32_t id = 0; id < n; ++id) {
    const auto i = static_cast<Eigen::Index>(sim.slot(id));
    for (const auto* field : {&state.position, &state.velocity, &state.angular_velocity}) {
      bytes.append(reinterpret_cast<const char*>(field->col(i).data()), 3 * sizeof(double));
    }
  }
  return support::sha256_hex(bytes);
}

CoreRun run_core(const dem::SimulationSetup& setup, std::uint64_t steps,
                 std::span<const std::uint64_t> energy_steps) {
  dem::Simulation sim(setup);
  CoreRun run;
  run.threads = setup.threads;
  run.particles = setup.particles.size();
  run.steps = steps;
  const auto sample = [&](std::uint64_t n) {
    if (std::find(energy_steps.begin(), energy_steps.end(), n) != energy_steps.end()) {
      run.energies.emplace_back(n, all_kinetic_energy(sim));
    }
  };
  const dem::LoopTiming before = sim.force_field().timing();
  const std::uint64_t builds = sim.force_field().list_builds();
  sample(0);
  const auto start = std::chrono::steady_clock::now();
  // Whole stretches between the samples, as a run between its outputs (Simulation::advance).
  std::uint64_t n = 0;
  while (n < steps) {
    std::uint64_t to = steps;
    for (const std::uint64_t s : energy_steps) {
      if (s > n && s < to) to = s;
    }
    sim.advance(to - n);
    n = to;
    sample(n);
  }
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.particle_steps_per_s = static_cast<double>(run.particles) * static_cast<double>(steps) / run.wall_s;
  run.bytes = sim.bytes();
  run.peak_rss_bytes = peak_rss_bytes();
  const dem::LoopTiming& after = sim.force_field().timing();
  run.timing = {after.neighbor_build - before.neighbor_build, after.pair_loop - before.pair_loop,
                after.sphere_loop - before.sphere_loop, after.other - before.other};
  run.list_builds = sim.force_field().list_builds() - builds;
  run.list_entries = sim.force_field().neighbors().size();
  run.interacting_pairs = sim.force_field().interacting_pairs();
  run.reorders = sim.reorders();
  run.state_sha256 = state_sha256(sim);
  return run;
}

}  // namespace bench
