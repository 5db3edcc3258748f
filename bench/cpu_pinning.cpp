// SPDX-License-Identifier: MIT
#include "bench/cpu_pinning.hpp"

#include <pthread.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace bench {
namespace {

/// The calling thread's affinity mask.
cpu_set_t current_mask() {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (const int err = pthread_getaffinity_np(pthread_self(), sizeof mask, &mask); err != 0) {
    throw std::runtime_error(fmt::format("cannot read this thread's CPU affinity: {}", std::strerror(err)));
  }
  return mask;
}

}  // namespace

std::vector<int> allowed_cpus() {
  const cpu_set_t mask = current_mask();
  std::vector<int> cpus;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
    if (CPU_ISSET(cpu, &mask)) cpus.push_back(cpu);
  }
  return cpus;
}

PinnedToCpu::PinnedToCpu(int cpu) : before_(current_mask()) {
  if (cpu < 0 || cpu >= CPU_SETSIZE || !CPU_ISSET(cpu, &before_)) {
    throw std::invalid_argument(fmt::format("CPU {} is not one this thread may run on", cpu));
  }
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(cpu, &one);
  if (const int err = pthread_setaffinity_np(pthread_self(), sizeof one, &one); err != 0) {
    throw std::runtime_error(fmt::format("cannot pin this thread to CPU {}: {}", cpu, std::strerror(err)));
  }
}

PinnedToCpu::~PinnedToCpu() {
  // Restoring a mask the thread had a moment ago does not fail short of the CPUs going offline;
  // a destructor cannot report it anyway.
  (void)pthread_setaffinity_np(pthread_self(), sizeof before_, &before_);
}

}  // namespace bench
