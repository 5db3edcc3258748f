// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

namespace bench {

/// What the machine itself gave several threads against one, in the same minutes as a bench run:
/// two fixed kernels that share nothing with the core, so that a thread speed-up can be read
/// against what the processors delivered. On a virtual machine two "CPUs" may be one core's two
/// hardware threads or be time-shared with other guests, and that changes from minute to minute.
struct MachineProbe {
  int threads = 1;          ///< the thread count probed (against one)
  double arithmetic = 0.0;  ///< multiply–add throughput on `threads` threads over one thread (ideal: threads)
  double memory = 0.0;      ///< streaming read–modify–write throughput, the same ratio (ideal: threads)
  /// The slowest thread's time over the fastest's in the multiply–add run on `threads` threads:
  /// 1 when the CPUs ran at one speed. Throughput counts each thread at its own speed, so unequal
  /// CPUs can give more than `threads` when the one-thread run landed on the slower one.
  double unequal = 1.0;
};

/// Throughput and spread of one kernel run on several threads at once, from each thread's own time.
struct ProbeTiming {
  double throughput = 0.0;  ///< Σ 1 / (each thread's seconds): kernels per second
  double unequal = 1.0;     ///< the slowest thread's seconds over the fastest's
};

/// ProbeTiming of threads that took `seconds` each (every value > 0; at least one).
[[nodiscard]] ProbeTiming probe_timing(const double* seconds, std::size_t threads);

/// The sizes of the probe's kernels: the arithmetic kernel's iterations per thread, and the
/// stream's buffer per thread (bytes, larger than a core's private caches) and passes over it.
struct ProbeWork {
  std::size_t arithmetic_iterations = 6'000'000;  ///< of eight independent multiply–add chains (tens of ms)
  std::size_t stream_bytes = 16U << 20U;          ///< per thread
  int stream_passes = 6;
};

/// Runs each kernel on one thread, then on `threads` threads at once (every thread the same
/// work), three times over, and returns the median of each ratio: the sum over the threads of
/// work / the thread's own time, over the one thread's work / time. Throws std::invalid_argument
/// for fewer than one thread.
[[nodiscard]] MachineProbe probe_machine(int threads, const ProbeWork& work = {});

}  // namespace bench
