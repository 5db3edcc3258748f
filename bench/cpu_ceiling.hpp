// SPDX-License-Identifier: MIT
#pragma once

#include <span>

namespace bench {

/// One CPU's speed on the core's work: one thread pinned to it.
struct CpuSpeed {
  int cpu = 0;
  double particle_steps_per_s = 0.0;
};

/// What one thread pinned to each CPU says about a run on several threads made in the same
/// minutes. On a virtual machine the CPUs need not run at one speed: a team of N threads can at
/// best add up the N fastest CPUs' one-thread speeds, so the speed-up over one thread on the
/// fastest CPU is capped at `ceiling` (N only when they are equal), and `efficiency` is how much
/// of that sum the team reached — the code's share of a shortfall, the machine's removed.
struct CpuCeiling {
  int fastest_cpu = 0;
  double fastest = 0.0;     ///< particle-steps/s of one thread on the fastest CPU
  double ceiling = 0.0;     ///< Σ over the N fastest CPUs of speed / fastest (≤ N)
  double speedup = 0.0;     ///< the team's particle-steps/s over `fastest`
  double efficiency = 0.0;  ///< speedup / ceiling: the team over the N fastest CPUs' summed speed
};

/// True for a speed a timing can give: positive and finite (a run too short for the clock gives
/// infinity, a failed one zero).
[[nodiscard]] bool is_speed(double particle_steps_per_s) noexcept;

/// CpuCeiling of a team of `threads` threads that ran at `team` particle-steps/s, from one run
/// on each CPU; with fewer CPUs than threads, the team shares all of them. Throws
/// std::invalid_argument for no CPUs, fewer than one thread, or a speed that is not positive
/// and finite.
[[nodiscard]] CpuCeiling cpu_ceiling(std::span<const CpuSpeed> cpus, int threads, double team);

}  // namespace bench
