// SPDX-License-Identifier: MIT
// `demwb bench`: what it writes and how it fails. Timings are never asserted (benchmarks are
// not timed tests); the chute's energy check is exercised where its deck is available.
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "demwb_process.hpp"
#include "support/process.hpp"
#include "support/text_file.hpp"

namespace bench_e2e_test {

using demwb_e2e::demwb;
using demwb_e2e::scratch;
namespace fs = std::filesystem;

TEST(DemwbBench, BoxWritesBenchJsonWithTheContractFields) {
  const fs::path out = scratch("bench_box");
  const auto r = demwb({"bench", "box", "--engines", "inhouse", "--particles", "300", "--steps", "30", "--repeat", "2",
                        "--threads", "2", "-o", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(support::read_file(out / "bench.json"));
  EXPECT_EQ(j["scene"], "box");
  EXPECT_EQ(j["n_particles"], 300);
  EXPECT_EQ(j["steps"], 30);
  const auto& core = j["engines"]["inhouse"];
  EXPECT_EQ(core["threads"], 2);
  EXPECT_GT(core["particle_steps_per_s"].get<double>(), 0.0);
  EXPECT_GT(core["wall_s"].get<double>(), 0.0);
  EXPECT_GT(core["bytes_per_particle"].get<double>(), 100.0);
  EXPECT_EQ(j["repetitions"].size(), 2U);
  EXPECT_TRUE(j["ratio_inhouse_to_lammps"].is_null());  // LAMMPS not asked for
  EXPECT_NE(support::read_file(out / "report.md").find("particle-steps/s"), std::string::npos);
  EXPECT_NE(r.out.find("inhouse"), std::string::npos);
}

/// The core alone on a 1,100-sphere box (more than one 512-sphere chunk, so the balanced
/// per-sphere passes share out), 30 steps, twice, on two threads, with `option` (--speedup or
/// --per-cpu), written to scratch `name`: the run, and its bench.json when it succeeded.
struct TwoThreadBox {
  demwb_e2e::Outcome run;
  nlohmann::json json;
};
TwoThreadBox two_thread_box(const std::string& name, const std::string& option) {
  const fs::path out = scratch(name);
  TwoThreadBox b{demwb({"bench", "box", "--engines", "inhouse", "--particles", "1100", "--steps", "30", "--repeat", "2",
                        "--threads", "2", option, "-o", out.string()}),
                 nullptr};
  if (b.run.exit_code == 0) b.json = nlohmann::json::parse(support::read_file(out / "bench.json"));
  return b;
}

TEST(DemwbBench, SpeedupRunsTheCoreOnOneThreadToo) {
  const auto [r, j] = two_thread_box("bench_speedup", "--speedup");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto& s = j["thread_speedup"];
  EXPECT_EQ(s["threads"], 2);
  EXPECT_EQ(s["pairs"].size(), 2U);
  EXPECT_GT(s["median"].get<double>(), 0.0);
  EXPECT_EQ(s["one_thread"]["threads"], 1);
  EXPECT_GT(s["one_thread"]["particle_steps_per_s"].get<double>(), 0.0);
  // The deterministic mode: the same final state on one thread and on two.
  EXPECT_TRUE(s["identical_across_threads"].get<bool>());
  EXPECT_EQ(s["state_sha256"].get<std::string>().size(), 64U);
  EXPECT_EQ(s["one_thread"]["state_sha256"], s["state_sha256"]);
  EXPECT_NE(r.out.find("inhouse on 2 threads / on 1 thread"), std::string::npos) << r.out;
  // The machine probed after each pair: its own two-thread ratios, one probe per repetition.
  EXPECT_EQ(s["machine"]["threads"], 2);
  EXPECT_EQ(s["machine"]["probes"].size(), 2U);
  EXPECT_GT(s["machine"]["arithmetic"].get<double>(), 0.0);
  EXPECT_GT(s["machine"]["memory"].get<double>(), 0.0);
  EXPECT_NE(r.out.find("the machine itself on 2 threads"), std::string::npos) << r.out;
  // Without --speedup nothing of it.
  const fs::path plain = scratch("bench_no_speedup");
  ASSERT_EQ(demwb({"bench", "box", "--engines", "inhouse", "--particles", "300", "--steps", "30", "-o", plain.string()})
                .exit_code,
            0);
  EXPECT_TRUE(nlohmann::json::parse(support::read_file(plain / "bench.json"))["thread_speedup"].is_null());
}

TEST(DemwbBench, PerCpuPinsOneThreadToEachCpuInTurn) {
  const auto [r, j] = two_thread_box("bench_per_cpu", "--per-cpu");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto& p = j["per_cpu"];
  EXPECT_EQ(p["threads"], 2);
  ASSERT_EQ(p["repetitions"].size(), 2U);
  // One pinned run per CPU this process may use, the same CPUs in each repetition, in order.
  const std::size_t cpus = p["cpus"].size();
  EXPECT_GE(cpus, 1U);
  for (std::size_t r_index = 0; r_index < p["repetitions"].size(); ++r_index) {
    const auto& rep = p["repetitions"][r_index];
    ASSERT_EQ(rep["runs"].size(), cpus);
    for (std::size_t k = 0; k < cpus; ++k) {
      EXPECT_EQ(rep["runs"][k]["cpu"], p["cpus"][k]["cpu"]);
      // The pin held: the run ended on the CPU it was pinned to.
      EXPECT_EQ(rep["runs"][k]["ran_on"], rep["runs"][k]["cpu"]);
      // In increasing order in the first repetition, reversed in the second.
      EXPECT_EQ(rep["runs"][k]["order"].get<std::size_t>(), r_index == 0 ? k : cpus - 1 - k);
      EXPECT_GT(rep["runs"][k]["wall_s"].get<double>(), 0.0);
    }
    EXPECT_GT(rep["efficiency"].get<double>(), 0.0);
    EXPECT_GT(rep["ceiling"].get<double>(), 0.0);
    EXPECT_LE(rep["ceiling"].get<double>(), 2.0 + 1e-12);  // never more than the threads
  }
  EXPECT_TRUE(p["identical_across_threads"].get<bool>());
  EXPECT_TRUE(j["thread_speedup"].is_null());  // --per-cpu alone
  EXPECT_NE(r.out.find("inhouse on 1 thread pinned to each CPU in turn"), std::string::npos) << r.out;
  const auto one = demwb({"bench", "box", "--per-cpu"});
  EXPECT_EQ(one.exit_code, 2);
  EXPECT_NE(one.err.find("--per-cpu"), std::string::npos) << one.err;
}

TEST(DemwbBench, BadUsageExitsTwoNamingTheProblem) {
  const auto scene = demwb({"bench", "pyramid"});
  EXPECT_EQ(scene.exit_code, 2);
  EXPECT_NE(scene.err.find("unknown bench scene 'pyramid'"), std::string::npos) << scene.err;
  const auto chute = demwb({"bench", "chute", "--chute-dir", scratch("no_chute").string()});
  EXPECT_EQ(chute.exit_code, 2);
  EXPECT_NE(chute.err.find("in.chute and data.chute"), std::string::npos) << chute.err;
  const auto threads = demwb({"bench", "box", "--threads", "0"});
  EXPECT_EQ(threads.exit_code, 2);
  EXPECT_NE(threads.err.find("--threads"), std::string::npos) << threads.err;
  const auto none = demwb({"bench", "box", "--engines", ","});
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("name at least one"), std::string::npos) << none.err;
  const auto speedup = demwb({"bench", "box", "--speedup"});
  EXPECT_EQ(speedup.exit_code, 2);
  EXPECT_NE(speedup.err.find("--speedup"), std::string::npos) << speedup.err;
  const auto engines = demwb({"bench", "box", "--engines", "yade"});
  EXPECT_EQ(engines.exit_code, 2);
  EXPECT_NE(engines.err.find("cannot be benchmarked"), std::string::npos) << engines.err;
}

TEST(DemwbBench, ChuteMatchesLammpsStep100EnergiesWhenTheDeckIsThere) {
  const auto dir = std::getenv("DEMWB_CHUTE_DIR");
  const fs::path chute = dir != nullptr ? fs::path(dir) : fs::path(DEMWB_SOURCE_DIR) / ".." / "shared" / "bench" / "lammps-chute";
  if (!fs::exists(chute / "data.chute")) GTEST_SKIP() << "LAMMPS's chute deck is not on this machine";
  const fs::path out = scratch("bench_chute");
  const auto r = demwb({"bench", "chute", "--engines", "inhouse", "--steps", "100", "--chute-dir", chute.string(),
                        "-o", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(support::read_file(out / "bench.json"));
  ASSERT_EQ(j["checks"].size(), 2U);
  for (const auto& c : j["checks"]) EXPECT_TRUE(c["match"].get<bool>()) << c.dump();
  EXPECT_EQ(j["checks"][0]["inhouse"], "784292.08");
  EXPECT_EQ(j["checks"][1]["inhouse"], "1571.0968");
}

}  // namespace
