// SPDX-License-Identifier: MIT
// The balanced loop (dem/core/balanced_for.hpp): every index runs exactly once, whatever the
// thread count, chunk size, speed of the threads or size of the team OpenMP grants, and the
// largest value is the serial loop's.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <random>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <omp.h>

#include "dem/core/balanced_for.hpp"

namespace balanced_for_test {

/// How often each index of [0, n) ran.
std::vector<int> runs_of(int threads, std::int64_t n, std::int64_t chunk) {
  std::vector<std::atomic<int>> count(static_cast<std::size_t>(n));
  dem::balanced_for(threads, n, chunk, [&](std::int64_t i) { count[static_cast<std::size_t>(i)].fetch_add(1); });
  std::vector<int> out;
  for (const auto& c : count) out.push_back(c.load());
  return out;
}

TEST(BalancedFor, RunsEveryIndexOnceForAnyThreadsAndChunks) {
  std::mt19937 rng(5);
  for (int k = 0; k < 60; ++k) {
    const int threads = 1 + static_cast<int>(rng() % 5);
    const auto n = static_cast<std::int64_t>(rng() % 3000);
    const auto chunk = static_cast<std::int64_t>(1 + rng() % 300);
    const std::vector<int> runs = runs_of(threads, n, chunk);
    for (std::int64_t i = 0; i < n; ++i) {
      ASSERT_EQ(runs[static_cast<std::size_t>(i)], 1) << "index " << i << " of " << n << ", " << threads
                                                      << " threads, chunks of " << chunk;
    }
  }
  // More threads than chunks, and more threads than it balances (a static split runs them).
  for (const int threads : {8, dem::kMaxBalancedThreads + 1}) {
    for (const int r : runs_of(threads, 5, 1)) EXPECT_EQ(r, 1) << threads;
  }
}

TEST(BalancedFor, AFastThreadTakesOverTheSlowOnesShare) {
  // Thread 0 stalls in chunk 0 (the front of its share) until thread 1 has run 40 chunks: 8 more
  // than its own share of 32, which it can only have taken from the back of thread 0's. Without
  // the taking thread 0 would wait out the 10 s limit and the counts below would fail.
  constexpr std::int64_t n = 64;
  std::vector<int> ran_by(n, -1);
  std::vector<std::atomic<int>> count(n);
  std::atomic<int> by_one{0};
  std::atomic<int> team{1};
  dem::balanced_for(2, n, std::int64_t{1}, [&](std::int64_t i) {
    const int me = omp_get_thread_num();
    team = omp_get_num_threads();
    if (me == 0 && i == 0 && team == 2) {
      const auto limit = std::chrono::steady_clock::now() + std::chrono::seconds(10);
      while (by_one.load() < 40 && std::chrono::steady_clock::now() < limit) {
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      }
    }
    if (me == 1) by_one.fetch_add(1);
    ran_by[static_cast<std::size_t>(i)] = me;
    count[static_cast<std::size_t>(i)].fetch_add(1);
  });
  int by_one_in_share_of_zero = 0;
  for (std::int64_t i = 0; i < n; ++i) {
    EXPECT_EQ(count[static_cast<std::size_t>(i)].load(), 1) << i;
    if (i < n / 2 && ran_by[static_cast<std::size_t>(i)] == 1) ++by_one_in_share_of_zero;
  }
  if (team == 2) {
    EXPECT_GE(by_one.load(), 40);
    EXPECT_GE(by_one_in_share_of_zero, 8);
  }
}

TEST(BalancedFor, ASmallerTeamThanAskedForStillRunsEveryShare) {
  // Inside a parallel region with nesting off OpenMP grants a team of one: the shares of the
  // threads that never start are taken from the back by the one that does.
  const int levels = omp_get_max_active_levels();
  omp_set_max_active_levels(1);
  std::vector<int> runs;
  int inner_team = 0;
  int outer_team = 0;
#pragma omp parallel num_threads(2)
  {
#pragma omp single
    {
      outer_team = omp_get_num_threads();
      runs = runs_of(4, 1000, 7);
      dem::balanced_for(4, 100, 7, [&](int) { inner_team = omp_get_num_threads(); });
    }
  }
  omp_set_max_active_levels(levels);
  ASSERT_EQ(runs.size(), 1000U);
  for (const int r : runs) EXPECT_EQ(r, 1);
  if (outer_team == 2) {
    EXPECT_EQ(inner_team, 1);  // the case this test is for
  }
}

TEST(BalancedFor, CountsChunksWithoutOverflow) {
  EXPECT_EQ(dem::chunk_count<std::int64_t>(0, 512), 0U);
  EXPECT_EQ(dem::chunk_count<std::int64_t>(1, 512), 1U);
  EXPECT_EQ(dem::chunk_count<std::int64_t>(1024, 512), 2U);
  EXPECT_EQ(dem::chunk_count<std::int64_t>(1025, 512), 3U);
  // n + chunk − 1 would wrap here; the count is still right.
  EXPECT_EQ(dem::chunk_count<std::uint32_t>(0xFFFFFFFFU, 512U), 0x800000U);
  // More chunks than 32-bit cursors hold: 0, and the loop runs a static split.
  EXPECT_EQ(dem::chunk_count<std::int64_t>(std::int64_t{1} << 33, 1), 0U);
  for (const int r : runs_of(2, 100, 0)) EXPECT_EQ(r, 1);  // a chunk of 0 counts as 1
}

TEST(BalancedForThreads, TellsEachBodyAThreadWithinTheTeamEvenInsideTheCallersRegion) {
  // Per-thread scratch indexed by the thread the loop names: every index once, each thread number
  // below the thread count asked for — also when the loop runs in place (one thread, or one chunk)
  // on a thread of the caller's own OpenMP region, whose number there may be larger.
  const auto check = [](int threads, std::int64_t n, std::int64_t chunk) {
    std::vector<std::atomic<int>> count(static_cast<std::size_t>(n));
    std::atomic<std::uint32_t> highest{0};
    dem::balanced_for_threads(threads, n, chunk, [&](std::uint32_t thread, std::int64_t i) {
      count[static_cast<std::size_t>(i)].fetch_add(1);
      std::uint32_t seen = highest.load();
      while (thread > seen && !highest.compare_exchange_weak(seen, thread)) {
      }
    });
    for (const auto& c : count) EXPECT_EQ(c.load(), 1) << threads << " threads, " << n << " indices";
    EXPECT_LT(highest.load(), static_cast<std::uint32_t>(std::max(threads, 1)));
  };
  for (const int threads : {1, 2, 3, dem::kMaxBalancedThreads + 1}) check(threads, 1000, 7);
  check(2, 5, 10);  // one chunk: in place
#pragma omp parallel num_threads(3)
  {
    if (omp_get_thread_num() == 2) {
      check(1, 100, 7);  // in place, on thread 2 of this region: the body is told 0
      check(2, 5, 10);
    }
  }
}

TEST(BalancedMax, IsTheSerialLargestForAnyThreadCount) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const std::int64_t n : {0, 1, 511, 512, 513, 40000}) {
    std::vector<double> v(static_cast<std::size_t>(n));
    for (double& x : v) x = u(rng);
    double serial = -2.0;
    for (const double x : v) serial = std::max(serial, x);
    for (const int threads : {1, 2, 3, 4}) {
      const double got =
          dem::balanced_max(threads, n, std::int64_t{512}, -2.0, [&](std::int64_t i) { return v[static_cast<std::size_t>(i)]; });
      EXPECT_EQ(got, serial) << n << " values, " << threads << " threads";
    }
  }
}

}  // namespace balanced_for_test
