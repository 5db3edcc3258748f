// SPDX-License-Identifier: MIT
// The one rule that turns requested snapshot times into steps, shared by the core, the closed
// forms and the LAMMPS deck: the first step n in [0, steps] with n·Δt ≥ t − Δt/2.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "cases/time_step.hpp"

namespace snapshot_steps_test {

using cases::snapshot_steps;
using Steps = std::vector<std::uint64_t>;

TEST(SnapshotSteps, TakesTheFirstStepWithinHalfAStepOfEachTimeInTimeOrder) {
  EXPECT_EQ(snapshot_steps({8e-4, 0.0, 3.7e-4}, 5e-6, 160), (Steps{0, 74, 160}));
  EXPECT_EQ(snapshot_steps({0.4e-5, 0.6e-5}, 1e-5, 10), (Steps{0, 1}));
  EXPECT_EQ(snapshot_steps({0.5e-5}, 1e-5, 10), (Steps{0}));  // exactly half a step: the earlier
  EXPECT_EQ(snapshot_steps({3e-5, 3e-5}, 1e-5, 10), (Steps{3, 3}));  // repeats kept
}

TEST(SnapshotSteps, TimesPastTheEndOrNotANumberGetNone) {
  EXPECT_EQ(snapshot_steps({2.0}, 1e-5, 10), Steps{});
  EXPECT_EQ(snapshot_steps({1.04e-4}, 1e-5, 10), (Steps{10}));  // within half a step of the end
  EXPECT_EQ(snapshot_steps({1.06e-4}, 1e-5, 10), Steps{});
  EXPECT_EQ(snapshot_steps({std::numeric_limits<double>::quiet_NaN(), 5e-5}, 1e-5, 10), (Steps{5}));
  EXPECT_EQ(snapshot_steps({std::numeric_limits<double>::infinity()}, 1e-5, 10), Steps{});
  EXPECT_EQ(snapshot_steps({-1.0}, 1e-5, 10), (Steps{0}));
}

TEST(SnapshotSteps, AgreesWithAStepByStepScanOnRandomTimes) {
  // The oracle is the loop a simulation runs: at each step n, take every pending time whose
  // threshold n·Δt has reached.
  std::mt19937_64 rng(2026);
  for (int trial = 0; trial < 2000; ++trial) {
    const double dt = std::uniform_real_distribution<double>(1e-7, 1e-3)(rng);
    const auto steps = std::uniform_int_distribution<std::uint64_t>(1, 400)(rng);
    std::vector<double> times;
    const int count = std::uniform_int_distribution<int>(0, 6)(rng);
    for (int k = 0; k < count; ++k) {
      // Half of them on the half-step boundaries, where round-off decides.
      const double at = static_cast<double>(std::uniform_int_distribution<std::uint64_t>(0, steps + 3)(rng));
      times.push_back(k % 2 == 0 ? (at + 0.5) * dt : std::uniform_real_distribution<double>(0.0, 1.1)(rng) *
                                                         static_cast<double>(steps) * dt);
    }
    std::vector<double> sorted = times;
    std::sort(sorted.begin(), sorted.end());
    Steps expected;
    std::size_t next = 0;
    for (std::uint64_t n = 0; n <= steps; ++n) {
      while (next < sorted.size() && static_cast<double>(n) * dt >= sorted[next] - 0.5 * dt) {
        expected.push_back(n);
        ++next;
      }
    }
    ASSERT_EQ(snapshot_steps(times, dt, steps), expected) << "trial " << trial << " dt " << dt;
  }
}

}  // namespace snapshot_steps_test
