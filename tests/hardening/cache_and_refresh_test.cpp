// SPDX-License-Identifier: MIT
// With the real reference codes: `refresh` of a folder of cases exits 0 (n/a is an answer, not a failure), a
// tampered cache entry is detected and run again, a tampered baseline is refused, and two
// --reproducible runs write byte-identical results.json.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/process.hpp"
#include "tests/app/demwb_process.hpp"

namespace cache_and_refresh_test {

using demwb_e2e::canonical;
using demwb_e2e::demwb;
using demwb_e2e::scratch;
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

bool have_lammps() { return support::find_program("lmp").has_value(); }
bool have_yade() { return support::find_program("yade").has_value(); }

// A folder of two canonical cases: JKR pull-off, which YADE cannot express (n/a), and the oblique
// wall impact, which both codes run. (The whole canonical suite runs against both codes in the
// suite's end-to-end test and in CI's gate phase; refreshing all of it here took 219 s of CI.)
TEST(Refresh, AFolderOfCasesExitsZeroWithItsNotApplicableRows) {
  if (!have_lammps() || !have_yade()) GTEST_SKIP() << "needs LAMMPS and YADE (scripts/setup.sh installs them)";
  const fs::path dir = scratch("refresh-cases");
  fs::create_directories(dir);
  for (const char* name : {"jkr_pulloff", "oblique_wall_impact"}) {
    fs::copy_file(canonical(name), dir / (std::string(name) + ".toml"), fs::copy_options::overwrite_existing);
  }
  const auto r = demwb({"refresh", dir.string(), "--cache", scratch("refresh-cache").string(), "-o",
                        scratch("refresh-out").string()});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("| jkr_pulloff | yade | n/a |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| oblique_wall_impact | yade | ok |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| oblique_wall_impact | lammps | ok |"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("| error |"), std::string::npos) << r.out;
}

TEST(Refresh, AMissingReferenceCodeFailsIt) {
  const auto r = demwb({"refresh", canonical("single_collision"), "--lammps", "/nonexistent/lmp", "--cache",
                        scratch("refresh-missing-cache").string(), "-o", scratch("refresh-missing-out").string()});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("| lammps | missing |"), std::string::npos) << r.out;
}

/// The cache entry of `engine` under `cache` for the case's own run: the time-step check adds
/// entries for the same scene at Δt/2, Δt/4, …, so it is the entry with the largest Δt.
fs::path case_entry(const fs::path& cache, const std::string& engine) {
  fs::path best;
  double largest = 0.0;
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(cache / engine)) {
    ++entries;
    const double dt = Json::parse(support::read_file(e.path()))["scene"]["integration"]["timestep"].get<double>();
    if (dt > largest) {
      largest = dt;
      best = e.path();
    }
  }
  EXPECT_GE(entries, 2U) << "the case's run and at least its Δt/2 check";
  return best;
}

TEST(Cache, ATamperedEntryIsDetectedRunAgainAndReplaced) {
  if (!have_lammps()) GTEST_SKIP() << "lmp is not installed (scripts/setup.sh installs it)";
  const fs::path cache = scratch("tamper-cache");
  // Without the case's matched line: LAMMPS' entry is the one under test, YADE's runs add nothing.
  const std::vector<std::string> base{"run", demwb_e2e::canonical_unmatched("single_collision"), "--engine",
                                      "analytic,lammps", "--cache", cache.string()};
  const fs::path first = scratch("tamper-first");
  const fs::path second_out = scratch("tamper-second");
  const fs::path third_out = scratch("tamper-third");
  auto with_out = [&](const fs::path& out) {
    auto a = base;
    a.insert(a.end(), {"-o", out.string()});
    return a;
  };
  ASSERT_EQ(demwb(with_out(first)).exit_code, 0);
  const fs::path entry = case_entry(cache, "lammps");
  const std::string genuine = support::read_file(entry);
  // Scale every position of the stored trace by 1 + 1e-5: valid JSON, plausible numbers.
  Json j = Json::parse(genuine);
  for (auto& v : j["result"]["trace"]["p0.x"]) v = v.get<double>() * (1 + 1e-5);
  support::write_file(entry, j.dump());
  const auto second = demwb(with_out(second_out));
  EXPECT_EQ(second.exit_code, 0) << second.out << second.err;
  const Json results = Json::parse(support::read_file(second_out / "results.json"));
  const Json& lammps = results["engines"]["lammps"];
  EXPECT_EQ(lammps["source"], "run") << "the tampered entry was served";
  EXPECT_NE(lammps["warnings"].dump().find("cache entry not trusted"), std::string::npos) << lammps.dump(1);
  // Replaced by a genuine entry again: a third run is a cache hit.
  EXPECT_EQ(Json::parse(support::read_file(entry))["result"]["trace"], Json::parse(genuine)["result"]["trace"]);
  ASSERT_EQ(demwb(with_out(third_out)).exit_code, 0);
  const Json third = Json::parse(support::read_file(third_out / "results.json"));
  EXPECT_EQ(third["engines"]["lammps"]["source"], "cache");
}

