// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include <sched.h>

namespace bench {

/// The CPUs the calling thread may run on (its affinity mask), in increasing order.
[[nodiscard]] std::vector<int> allowed_cpus();

/// Pins the calling thread to one CPU for the object's lifetime and restores the mask it had
/// before when destroyed: `demwb bench --per-cpu` times the core on one thread on each CPU in
/// turn. Threads created while it lives inherit the pin (start OpenMP teams before, not during).
class PinnedToCpu {
 public:
  /// Throws std::invalid_argument for a CPU the thread may not run on, std::runtime_error when
  /// the system refuses the mask.
  explicit PinnedToCpu(int cpu);
  ~PinnedToCpu();
  PinnedToCpu(const PinnedToCpu&) = delete;
  PinnedToCpu& operator=(const PinnedToCpu&) = delete;

 private:
  cpu_set_t before_{};
};

}  // namespace bench
