// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>

namespace dem {

/// Runs body(i) for every i in [0, n): split statically over `threads` OpenMP threads, or as a
/// plain loop when threads ≤ 1. Entering an OpenMP region costs libgomp a team barrier and a
/// futex wake-up even when an `if` clause switches it to one thread; at a handful of regions per
/// step that was 13 % of a 125-sphere agglomerate impact (docs/performance.md), so one thread
/// never enters one. The order of the work within a thread is the same either way.
template <typename Index, typename Body>
inline void parallel_for(int threads, Index n, Body&& body) {
  if (threads > 1) {
#pragma omp parallel for schedule(static) num_threads(threads)
    for (Index i = 0; i < n; ++i) body(i);
  } else {
    for (Index i = 0; i < n; ++i) body(i);
  }
}

/// The largest of body(i) over [0, n) (and `start`), computed as parallel_for runs its loop.
template <typename Index, typename Body>
inline double parallel_max(int threads, Index n, double start, Body&& body) {
  double worst = start;
  if (threads > 1) {
#pragma omp parallel for schedule(static) reduction(max : worst) num_threads(threads)
    for (Index i = 0; i < n; ++i) worst = std::max(worst, body(i));
  } else {
    for (Index i = 0; i < n; ++i) worst = std::max(worst, body(i));
  }
  return worst;
}

}  // namespace dem
