// SPDX-License-Identifier: MIT
// The machine probe `demwb bench --speedup` reports beside the core's speed-up: what it returns
// and what it refuses (its ratios are timings, never asserted: docs/performance.md).
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "bench/bench_result.hpp"
#include "bench/machine_probe.hpp"

namespace machine_probe_test {

/// A probe small enough for a unit test (a few milliseconds).
bench::ProbeWork small() {
  bench::ProbeWork w;
  w.arithmetic_iterations = 20'000;
  w.stream_bytes = 1U << 16U;
  w.stream_passes = 2;
  return w;
}

TEST(MachineProbe, GivesPositiveFiniteRatiosForTheThreadsItGot) {
  for (const int threads : {1, 2, 3}) {
    const bench::MachineProbe p = bench::probe_machine(threads, small());
    EXPECT_EQ(p.threads, threads);
    EXPECT_TRUE(std::isfinite(p.arithmetic) && p.arithmetic > 0.0) << p.arithmetic;
    EXPECT_TRUE(std::isfinite(p.memory) && p.memory > 0.0) << p.memory;
    EXPECT_TRUE(std::isfinite(p.unequal) && p.unequal >= 1.0) << p.unequal;
    if (threads == 1) {
      EXPECT_DOUBLE_EQ(p.unequal, 1.0);  // one thread is as fast as itself
    }
  }
}

TEST(MachineProbe, ThroughputCountsEachThreadAtItsOwnSpeed) {
  // Two threads each doing one kernel, in 1 s and 2 s: 1.5 kernels a second, the slower taking 2×.
  const double two[] = {1.0, 2.0};
  const bench::ProbeTiming t = bench::probe_timing(two, 2);
  EXPECT_DOUBLE_EQ(t.throughput, 1.5);
  EXPECT_DOUBLE_EQ(t.unequal, 2.0);
  // Against one thread that took 1 s, the ratio the probe reports is 1.5 (not 1, the wall time's).
  const double one[] = {1.0};
  EXPECT_DOUBLE_EQ(t.throughput / bench::probe_timing(one, 1).throughput, 1.5);
  EXPECT_DOUBLE_EQ(bench::probe_timing(one, 1).unequal, 1.0);
  const double three[] = {0.5, 0.5, 0.25};
  EXPECT_DOUBLE_EQ(bench::probe_timing(three, 3).throughput, 8.0);
  EXPECT_DOUBLE_EQ(bench::probe_timing(three, 3).unequal, 2.0);
  const double bad[] = {1.0, 0.0};
  EXPECT_THROW((void)bench::probe_timing(bad, 2), std::invalid_argument);
  EXPECT_THROW((void)bench::probe_timing(one, 0), std::invalid_argument);
}

TEST(MachineProbe, RefusesNoThreadsAndNoWork) {
  EXPECT_THROW((void)bench::probe_machine(0, small()), std::invalid_argument);
  EXPECT_THROW((void)bench::probe_machine(-2, small()), std::invalid_argument);
  bench::ProbeWork none = small();
  none.stream_passes = 0;
  EXPECT_THROW((void)bench::probe_machine(2, none), std::invalid_argument);
  none = small();
  none.arithmetic_iterations = 0;
  EXPECT_THROW((void)bench::probe_machine(2, none), std::invalid_argument);
}

TEST(MachineProbe, TheBenchReportsTheMediansOfItsProbesBesideTheSpeedup) {
  bench::BenchResult r;
  bench::CoreRun two;
  two.threads = 2;
  two.particle_steps_per_s = 300.0;
  two.wall_s = 1.0;
  two.particles = 10;
  two.state_sha256 = "same";
  bench::CoreRun one = two;
  one.threads = 1;
  one.particle_steps_per_s = 200.0;
  r.core_runs = {two, two, two};
  r.one_thread_runs = {one, one, one};
  bench::choose_medians(r);
  EXPECT_FALSE(r.machine().has_value());
  EXPECT_TRUE(bench::bench_json(r)["thread_speedup"]["machine"].is_null());
  r.machine_probes = {{2, 1.9, 1.2, 1.4}, {2, 1.5, 1.0, 1.0}, {2, 2.0, 2.1, 1.1}};
  const auto m = r.machine();
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(m->threads, 2);
  EXPECT_DOUBLE_EQ(m->arithmetic, 1.9);
  EXPECT_DOUBLE_EQ(m->memory, 1.2);
  EXPECT_DOUBLE_EQ(m->unequal, 1.1);
  const nlohmann::json j = bench::bench_json(r)["thread_speedup"]["machine"];
  EXPECT_DOUBLE_EQ(j["arithmetic"].get<double>(), 1.9);
  EXPECT_DOUBLE_EQ(j["memory"].get<double>(), 1.2);
  EXPECT_EQ(j["probes"].size(), 3U);
  EXPECT_DOUBLE_EQ(j["probes"][1]["arithmetic"].get<double>(), 1.5);
  EXPECT_NE(bench::bench_table(r).find("the machine itself on 2 threads / on 1 thread, probed in the same minutes with "
                                       "kernels independent of the core: arithmetic 1.90, memory stream 1.20 (ideal 2); its slowest thread "
                                       "took 1.10× its fastest's time"),
            std::string::npos)
      << bench::bench_table(r);
  EXPECT_NE(bench::bench_markdown(r, "demwb bench box --threads 2 --speedup").find("medians of 3 probes"), std::string::npos);
  // The probe does not decide whether the bench passed: only the core's own checks do.
  EXPECT_TRUE(r.ok());
}

}  // namespace machine_probe_test
