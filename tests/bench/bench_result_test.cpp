// SPDX-License-Identifier: MIT
// What a bench with several reference codes reports: pairwise ratios, medians, and which
// outcomes fail it (a code missing, crashed or timed out fails; one that cannot express the
// scene is n/a and does not).
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

}  // namespace
