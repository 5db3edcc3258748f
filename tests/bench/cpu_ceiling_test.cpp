// SPDX-License-Identifier: MIT
// How far unequal CPUs cap a thread speed-up (`demwb bench --per-cpu`), against hand-worked
// cases, and what the pin does to the calling thread.
#include <sched.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "bench/cpu_ceiling.hpp"
#include "bench/cpu_pinning.hpp"

namespace cpu_ceiling_test {

TEST(CpuCeiling, EqualCpusAllowTheThreadCountAndTheEfficiencyIsTheSpeedupOverIt) {
  const std::vector<bench::CpuSpeed> cpus{{0, 100.0}, {1, 100.0}};
  const bench::CpuCeiling c = bench::cpu_ceiling(cpus, 2, 180.0);
  EXPECT_DOUBLE_EQ(c.ceiling, 2.0);
  EXPECT_DOUBLE_EQ(c.speedup, 1.8);
  EXPECT_DOUBLE_EQ(c.efficiency, 0.9);
  EXPECT_EQ(c.fastest_cpu, 0);  // a tie goes to the lower number
}

TEST(CpuCeiling, ASlowerCpuLowersTheCeilingNotTheEfficiency) {
  // CPU 0 takes 1.25× CPU 1's time: 80 against 100. Perfect sharing gives 180 = 1.8 × 100.
  const std::vector<bench::CpuSpeed> cpus{{0, 80.0}, {1, 100.0}};
  const bench::CpuCeiling perfect = bench::cpu_ceiling(cpus, 2, 180.0);
  EXPECT_EQ(perfect.fastest_cpu, 1);
  EXPECT_DOUBLE_EQ(perfect.fastest, 100.0);
  EXPECT_DOUBLE_EQ(perfect.ceiling, 1.8);
  EXPECT_DOUBLE_EQ(perfect.speedup, 1.8);
  EXPECT_DOUBLE_EQ(perfect.efficiency, 1.0);
  const bench::CpuCeiling short_of_it = bench::cpu_ceiling(cpus, 2, 162.0);
  EXPECT_DOUBLE_EQ(short_of_it.efficiency, 0.9);
  EXPECT_DOUBLE_EQ(short_of_it.speedup, 1.62);
}

TEST(CpuCeiling, ATeamUsesItsThreadCountOfTheFastestCpusAndAllOfTooFew) {
  const std::vector<bench::CpuSpeed> four{{0, 50.0}, {1, 100.0}, {2, 90.0}, {3, 70.0}};
  // Two threads: the two fastest, 100 + 90.
  EXPECT_DOUBLE_EQ(bench::cpu_ceiling(four, 2, 95.0).ceiling, 1.9);
  EXPECT_DOUBLE_EQ(bench::cpu_ceiling(four, 2, 95.0).efficiency, 0.5);
  // Eight threads on four CPUs: all of them, 310.
  EXPECT_DOUBLE_EQ(bench::cpu_ceiling(four, 8, 310.0).ceiling, 3.1);
  EXPECT_DOUBLE_EQ(bench::cpu_ceiling(four, 8, 310.0).efficiency, 1.0);
  // The order given does not matter.
  const std::vector<bench::CpuSpeed> shuffled{four[3], four[1], four[0], four[2]};
  EXPECT_DOUBLE_EQ(bench::cpu_ceiling(shuffled, 3, 130.0).ceiling, bench::cpu_ceiling(four, 3, 130.0).ceiling);
  EXPECT_EQ(bench::cpu_ceiling(shuffled, 3, 130.0).fastest_cpu, 1);
}

TEST(CpuCeiling, RefusesWhatCannotBeATiming) {
  const std::vector<bench::CpuSpeed> none;
  EXPECT_THROW((void)bench::cpu_ceiling(none, 2, 1.0), std::invalid_argument);
  const std::vector<bench::CpuSpeed> one{{0, 1.0}};
  EXPECT_THROW((void)bench::cpu_ceiling(one, 0, 1.0), std::invalid_argument);
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW((void)bench::cpu_ceiling(one, 2, bad), std::invalid_argument) << bad;
    const std::vector<bench::CpuSpeed> bad_cpu{{0, 1.0}, {1, bad}};
    EXPECT_THROW((void)bench::cpu_ceiling(bad_cpu, 2, 1.0), std::invalid_argument) << bad;
  }
}

TEST(PinnedToCpu, RunsTheThreadOnThatCpuAndRestoresItsMaskAfter) {
  const std::vector<int> before = bench::allowed_cpus();
  ASSERT_FALSE(before.empty());
  for (const int cpu : before) {
    {
      const bench::PinnedToCpu pin(cpu);
      EXPECT_EQ(bench::allowed_cpus(), std::vector<int>{cpu});
      EXPECT_EQ(sched_getcpu(), cpu);
    }
    EXPECT_EQ(bench::allowed_cpus(), before);
  }
}

TEST(PinnedToCpu, RefusesACpuTheThreadMayNotRunOn) {
  EXPECT_THROW(bench::PinnedToCpu(-1), std::invalid_argument);
  EXPECT_THROW(bench::PinnedToCpu(CPU_SETSIZE), std::invalid_argument);
  const std::vector<int> before = bench::allowed_cpus();
  {
    const bench::PinnedToCpu pin(before.front());
    if (before.size() > 1) {
      EXPECT_THROW(bench::PinnedToCpu(before.back()), std::invalid_argument);  // outside the pin
    }
  }
  EXPECT_EQ(bench::allowed_cpus(), before);
}

}  // namespace cpu_ceiling_test
