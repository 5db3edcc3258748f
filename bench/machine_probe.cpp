// SPDX-License-Identifier: MIT
#include "bench/machine_probe.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/median.hpp"

namespace bench {
namespace {

/// Keeps the compiler from folding or dropping a value it could otherwise compute ahead.
inline void keep(double& v) noexcept {
#if defined(__GNUC__) && defined(__SSE2__)
  asm volatile("" : "+x"(v));  // the value stays in its vector register
#elif defined(__GNUC__) && defined(__aarch64__)
  asm volatile("" : "+w"(v));
#elif defined(__GNUC__)
  asm volatile("" : "+m"(v));  // elsewhere through memory: the kernel then also times a store and load
#else
  volatile double held = v;
  v = held;
#endif
}

/// Eight independent multiply–add chains: arithmetic throughput, no memory traffic. keep() makes
/// every step happen, so nothing needs to read the result.
void multiply_add_chains(std::size_t iterations) noexcept {
  std::array<double, 8> a{};
  for (std::size_t k = 0; k < a.size(); ++k) a[k] = 1.0 + 1e-3 * static_cast<double>(k);
  for (std::size_t i = 0; i < iterations; ++i) {
    for (double& v : a) {
      v = v * 0.999999999 + 1e-9;
      keep(v);
    }
  }
}

/// Passes of x ← x·m + c over a buffer (which outlives the call): streaming reads and writes.
void stream(std::vector<double>& x, int passes) noexcept {
  for (int p = 0; p < passes; ++p) {
    for (double& v : x) v = v * 0.999999999 + 1e-9;
    keep(x[static_cast<std::size_t>(p) % x.size()]);
  }
}

/// Runs kernel(thread) on `threads` threads from a common start; the threads the runtime gave go
/// to `team`.
template <class Kernel>
ProbeTiming timed(int threads, int& team, Kernel&& kernel) {
  std::vector<double> spent(static_cast<std::size_t>(threads), 0.0);
#pragma omp parallel num_threads(threads)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
#pragma omp single
    team = omp_get_num_threads();
    // The implicit barrier of `single` lines the threads up: all start together.
    const auto start = std::chrono::steady_clock::now();
    kernel(t);
    spent[t] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  for (double& s : spent) s = std::max(s, 1e-9);  // a clock that did not tick
  return probe_timing(spent.data(), static_cast<std::size_t>(team));
}

}  // namespace

ProbeTiming probe_timing(const double* seconds, std::size_t threads) {
  if (threads == 0) throw std::invalid_argument("probe_timing: no threads");
  ProbeTiming out;
  double slowest = seconds[0];
  double fastest = seconds[0];
  for (std::size_t t = 0; t < threads; ++t) {
    if (!(seconds[t] > 0.0)) throw std::invalid_argument("probe_timing: a thread's time is not positive");
    out.throughput += 1.0 / seconds[t];
    slowest = std::max(slowest, seconds[t]);
    fastest = std::min(fastest, seconds[t]);
  }
  out.unequal = slowest / fastest;
  return out;
}

MachineProbe probe_machine(int threads, const ProbeWork& work) {
  if (threads < 1) throw std::invalid_argument("probe_machine: the thread count must be at least 1, not " + std::to_string(threads));
  if (work.arithmetic_iterations == 0 || work.stream_bytes < sizeof(double) || work.stream_passes < 1) {
    throw std::invalid_argument("probe_machine: every kernel needs some work");
  }
  const auto count = static_cast<std::size_t>(threads);
  // One buffer per thread, first written by the thread that streams it.
  std::vector<std::vector<double>> buffers(count);
  const std::size_t length = work.stream_bytes / sizeof(double);
#pragma omp parallel num_threads(threads)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    buffers[t].assign(length, 1.0);
  }
  for (auto& b : buffers) {
    if (b.empty()) b.assign(length, 1.0);  // a thread the runtime did not give
  }
  const auto arithmetic = [&](std::size_t) { multiply_add_chains(work.arithmetic_iterations); };
  const auto streaming = [&](std::size_t t) { stream(buffers[t], work.stream_passes); };
  std::vector<double> arithmetic_ratio;
  std::vector<double> memory_ratio;
  std::vector<double> unequal;
  int team = 1;
  int one = 1;
  for (int k = 0; k < 3; ++k) {
    const ProbeTiming a1 = timed(1, one, arithmetic);
    const ProbeTiming an = timed(threads, team, arithmetic);
    arithmetic_ratio.push_back(an.throughput / a1.throughput);
    unequal.push_back(an.unequal);
    const ProbeTiming s1 = timed(1, one, streaming);
    const ProbeTiming sn = timed(threads, team, streaming);
    memory_ratio.push_back(sn.throughput / s1.throughput);
  }
  MachineProbe p;
  p.threads = team;
  p.arithmetic = median_of(arithmetic_ratio);
  p.memory = median_of(memory_ratio);
  p.unequal = median_of(unequal);
  return p;
}

}  // namespace bench
