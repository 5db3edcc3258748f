// SPDX-License-Identifier: MIT
// `demwb bench` with the reference codes: the real LAMMPS and LIGGGHTS timed beside the core, and
// a code that is missing, crashes, hangs or cannot express the scene. Timings are never asserted.
#include <filesystem>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "fake_engines.hpp"
#include "support/process.hpp"
#include "support/text_file.hpp"
#include "tests/app/demwb_process.hpp"

namespace {

using namespace demwb_hardening;
using demwb_e2e::demwb;
using demwb_e2e::scratch;
using Json = nlohmann::json;

bool have(const char* program) { return support::find_program(program).has_value(); }

/// `demwb bench box` on 300 spheres for 30 steps (or `scene` for 20) with these extra arguments;
/// bench.json, the exit status and the output directory.
struct Bench {
  int exit_code = -1;
  Json json;
  std::string output;
  fs::path dir;
};
Bench bench_box(const std::string& name, const std::vector<std::string>& extra, const std::string& scene = "box") {
  const fs::path out = scratch(name);
  std::vector<std::string> args{"bench", scene, "--steps", scene == "box" ? "30" : "20", "-o", out.string()};
  if (scene == "box") args.insert(args.end(), {"--particles", "300"});
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = demwb(args);
  Bench b;
  b.exit_code = r.exit_code;
  b.output = r.out + r.err;
  b.dir = out;
  if (fs::exists(out / "bench.json")) b.json = Json::parse(support::read_file(out / "bench.json"));
  return b;
}

TEST(BenchCodes, TheBoxRunsOnTheCoreLammpsAndLiggghtsSideBySide) {
  if (!have("lmp") || !have("liggghts")) GTEST_SKIP() << "lmp or liggghts is not installed (scripts/setup.sh installs both)";
  const Bench b = bench_box("bench-three", {"--engines", "inhouse,lammps,liggghts", "--repeat", "2"});
  ASSERT_EQ(b.exit_code, 0) << b.output;
  for (const char* engine : {"lammps", "liggghts"}) {
    const Json& e = b.json["engines"][engine];
    EXPECT_EQ(e["status"], "ok") << engine << ": " << e.dump();
    EXPECT_EQ(e["ranks"], 1);
    EXPECT_GT(e["particle_steps_per_s"].get<double>(), 0.0) << engine;
    EXPECT_GT(e["bytes_per_particle"].get<double>(), 0.0) << engine;
    // The codes' own timing breakdowns were read (LIGGGHTS prints the 2013 form).
    EXPECT_GT(e["time_share_percent"]["forces"].get<double>(), 0.0) << engine;
    EXPECT_TRUE(b.json[fmt::format("ratio_inhouse_to_{}", engine)].is_number()) << engine;
    for (const Json& rep : b.json["repetitions"]) EXPECT_TRUE(rep.contains(fmt::format("{}_particle_steps_per_s", engine)));
  }
  EXPECT_NE(b.json["engines"]["liggghts"]["version"].get<std::string>().find("LIGGGHTS-PUBLIC"), std::string::npos);
  EXPECT_EQ(b.json["repetitions"].size(), 2U);
  const std::string deck = support::read_file(b.dir / "liggghts" / "deck.in");
  // The timing deck: LIGGGHTS's Hertz–Mindlin, the LAMMPS deck's skin, no stored forces.
  EXPECT_NE(deck.find("pair_style      gran model hertz tangential history"), std::string::npos) << deck;
  EXPECT_NE(deck.find("neighbor        0.00020000000000000001 bin"), std::string::npos) << deck;
  EXPECT_EQ(deck.find("store"), std::string::npos) << deck;
  EXPECT_NE(b.output.find("ratio inhouse / liggghts"), std::string::npos) << b.output;
  // The same physics in the three: the settling lattice's kinetic energy after 30 steps agrees
  // (LAMMPS' Tsuji dashpot is set through its own polynomial, hence not to the last digit).
  const Json& ke = b.json["kinetic_energy_at_end"];
  ASSERT_EQ(ke.size(), 3U) << b.json.dump();
  const double core = ke["inhouse"].get<double>();
  EXPECT_GT(core, 0.0);
  for (const char* engine : {"lammps", "liggghts"}) {
    EXPECT_NEAR(ke[engine].get<double>() / core, 1.0, 1e-2) << engine << ": " << ke.dump();
  }
}

TEST(BenchCodes, RanksRunLiggghtsUnderMpirun) {
  if (!have("liggghts") || !have("mpirun")) GTEST_SKIP() << "liggghts or mpirun is not installed";
  const Bench b = bench_box("bench-ranks", {"--engines", "liggghts", "--ranks", "2"});
  ASSERT_EQ(b.exit_code, 0) << b.output;
  EXPECT_EQ(b.json["engines"]["liggghts"]["ranks"], 2);
  EXPECT_NE(support::read_file(b.dir / "liggghts" / "log.liggghts").find("on 2 procs for 30 steps with 300 atoms"),
            std::string::npos);
}

TEST(BenchCodes, AMissingLiggghtsIsMissingAndFailsTheBenchWhileTheOthersStillRun) {
  const Bench b = bench_box("bench-no-liggghts", {"--engines", "inhouse,liggghts,lammps", "--liggghts",
                                                  "/nonexistent/liggghts", "--repeat", "2"});
  EXPECT_EQ(b.exit_code, 1) << b.output;
  EXPECT_EQ(b.json["engines"]["liggghts"]["status"], "missing");
  EXPECT_NE(b.json["engines"]["liggghts"]["reason"].get<std::string>().find("/nonexistent/liggghts"), std::string::npos);
  EXPECT_TRUE(b.json["ratio_inhouse_to_liggghts"].is_null());
  EXPECT_EQ(b.json["engines"]["inhouse"]["threads"], 1);  // the core still ran, every repetition
  EXPECT_EQ(b.json["repetitions"].size(), 2U);
  if (have("lmp")) {  // and so did LAMMPS, listed after the missing code
    EXPECT_EQ(b.json["engines"]["lammps"]["status"], "ok") << b.json.dump();
    EXPECT_TRUE(b.json["ratio_inhouse_to_lammps"].is_number());
  }
}

TEST(BenchCodes, ACrashingLiggghtsIsAnErrorNamingTheSignal) {
  if (!have("liggghts")) GTEST_SKIP() << "liggghts is not installed (scripts/setup.sh installs it)";
  const fs::path dir = scratch("bench-crash-liggghts");
  fs::create_directories(dir);
  const fs::path fake = dir / "liggghts";
  write_script(fake, fmt::format("for a in \"$@\"; do [ \"$a\" = /dev/null ] && exec {} \"$@\"; done\nkill -SEGV $$\n",
                                 support::find_program("liggghts")->string()));
  const Bench b = bench_box("bench-crash", {"--engines", "inhouse,liggghts", "--liggghts", fake.string()});
  EXPECT_EQ(b.exit_code, 1) << b.output;
  EXPECT_EQ(b.json["engines"]["liggghts"]["status"], "error");
  EXPECT_NE(b.json["engines"]["liggghts"]["reason"].get<std::string>().find("signal 11"), std::string::npos)
      << b.json.dump();
}

TEST(BenchCodes, AHungLiggghtsIsKilledAtTheTimeout) {
  if (!have("liggghts")) GTEST_SKIP() << "liggghts is not installed (scripts/setup.sh installs it)";
  const fs::path pids = scratch("bench-hang-liggghts-pid");
  const fs::path fake = fake_liggghts(scratch("bench-hang-liggghts"), Fault::hang, *support::find_program("liggghts"), pids);
  const Bench b = bench_box("bench-hang", {"--engines", "liggghts", "--liggghts", fake.string(), "--timeout", "3"});
  EXPECT_EQ(b.exit_code, 1) << b.output;
  EXPECT_EQ(b.json["engines"]["liggghts"]["status"], "error");
  EXPECT_NE(b.json["engines"]["liggghts"]["reason"].get<std::string>().find("timed out"), std::string::npos);
  EXPECT_FALSE(b.json["engines"].contains("inhouse"));
  const std::string pid = support::read_file(pids);
  EXPECT_TRUE(process_ended(pid.substr(0, pid.find_first_of("\n "))));
}

TEST(BenchCodes, ASceneLiggghtsCannotExpressIsNotApplicableWithTheReason) {
  // A case with JKR cohesion: LIGGGHTS' sjkr is not JKR; the bench says so and passes (n/a).
  const fs::path case_file = fs::path(DEMWB_SOURCE_DIR) / "cases" / "canonical" / "jkr_pulloff.toml";
  const Bench b = bench_box("bench-na", {"--engines", "inhouse,liggghts"}, case_file.string());
  EXPECT_EQ(b.exit_code, 0) << b.output;
  EXPECT_EQ(b.json["engines"]["liggghts"]["status"], "n/a");
  EXPECT_NE(b.json["engines"]["liggghts"]["reason"].get<std::string>().find("cohesion"), std::string::npos)
      << b.json.dump();
}

}  // namespace