TEST(Baselines, AnEditedBaselineIsRefusedNotUsed) {
  // LAMMPS "absent", so the run falls back to the committed baseline, which has been edited.
  const fs::path dir = scratch("edited-baselines");
  fs::create_directories(dir);
  Json b = Json::parse(support::read_file(fs::path(DEMWB_SOURCE_DIR) / "cases/baselines/single_collision.json"));
  ASSERT_TRUE(b.contains("sha256")) << "committed baselines carry their checksum";
  b["references"]["lammps"]["trace"]["p0.x"][10] = 0.0;
  support::write_file(dir / "single_collision.json", b.dump(1));
  const fs::path out = scratch("edited-baselines-out");
  const auto r = demwb({"run", canonical("single_collision"), "--engine", "analytic,lammps", "--lammps",
                        "/nonexistent/lmp", "--no-cache", "--baselines", dir.string(), "-o", out.string()});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const Json results = Json::parse(support::read_file(out / "results.json"));
  EXPECT_EQ(results["engines"]["lammps"]["status"], "error");
  EXPECT_NE(results["engines"]["lammps"]["reason"].get<std::string>().find("sha256"), std::string::npos)
      << results["engines"]["lammps"].dump(1);
}

TEST(Reproducible, TwoFreshRunsWriteIdenticalResults) {
  if (!have_lammps() || !have_yade()) GTEST_SKIP() << "needs LAMMPS and YADE (scripts/setup.sh installs them)";
  std::vector<std::string> texts;
  for (const char* name : {"repro-a", "repro-b"}) {
    const fs::path out = scratch(name);
    const auto r = demwb({"run", canonical("single_collision"), "--no-cache", "--reproducible", "-o", out.string()});
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    texts.push_back(support::read_file(out / "results.json"));
  }
  EXPECT_EQ(texts[0], texts[1]);
  EXPECT_EQ(texts[0].find("scratch_directory"), std::string::npos);
  EXPECT_EQ(texts[0].find("wall_time_s"), std::string::npos);
}


TEST(TimeStepCheck, NativeRowsCarryTheEstimateUnlessTheCheckIsTurnedOff) {
  if (!have_lammps()) GTEST_SKIP() << "lmp is not installed (scripts/setup.sh installs it)";
  const fs::path with = scratch("step-check-on");
  const fs::path without = scratch("step-check-off");
  const std::vector<std::string> base{"compare", canonical("hertz_damped_collision"), "--engines", "analytic,lammps",
                                      "--no-cache", "--reproducible"};
  auto on = base;
  on.insert(on.end(), {"-o", with.string()});
  auto off = base;
  off.insert(off.end(), {"--no-time-step-check", "-o", without.string()});
  // With the check LAMMPS passes at a refined Δt; without it, at the case's Δt, it misses by 0.27 %.
  EXPECT_EQ(demwb(on).exit_code, 0);
  EXPECT_EQ(demwb(off).exit_code, 1);
  const Json a = Json::parse(support::read_file(with / "results.json"));
  const Json b = Json::parse(support::read_file(without / "results.json"));
  ASSERT_TRUE(a["engines"]["lammps"].contains("time_step_check")) << a["engines"]["lammps"].dump(1);
  EXPECT_FALSE(b["engines"]["lammps"].contains("time_step_check"));
  for (const Json& row : a["comparisons"]) {
    if (row["engine"] != "lammps") continue;
    EXPECT_TRUE(row.contains("error_estimate")) << row.dump();
    EXPECT_LT(row["timestep"].get<double>(), 6.9e-6) << row.dump();
  }
  for (const Json& row : b["comparisons"]) EXPECT_FALSE(row.contains("error_estimate")) << row.dump();
  EXPECT_NE(support::read_file(with / "report.md").find("own Δt error"), std::string::npos);
}

TEST(TimeStepCheck, AManyBodyCaseIsNotRefined) {
  // 27 spheres: chaotic, compared as an ensemble elsewhere; one run's Δt error is not the question.
  if (!have_lammps()) GTEST_SKIP() << "lmp is not installed (scripts/setup.sh installs it)";
  const fs::path out = scratch("step-check-many");
  const auto r = demwb({"run", std::string(DEMWB_TEST_DATA_DIR) + "/many_body/jkr_cluster_wall.toml", "--engine",
                        "lammps", "--no-cache", "-o", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const Json results = Json::parse(support::read_file(out / "results.json"));
  EXPECT_EQ(results["engines"]["lammps"]["status"], "ok");
  EXPECT_FALSE(results["engines"]["lammps"].contains("time_step_check")) << results["engines"]["lammps"].dump(1);
}

}  // namespace
