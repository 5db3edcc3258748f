// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>

#include <omp.h>

#include "dem/core/parallel_for.hpp"

namespace dem {

/// The chunks of one thread's share of a balanced loop still to run, [front, back), in one word:
/// the owner claims from the front and a thread that has finished its own share from the back,
/// each with one compare-and-swap, so that no chunk runs twice and none is left.
struct alignas(64) ShareCursor {
  std::atomic<std::uint64_t> range{0};

  /// Sets the share to the chunks [front, back).
  void reset(std::uint32_t front, std::uint32_t back) noexcept {
    range.store((static_cast<std::uint64_t>(back) << 32) | front, std::memory_order_relaxed);
  }
  /// Claims the next chunk from the front (the owner); false when none is left.
  bool claim_front(std::uint32_t& chunk) noexcept { return claim(false, 0, chunk); }
  /// Claims the last chunk (a thief) while more than `leave` remain; false otherwise.
  bool claim_back(std::uint32_t leave, std::uint32_t& chunk) noexcept { return claim(true, leave, chunk); }

 private:
  bool claim(bool from_back, std::uint32_t leave, std::uint32_t& chunk) noexcept {
    std::uint64_t r = range.load(std::memory_order_relaxed);
    for (;;) {
      const auto front = static_cast<std::uint32_t>(r);
      const auto back = static_cast<std::uint32_t>(r >> 32);
      if (front >= back || back - front <= leave) return false;
      const std::uint64_t next = from_back ? (static_cast<std::uint64_t>(back - 1) << 32) | front
                                           : (static_cast<std::uint64_t>(back) << 32) | (front + 1);
      if (range.compare_exchange_weak(r, next, std::memory_order_relaxed)) {
        chunk = from_back ? back - 1 : front;
        return true;
      }
    }
  }
};

/// Most threads a balanced loop shares its work between; a larger team runs parallel_for's
/// static split instead.
inline constexpr int kMaxBalancedThreads = 64;

/// The number of chunks of `chunk` (≥ 1) indices that cover [0, n), or 0 when it does not fit the
/// cursors' 32 bits (the caller then runs a static split).
template <typename Index>
[[nodiscard]] inline std::uint32_t chunk_count(Index n, Index chunk) noexcept {
  const auto count = static_cast<std::uint64_t>(n / chunk) + (n % chunk != 0 ? 1U : 0U);
  return count > 0xFFFFFFFFULL ? 0U : static_cast<std::uint32_t>(count);
}

/// Runs run(thread, c) for every chunk c in [0, chunks) on `threads` OpenMP threads (2 ≤ threads ≤
/// kMaxBalancedThreads). Thread t starts on its own share, chunks [chunks·t/T, chunks·(t+1)/T) from
/// the front, then takes chunks from the back of the other shares, nearest first, leaving every
/// owner in the team one unclaimed chunk of its own: on cores of equal speed, where the threads
/// finish nearly together, a chunk's data then stays in the cache of the thread the next pass
/// gives it to (the price: a slow owner runs one more chunk after the one it is on). A share no
/// thread owns (a team smaller than asked for) is taken whole by the others.
template <typename Run>
inline void balanced_chunks(int threads, std::uint32_t chunks, Run&& run) {
  std::array<ShareCursor, kMaxBalancedThreads> shares;
  const auto parts = static_cast<std::uint32_t>(threads);
  const auto first_of = [&](std::uint32_t t) {
    return static_cast<std::uint32_t>(static_cast<std::uint64_t>(chunks) * t / parts);
  };
  for (std::uint32_t t = 0; t < parts; ++t) shares[t].reset(first_of(t), first_of(t + 1));
#pragma omp parallel num_threads(threads)
  {
    const auto me = static_cast<std::uint32_t>(omp_get_thread_num());
    const auto team = static_cast<std::uint32_t>(omp_get_num_threads());
    std::uint32_t c = 0;
    while (shares[me].claim_front(c)) run(me, c);
    for (std::uint32_t k = 1; k < parts; ++k) {
      const std::uint32_t other = (me + k) % parts;
      const std::uint32_t leave = other < team ? 1 : 0;  // an owner in the team keeps one chunk
      while (shares[other].claim_back(leave, c)) run(me, c);
    }
  }
}

/// Runs each(thread, local, from, to) for every chunk [from, to) of `chunk` indices of [0, n), as
/// balanced_chunks shares them out; `local` is a copy of `body` in the chunk's frame, so that the
/// body's stores through its captured pointers cannot alias it and its captures stay in registers
/// (through a reference to the caller's closure every such store made them be loaded again).
/// Flattened: `each` and the body are inlined into the chunk's loop as a static split's loop
/// inlines them. False, running nothing, when the chunks do not fit the cursors' 32 bits.
template <typename Index, typename Body, typename Each>
inline bool for_each_chunk(int threads, Index n, Index chunk, const Body& body, Each&& each) {
  const std::uint32_t chunks = chunk_count(n, chunk);
  if (chunks == 0) return false;
  balanced_chunks(threads, chunks, [&](std::uint32_t thread, std::uint32_t c) __attribute__((flatten)) {
    const Body local = body;
    const Index from = static_cast<Index>(c) * chunk;
    each(thread, local, from, std::min<Index>(n, from + chunk));
  });
  return true;
}

/// parallel_for's static split with the body told its OpenMP thread: body(thread, i), for loops
/// beyond the balanced loops' cursors.
template <typename Index, typename Body>
inline void parallel_for_threads(int threads, Index n, const Body& body) {
  parallel_for(threads, n, [&body](Index i) { body(static_cast<std::uint32_t>(omp_get_thread_num()), i); });
}

/// balanced_for_threads' loop on 2 ≤ threads ≤ kMaxBalancedThreads. Kept out of line: inlined
/// beside the caller's one-thread loop, its arrays of cursors aligned to cache lines cost that
/// loop 8–20 % (the chute's opening pass on one thread, docs/performance.md).
template <typename Index, typename Body>
[[gnu::noinline]] void balanced_for_chunks(int threads, Index n, Index chunk, const Body& body) {
  const auto each = [](std::uint32_t thread, const Body& b, Index from, Index to) {
    for (Index i = from; i < to; ++i) b(thread, i);
  };
  if (!for_each_chunk(threads, n, chunk, body, each)) parallel_for_threads(threads, n, body);
}

/// balanced_max's loop on 2 ≤ threads ≤ kMaxBalancedThreads (out of line, as balanced_for_chunks).
template <typename Index, typename Body>
[[gnu::noinline]] double balanced_max_chunks(int threads, Index n, Index chunk, double start, const Body& body) {
  struct alignas(64) Largest {
    double value;
  };
  std::array<Largest, kMaxBalancedThreads> worst;
  worst.fill({start});
  const auto each = [&worst](std::uint32_t thread, const Body& b, Index from, Index to) {
    double largest = worst[thread].value;
    for (Index i = from; i < to; ++i) largest = std::max(largest, b(i));
    worst[thread].value = largest;
  };
  if (!for_each_chunk(threads, n, chunk, body, each)) return parallel_max(threads, n, start, body);
  double largest = start;
  for (const Largest& w : worst) largest = std::max(largest, w.value);
  return largest;
}

/// As balanced_for, with the body told which thread runs it: body(thread, i), thread in
/// [0, threads) — 0 when the loop runs in place, whatever OpenMP region the caller is in — for a
/// body that uses scratch of its own per thread.
template <typename Index, typename Body>
inline void balanced_for_threads(int threads, Index n, Index chunk, const Body& body) {
  chunk = std::max<Index>(chunk, 1);
  if (threads <= 1 || n <= chunk) {
    for (Index i = 0; i < n; ++i) body(std::uint32_t{0}, i);
  } else if (threads > kMaxBalancedThreads) {
    parallel_for_threads(threads, n, body);
  } else {
    balanced_for_chunks(threads, n, chunk, body);
  }
}

/// Runs body(i) for every i in [0, n) on `threads` OpenMP threads, in chunks of `chunk`
/// consecutive indices. Each thread starts on its own contiguous share, the share a static split
/// would give it (so a thread meets the same data pass after pass), and then takes chunks from
/// the far end of the shares still unfinished. On a machine whose cores run at unequal speed (a
/// virtual machine whose host loads one of them) the faster core does more, where a static split
/// would leave it waiting at the barrier. Within a chunk the indices run in increasing order;
/// which thread runs a chunk varies, so body(i) must not depend on it: the loop gives the same
/// results as parallel_for whenever the bodies are independent of one another. One thread (or a
/// loop of one chunk) runs the plain loop in place. A chunk below 1 counts as 1.
template <typename Index, typename Body>
inline void balanced_for(int threads, Index n, Index chunk, Body&& body) {
  chunk = std::max<Index>(chunk, 1);
  if (threads > kMaxBalancedThreads) {
    parallel_for(threads, n, body);
  } else if (threads <= 1 || n <= chunk) {
    for (Index i = 0; i < n; ++i) body(i);
  } else {
    // By value, so that the chunks' copies hold the captures themselves.
    balanced_for_chunks(threads, n, chunk, [body](std::uint32_t, Index i) { body(i); });
  }
}

/// The largest of body(i) over [0, n) (and `start`), computed as balanced_for runs its loop (the
/// largest of a set does not depend on the order it is taken in).
template <typename Index, typename Body>
inline double balanced_max(int threads, Index n, Index chunk, double start, Body&& body) {
  chunk = std::max<Index>(chunk, 1);
  if (threads > kMaxBalancedThreads) return parallel_max(threads, n, start, body);
  if (threads > 1 && n > chunk) return balanced_max_chunks(threads, n, chunk, start, body);
  double worst = start;
  for (Index i = 0; i < n; ++i) worst = std::max(worst, body(i));
  return worst;
}

}  // namespace dem
