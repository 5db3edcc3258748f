// SPDX-License-Identifier: MIT
#include "bench/cpu_ceiling.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace bench {

bool is_speed(double particle_steps_per_s) noexcept {
  return std::isfinite(particle_steps_per_s) && particle_steps_per_s > 0.0;
}

CpuCeiling cpu_ceiling(std::span<const CpuSpeed> cpus, int threads, double team) {
  if (cpus.empty()) throw std::invalid_argument("cpu_ceiling: no CPU was timed");
  if (threads < 1) throw std::invalid_argument("cpu_ceiling: fewer than one thread");
  if (!is_speed(team)) throw std::invalid_argument("cpu_ceiling: the team's speed is not positive and finite");
  std::vector<CpuSpeed> by_speed(cpus.begin(), cpus.end());
  for (const CpuSpeed& c : by_speed) {
    if (!is_speed(c.particle_steps_per_s)) {
      throw std::invalid_argument("cpu_ceiling: a CPU's speed is not positive and finite");
    }
  }
  // Fastest first; among equals the lower CPU number, so the result does not depend on the order given.
  std::stable_sort(by_speed.begin(), by_speed.end(), [](const CpuSpeed& a, const CpuSpeed& b) {
    return a.particle_steps_per_s > b.particle_steps_per_s ||
           (a.particle_steps_per_s == b.particle_steps_per_s && a.cpu < b.cpu);
  });
  CpuCeiling c;
  c.fastest_cpu = by_speed.front().cpu;
  c.fastest = by_speed.front().particle_steps_per_s;
  const std::size_t shared = std::min(by_speed.size(), static_cast<std::size_t>(threads));
  double sum = 0.0;
  for (std::size_t k = 0; k < shared; ++k) sum += by_speed[k].particle_steps_per_s;
  c.ceiling = sum / c.fastest;
  c.speedup = team / c.fastest;
  c.efficiency = team / sum;
  return c;
}

}  // namespace bench
