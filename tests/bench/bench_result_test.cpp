// SPDX-License-Identifier: MIT
// What a bench with several reference codes reports: pairwise ratios, medians, and which
// outcomes fail it (a code missing, crashed or timed out fails; one that cannot express the
// scene is n/a and does not).
#include <limits>

#include <gtest/gtest.h>

#include "bench/bench_result.hpp"

namespace {

bench::CoreRun core(double speed, int threads = 1, const std::string& state = "same") {
  bench::CoreRun c;
  c.threads = threads;
  c.state_sha256 = state;
  c.particle_steps_per_s = speed;
  c.wall_s = 1.0;
  c.particles = 10;
  c.bytes = 1000;
  return c;
}

bench::CodeRun code(const std::string& engine, const std::string& status, double speed = 0.0) {
  bench::CodeRun r;
  r.engine = engine;
  r.status = status;
  r.particle_steps_per_s = speed;
  r.log.loop_s = 1.0;
  return r;
}

bench::BenchResult two_codes() {
  bench::BenchResult r;
  r.core_runs = {core(300.0), core(200.0), core(400.0)};
  r.codes.push_back({bench::lammps_code("lmp", 10.0), {code("lammps", "ok", 100.0), code("lammps", "ok", 100.0),
                                                 code("lammps", "ok", 200.0)}, std::nullopt});
  r.codes.push_back({bench::liggghts_code("liggghts", 10.0), {code("liggghts", "ok", 150.0), code("liggghts", "ok", 400.0),
                                                        code("liggghts", "ok", 100.0)}, std::nullopt});
  bench::choose_medians(r);
  return r;
}

TEST(BenchResult, EachCodesRatioIsTheMedianOfTheRunsMadeOneAfterTheOther) {
  const bench::BenchResult r = two_codes();
  EXPECT_EQ(r.ratios("lammps"), (std::vector<double>{3.0, 2.0, 2.0}));
  EXPECT_DOUBLE_EQ(*r.ratio("lammps"), 2.0);
  EXPECT_EQ(r.ratios("liggghts"), (std::vector<double>{2.0, 0.5, 4.0}));
  EXPECT_DOUBLE_EQ(*r.ratio("liggghts"), 2.0);
  EXPECT_FALSE(r.ratio("yade").has_value());
  EXPECT_DOUBLE_EQ(r.core->particle_steps_per_s, 300.0);
  EXPECT_DOUBLE_EQ(r.code("liggghts")->median->particle_steps_per_s, 150.0);
  EXPECT_TRUE(r.ok());
  const nlohmann::json j = bench::bench_json(r);
  EXPECT_DOUBLE_EQ(j["ratio_inhouse_to_lammps"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["ratio_inhouse_to_liggghts"].get<double>(), 2.0);
  EXPECT_EQ(j["engines"]["liggghts"]["status"], "ok");
  EXPECT_DOUBLE_EQ(j["repetitions"][1]["liggghts_particle_steps_per_s"].get<double>(), 400.0);
  const std::string md = bench::bench_markdown(r, "demwb bench box");
  EXPECT_NE(md.find("inhouse / LIGGGHTS"), std::string::npos) << md;
  EXPECT_NE(bench::bench_table(r).find("ratio inhouse / lammps: 2.00"), std::string::npos);
}

TEST(BenchResult, AFailedCodeFailsTheBenchAndNotApplicableDoesNot) {
  for (const char* failed : {"missing", "error"}) {
    bench::BenchResult r = two_codes();
    r.codes[1].runs[2] = code("liggghts", failed);
    r.codes[1].runs[2].reason = "why";
    bench::choose_medians(r);
    EXPECT_FALSE(r.ok()) << failed;
    EXPECT_EQ(r.code("liggghts")->median->status, failed);
    const nlohmann::json j = bench::bench_json(r);
    EXPECT_EQ(j["engines"]["liggghts"]["status"], failed);
    EXPECT_EQ(j["engines"]["liggghts"]["reason"], "why");
    EXPECT_FALSE(j["engines"]["liggghts"].contains("particle_steps_per_s"));
  }
  bench::BenchResult na = two_codes();
  na.codes[1].runs.clear();
  na.codes[1].median = code("liggghts", "n/a");
  EXPECT_TRUE(na.ok());
  EXPECT_FALSE(na.ratio("liggghts").has_value());
  EXPECT_TRUE(bench::bench_json(na)["ratio_inhouse_to_liggghts"].is_null());
}

TEST(BenchResult, TheThreadSpeedupIsTheMedianOfAlternatingPairsAndDifferentFinalStatesFailTheBench) {
  bench::BenchResult r;
  r.core_runs = {core(380.0, 2), core(360.0, 2), core(400.0, 2)};
  EXPECT_FALSE(r.speedup().has_value());  // no one-thread runs: nothing to say
  EXPECT_FALSE(r.identical_across_threads().has_value());
  EXPECT_TRUE(r.ok());
  r.one_thread_runs = {core(200.0), core(150.0), core(200.0)};
  bench::choose_medians(r);
  EXPECT_EQ(r.speedups(), (std::vector<double>{1.9, 2.4, 2.0}));
  EXPECT_DOUBLE_EQ(*r.speedup(), 2.0);
  EXPECT_DOUBLE_EQ(r.one_thread->particle_steps_per_s, 200.0);
  EXPECT_EQ(r.identical_across_threads(), true);
  EXPECT_TRUE(r.ok());
  const nlohmann::json j = bench::bench_json(r);
  EXPECT_EQ(j["thread_speedup"]["threads"], 2);
  EXPECT_DOUBLE_EQ(j["thread_speedup"]["median"].get<double>(), 2.0);
  EXPECT_EQ(j["thread_speedup"]["pairs"].size(), 3U);
  EXPECT_EQ(j["thread_speedup"]["one_thread"]["threads"], 1);
  EXPECT_FALSE(j["thread_speedup"]["one_thread"].contains("peak_rss_bytes_per_particle"));
  EXPECT_TRUE(j["thread_speedup"]["identical_across_threads"].get<bool>());
  EXPECT_DOUBLE_EQ(j["repetitions"][1]["inhouse_one_thread_particle_steps_per_s"].get<double>(), 150.0);
  EXPECT_NE(bench::bench_table(r).find("inhouse on 2 threads / on 1 thread: 2.00 (median of 3 pairs, 2 threads then 1: "
                                       "1.90, 2.40, 2.00); final states identical to the last bit"),
            std::string::npos)
      << bench::bench_table(r);
  EXPECT_NE(bench::bench_markdown(r, "demwb bench box --threads 2 --speedup").find("Speed-up on 2 threads"),
            std::string::npos);
  // One run ending elsewhere — on one thread or on two — breaks the deterministic mode: the bench fails.
  for (const bool in_one : {true, false}) {
    bench::BenchResult broken = r;
    (in_one ? broken.one_thread_runs[2] : broken.core_runs[1]).state_sha256 = "other";
    EXPECT_EQ(broken.identical_across_threads(), false);
    EXPECT_FALSE(broken.ok());
    EXPECT_FALSE(bench::bench_json(broken)["thread_speedup"]["identical_across_threads"].get<bool>());
    EXPECT_NE(bench::bench_table(broken).find("DIFFER"), std::string::npos);
  }
}

TEST(BenchResult, PinnedRunsGiveEachRepetitionsCeilingAndTheirMediansAndMustEndInTheSameState) {
  bench::BenchResult r;
  r.core_runs = {core(180.0, 2), core(162.0, 2), core(190.0, 2)};
  EXPECT_FALSE(r.per_cpu().has_value());  // no pinned runs: nothing to say
  const auto pinned = [](double cpu0, double cpu1) {
    bench::CoreRun a = core(cpu0);
    a.wall_s = 10.0 / cpu0;
    bench::CoreRun b = core(cpu1);
    b.wall_s = 10.0 / cpu1;
    return std::vector<bench::PinnedRun>{{0, 0, 0, a}, {1, 1, 1, b}};
  };
  // CPU 0 slower in the first two repetitions (ceiling 1.8), equal in the third (ceiling 2).
  r.pinned_runs = {pinned(80.0, 100.0), pinned(80.0, 100.0), pinned(100.0, 100.0)};
  bench::choose_medians(r);
  const std::vector<bench::CpuCeiling> each = r.ceilings();
  ASSERT_EQ(each.size(), 3U);
  EXPECT_DOUBLE_EQ(each[0].efficiency, 1.0);
  EXPECT_DOUBLE_EQ(each[1].efficiency, 0.9);
  EXPECT_DOUBLE_EQ(each[2].efficiency, 0.95);
  EXPECT_EQ(each[0].fastest_cpu, 1);
  const auto p = r.per_cpu();
  ASSERT_TRUE(p.has_value());
  EXPECT_DOUBLE_EQ(p->ceiling, 1.8);
  EXPECT_DOUBLE_EQ(p->speedup, 1.8);
  EXPECT_DOUBLE_EQ(p->efficiency, 0.95);
  ASSERT_EQ(p->loop_s.size(), 2U);
  EXPECT_EQ(p->loop_s[0].first, 0);
  EXPECT_DOUBLE_EQ(p->loop_s[0].second, 0.125);  // median of 0.125, 0.125, 0.1
  EXPECT_DOUBLE_EQ(p->loop_s[1].second, 0.1);
  EXPECT_EQ(r.identical_across_threads(), true);  // pinned runs alone are enough to compare
  EXPECT_TRUE(r.ok());
  const nlohmann::json j = bench::bench_json(r);
  EXPECT_TRUE(j["thread_speedup"].is_null());  // no --speedup
  EXPECT_EQ(j["per_cpu"]["threads"], 2);
  EXPECT_DOUBLE_EQ(j["per_cpu"]["efficiency"].get<double>(), 0.95);
  EXPECT_DOUBLE_EQ(j["per_cpu"]["ceiling"].get<double>(), 1.8);
  EXPECT_EQ(j["per_cpu"]["cpus"].size(), 2U);
  EXPECT_EQ(j["per_cpu"]["repetitions"].size(), 3U);
  EXPECT_EQ(j["per_cpu"]["repetitions"][1]["runs"][0]["cpu"], 0);
  EXPECT_DOUBLE_EQ(j["per_cpu"]["repetitions"][1]["efficiency"].get<double>(), 0.9);
  EXPECT_TRUE(j["per_cpu"]["identical_across_threads"].get<bool>());
  const std::string table = bench::bench_table(r);
  EXPECT_NE(table.find("inhouse on 1 thread pinned to each CPU in turn (medians of 3 repetitions, each taken on its "
                       "own): CPU 0 loop 0.125 s, CPU 1 loop 0.100 s; on 2 threads over one thread on the fastest CPU "
                       "1.80, these CPUs' summed one-thread speeds allowing 1.80; the threads reached 95 % of that sum "
                       "(per repetition: 100 %, 90 %, 95 %); final states identical to the last bit"),
            std::string::npos)
      << table;
  EXPECT_EQ(j["per_cpu"]["timed_repetitions"], 3);
  EXPECT_NE(bench::bench_markdown(r, "demwb bench box --threads 2 --per-cpu").find("the code's share"), std::string::npos);
  EXPECT_TRUE(bench::bench_json(bench::BenchResult{})["per_cpu"].is_null());
  // A repetition whose runs were too short to time is left out of the medians, never a crash or a NaN.
  bench::BenchResult untimed = r;
  untimed.pinned_runs[0][1].run.particle_steps_per_s = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(untimed.ceiling_at(0).has_value());
  EXPECT_EQ(untimed.ceilings().size(), 2U);
  EXPECT_EQ(untimed.per_cpu()->repetitions, 2U);
  EXPECT_DOUBLE_EQ(untimed.per_cpu()->efficiency, 0.925);  // median of 0.9 and 0.95
  EXPECT_DOUBLE_EQ(untimed.per_cpu()->loop_s[0].second, 0.1125);  // CPU 0: 0.125 and 0.1, the untimed repetition out
  EXPECT_NE(bench::bench_table(untimed).find("(per repetition: untimed, 90 %, 95 %)"), std::string::npos)
      << bench::bench_table(untimed);
  const nlohmann::json u = bench::bench_json(untimed);
  EXPECT_TRUE(u["per_cpu"]["repetitions"][0]["efficiency"].is_null());
  EXPECT_DOUBLE_EQ(u["per_cpu"]["repetitions"][1]["efficiency"].get<double>(), 0.9);
  // A pinned run ending elsewhere breaks the deterministic mode: the bench fails.
  bench::BenchResult broken = r;
  broken.pinned_runs[1][1].run.state_sha256 = "other";
  EXPECT_EQ(broken.identical_across_threads(), false);
  EXPECT_FALSE(broken.ok());
  EXPECT_NE(bench::bench_table(broken).find("DIFFER"), std::string::npos);
}

}  // namespace
