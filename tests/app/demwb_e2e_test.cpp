// SPDX-License-Identifier: MIT
// End-to-end tests of the demwb program: real process, real files.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "demwb_process.hpp"
#include "support/process.hpp"
#include "support/text_file.hpp"

namespace demwb_e2e_test {

using demwb_e2e::canonical;
using demwb_e2e::demwb;
using demwb_e2e::scratch;
namespace fs = std::filesystem;

TEST(DemwbRun, SingleCollisionMatchesTheClosedFormAndEveryComparisonPasses) {
  const fs::path out = scratch("run");
  const auto r = demwb({"run", canonical("single_collision"), "--engine", "inhouse", "--engine", "analytic", "-o", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(support::read_file(out / "results.json"));
  EXPECT_EQ(j["case"], "single_collision");
  const double m = 4.0 / 3.0 * std::numbers::pi * 1000.0 * 1e-6;
  const double tc = std::numbers::pi * std::sqrt(m / 1e5);
  const double duration = j["engines"]["inhouse"]["metrics"]["contact_duration"];
  EXPECT_NEAR(duration, tc, 1e-3 * tc);
  EXPECT_LT(std::abs(j["engines"]["inhouse"]["metrics"]["restitution"].get<double>() - 1.0), 1e-3);
  ASSERT_FALSE(j["comparisons"].empty());
  for (const auto& c : j["comparisons"]) EXPECT_EQ(c["status"], "pass") << c.dump();
  EXPECT_EQ(support::read_file(out / "case.toml"), support::read_file(canonical("single_collision")));
  EXPECT_NE(support::read_file(out / "command.txt").find("single_collision.toml"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "trace_inhouse.csv"));
  EXPECT_TRUE(fs::exists(out / "trace_analytic.csv"));
  EXPECT_TRUE(fs::exists(out / "plots" / "position.png"));
  for (const char* engine : {"inhouse", "analytic"}) {
    for (int k = 0; k < 3; ++k) {
      const fs::path vtk = out / "snapshots" / (std::string(engine) + "_000" + std::to_string(k) + ".vtk");
      ASSERT_TRUE(fs::exists(vtk)) << vtk;
      EXPECT_NE(support::read_file(vtk).find("POINTS 2 double"), std::string::npos);
    }
  }
}

TEST(DemwbRun, NoMatchRunsOnlyTheNamedEnginesAndRefusesMatchBesideIt) {
  // single_collision names matched = ["lammps", "yade"]: without --no-match this run would add
  // LAMMPS, YADE and the two matched in-house engines.
  const fs::path out = scratch("no_match");
  const auto r = demwb({"run", canonical("single_collision"), "--engine", "inhouse,analytic", "--no-match", "-o",
                        out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const auto j = nlohmann::json::parse(support::read_file(out / "results.json"));
  std::vector<std::string> engines;
  for (const auto& [name, _] : j["engines"].items()) engines.push_back(name);
  EXPECT_EQ(engines, (std::vector<std::string>{"analytic", "inhouse"}));
  ASSERT_FALSE(j["comparisons"].empty());
  for (const auto& c : j["comparisons"]) EXPECT_EQ(c["status"], "pass") << c.dump();

  const auto both = demwb({"run", canonical("single_collision"), "--match", "lammps", "--no-match", "-o",
                           scratch("no_match_both").string()});
  EXPECT_NE(both.exit_code, 0);
  EXPECT_NE(both.err.find("--match and --no-match"), std::string::npos) << both.out << both.err;

  // Commands that run what their own files name refuse both options instead of ignoring them.
  for (const char* command : {"refresh", "sweep"}) {
    const auto refused = demwb({command, (scratch("no_match_absent") / "absent.toml").string(), "--no-match"});
    EXPECT_NE(refused.exit_code, 0) << command;
    EXPECT_NE(refused.err.find("--no-match does not apply"), std::string::npos) << command << ": " << refused.err;
  }
}

TEST(DemwbRun, SameCaseTwiceGivesBitIdenticalTraces) {
  const fs::path a = scratch("repro_a"), b = scratch("repro_b");
  ASSERT_EQ(demwb({"run", canonical("sandwich"), "-o", a.string()}).exit_code, 0);
  ASSERT_EQ(demwb({"run", canonical("sandwich"), "-o", b.string()}).exit_code, 0);
  EXPECT_EQ(support::read_file(a / "trace_inhouse.csv"), support::read_file(b / "trace_inhouse.csv"));
}

TEST(DemwbCompare, PrintsTheTableAndPassesOnTheCanonicalCases) {
  for (const char* name : {"single_collision", "sandwich"}) {
    const auto r = demwb({"compare", canonical(name)});
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("| amplitude_error | inhouse |"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("result: ✅ pass"), std::string::npos) << r.out;
  }
}

TEST(DemwbCompare, SaysWhatEachReferenceCodeTheCaseDoesNotListMakesOfIt) {
  // JKR pull-off on the core and the closed form alone: LAMMPS has JKR, YADE and LIGGGHTS do not.
  // The verdicts come from the drivers' mappings; no code runs (none needs to be installed).
  const fs::path file = scratch("unlisted") / "jkr_pulloff.toml";
  fs::create_directories(file.parent_path());
  support::write_file(file, demwb_e2e::canonical_text_unmatched("jkr_pulloff", R"(["inhouse", "analytic"])"));
  const fs::path out = scratch("unlisted-out");
  const auto r = demwb({"compare", file.string(), "--lammps", "/nonexistent/lmp", "-o", out.string()});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("lammps (not among the engines): expresses it"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("liggghts (not among the engines): n/a — LIGGGHTS driver:"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(support::read_file(out / "results.json"));
  EXPECT_EQ(j["unlisted_codes"]["lammps"]["status"], "expressible");
  EXPECT_EQ(j["unlisted_codes"]["yade"]["status"], "n/a");
  EXPECT_NE(j["unlisted_codes"]["yade"]["reason"].get<std::string>().find("JKR"), std::string::npos) << j.dump(1);
  EXPECT_EQ(j["unlisted_codes"]["liggghts"]["status"], "n/a");
  EXPECT_NE(j["unlisted_codes"]["liggghts"]["reason"].get<std::string>().find("sjkr"), std::string::npos) << j.dump(1);
  EXPECT_EQ(j["engines"].size(), 2U) << "nothing but the listed engines ran";
  EXPECT_NE(support::read_file(out / "report.md").find("| liggghts | n/a | LIGGGHTS driver:"), std::string::npos);
}

TEST(DemwbCompare, ExitsNonZeroWhenAComparisonFails) {
  // The canonical case with an impossible amplitude tolerance, on the core and the closed form
  // (the failing row is theirs; the reference codes would only add minutes of runs).
  std::string text = demwb_e2e::canonical_text_unmatched("single_collision", R"(["inhouse", "analytic"])");
  const std::string from = "amplitude_error = { abs = 1.0e-3 }";
  text.replace(text.find(from), from.size(), "amplitude_error = { abs = 1.0e-12 }");
  const fs::path file = scratch("strict") / "strict.toml";
  support::write_file(file, text);
  const auto r = demwb({"compare", file.string()});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("❌ fail"), std::string::npos) << r.out;
}

TEST(DemwbErrors, BadCaseFileNamesFileLineAndKeyAndExitsTwo) {
  const std::string bad = std::string(DEMWB_TEST_DATA_DIR) + "/bad_cases/negative_radius.toml";
  const auto r = demwb({"run", bad});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("negative_radius.toml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("radius"), std::string::npos) << r.err;
}

TEST(DemwbErrors, UnknownCommandsEnginesAndOptionsExitTwo) {
  EXPECT_EQ(demwb({"frobnicate"}).exit_code, 2);
  EXPECT_EQ(demwb({}).exit_code, 2);
  EXPECT_EQ(demwb({"run", canonical("sandwich"), "--engine", "gromacs"}).exit_code, 2);
  EXPECT_EQ(demwb({"run", canonical("sandwich"), "--no-such-option"}).exit_code, 2);
  EXPECT_EQ(demwb({"study", "turbulence"}).exit_code, 2);
}

TEST(DemwbHelp, EveryCommandHasHelp) {
  EXPECT_EQ(demwb({"--help"}).exit_code, 0);
  for (const char* cmd : {"run", "compare", "suite", "sweep", "study", "engines"}) {
    const auto r = demwb({cmd, "--help"});
    EXPECT_EQ(r.exit_code, 0) << cmd;
    EXPECT_NE(r.out.find("usage: demwb"), std::string::npos) << cmd << ": " << r.out;
  }
}

/// Where the canonical gate test writes its report: $DEMWB_SUITE_REPORT_DIR when set (CI keeps it
/// as an artifact; it must not hold anything yet), else a scratch folder; empty when the named
/// folder is not empty.
fs::path suite_report_dir() {
  const char* kept = std::getenv("DEMWB_SUITE_REPORT_DIR");
  if (kept == nullptr || *kept == '\0') return scratch("suite");
  const fs::path dir = kept;
  if (fs::exists(dir) && !fs::is_empty(dir)) {
    ADD_FAILURE() << "DEMWB_SUITE_REPORT_DIR=" << dir << " is not empty: the test writes a fresh report there";
    return {};
  }
  return dir;
}

// One run of the whole canonical suite through the gate serves every check (the gate passes, the
// report covers every case, pandoc renders it): each run costs minutes of CI, and CI keeps this
// run's report instead of running the suite again.
TEST(DemwbSuite, CanonicalSuitePassesTheGateWithOneReportCoveringEveryCaseThatPandocRendersCleanly) {
  const fs::path out = suite_report_dir();
  ASSERT_FALSE(out.empty());
  const auto r = demwb({"gate", "canonical", "-o", out.string(), "-j", "2"}, {}, 1500);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("— PASS"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(support::read_file(out / "results.json"));
  EXPECT_EQ(j["status"], "pass");
  EXPECT_GE(j["cases"].size(), 2U);
  const std::string report = support::read_file(out / "report.md");
  for (const auto& c : j["cases"]) {
    const std::string name = c["case"];
    EXPECT_NE(report.find("`" + name + "`"), std::string::npos) << name;
    EXPECT_TRUE(fs::exists(out / name / "results.json")) << name;
  }
  // Every figure the report links exists.
  std::size_t figures = 0;
  for (std::size_t at = report.find("]("); at != std::string::npos; at = report.find("](", at + 2)) {
    const auto end = report.find(')', at);
    const std::string target = report.substr(at + 2, end - at - 2);
    if (target.size() < 4 || target.substr(target.size() - 4) != ".png") continue;
    ++figures;
    EXPECT_TRUE(fs::exists(out / target)) << target;
  }
  EXPECT_GE(figures, j["cases"].size());
  // Every case says what every reference code makes of it: a run (ok, or n/a with the driver's
  // reason), or, for a code the case does not list, its driver's verdict.
  for (const auto& c : j["cases"]) {
    for (const char* code : {"lammps", "yade", "liggghts"}) {
      const bool ran = c["engines"].contains(code);
      const bool surveyed = c.contains("unlisted_codes") && c["unlisted_codes"].contains(code);
      EXPECT_NE(ran, surveyed) << c["case"] << ": " << code << " should be either an engine or an unlisted code";
      if (surveyed && c["unlisted_codes"][code]["status"] == "n/a") {
        EXPECT_FALSE(c["unlisted_codes"][code]["reason"].get<std::string>().empty()) << c["case"] << ": " << code;
      }
      if (ran && c["engines"][code]["status"] == "n/a") {
        EXPECT_FALSE(c["engines"][code]["reason"].get<std::string>().empty()) << c["case"] << ": " << code;
      }
    }
  }
  EXPECT_TRUE(fs::exists(out / "junit.xml"));

  support::ProcessSpec probe;
  probe.argv = {"pandoc", "--version"};
  probe.timeout_s = 30;
  if (const auto p = support::run_process(probe); !p.started || p.exit_code != 0) {
    GTEST_SKIP() << "pandoc is not installed (scripts/setup.sh installs it): the rendering is not checked";
  }
  support::ProcessSpec spec;
  spec.argv = {"pandoc", "--fail-if-warnings", "-f", "gfm", "-t", "html", "--standalone", "--metadata",
               "title=report", (out / "report.md").string(), "-o", (out / "report.html").string()};
  spec.stderr_file = out / "pandoc.err";
  spec.timeout_s = 120;
  const auto rendered = support::run_process(spec);
  ASSERT_TRUE(rendered.started) << rendered.error;
  EXPECT_EQ(rendered.exit_code, 0) << support::read_file(out / "pandoc.err");
  EXPECT_EQ(support::read_file(out / "pandoc.err"), "");
  const std::string html = support::read_file(out / "report.html");
  EXPECT_NE(html.find("<table"), std::string::npos);
  EXPECT_NE(html.find("<img src=\"single_collision/plots/"), std::string::npos);
  EXPECT_EQ(html.find("|---|"), std::string::npos) << "a table was left as text";
}

TEST(DemwbEngines, ListsTheBuiltInEngines) {
  const auto r = demwb({"engines"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("| inhouse | installed |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| analytic | installed |"), std::string::npos) << r.out;
}

}  // namespace
