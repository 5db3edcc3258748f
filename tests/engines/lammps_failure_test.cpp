// SPDX-License-Identifier: MIT
// A LAMMPS run that fails is an error with the log tail, never a pass; no binary is `missing`.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "compare/case_outcome.hpp"
#include "lammps_test_support.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/lammps/lammps_engine.hpp"

namespace lammps_failure_test {

using demwb_lammps_test::canonical;
using demwb_lammps_test::scratch;

reference::LammpsEngine with_extra(const std::string& commands) {
  return reference::LammpsEngine(reference::LammpsOptions{"lmp", commands});
}

TEST(LammpsFailure, AnErrorInTheDeckIsAnErrorWithTheLogTailAndNeverAPass) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  const cases::Scene scene = canonical("single_collision");
  std::vector<cases::RunResult> runs;
  runs.push_back(reference::run_engine(reference::AnalyticEngine{}, scene, {}));
  runs.push_back(reference::run_engine(with_extra("this_is_not_a_command"), scene,
                                       scratch("failure_unknown_command")));
  const cases::RunResult& lammps = runs.back();
  EXPECT_EQ(lammps.status, cases::RunStatus::error);
  EXPECT_NE(lammps.reason.find("LAMMPS exited with status 1: ERROR: Unknown command: "
                               "this_is_not_a_command"),
            std::string::npos)
      << lammps.reason;
  EXPECT_NE(lammps.log_tail.find("ERROR: Unknown command"), std::string::npos) << lammps.log_tail;

  const comparison::CaseOutcome outcome = comparison::evaluate_runs(scene, std::move(runs));
  std::size_t seen = 0;
  for (const auto& c : outcome.comparisons) {
    if (c.engine != "lammps") continue;
    ++seen;
    EXPECT_EQ(c.status, comparison::Status::error) << c.metric;
  }
  EXPECT_GT(seen, 0u);
  EXPECT_FALSE(comparison::is_green(comparison::worst_status(outcome)));
}

TEST(LammpsFailure, ARunWithoutItsTraceFileIsAnError) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  const auto r = reference::run_engine(with_extra("unfix tr_print\nshell rm trace.txt"),
                                       canonical("single_collision"), scratch("failure_no_trace"));
  EXPECT_EQ(r.status, cases::RunStatus::error);
  EXPECT_NE(r.reason.find("wrote no trace file"), std::string::npos) << r.reason;
  EXPECT_NE(r.log_tail.find("Total wall time"), std::string::npos) << r.log_tail;
}

TEST(LammpsFailure, ATraceWithMissingRowsIsAnError) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  const auto r = reference::run_engine(with_extra("unfix tr_print"), canonical("single_collision"),
                                       scratch("failure_short_trace"));
  EXPECT_EQ(r.status, cases::RunStatus::error);
  EXPECT_NE(r.reason.find("LAMMPS trace file has 0 rows; expected 161"), std::string::npos)
      << r.reason;
}

TEST(LammpsFailure, ARunPastItsTimeoutIsKilledAndAnError) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  reference::RunOptions options = scratch("failure_timeout");
  options.timeout_s = 0.01;  // LAMMPS needs longer than this just to start
  const auto r =
      reference::run_engine(reference::LammpsEngine{}, canonical("single_collision"), options);
  EXPECT_EQ(r.status, cases::RunStatus::error);
  EXPECT_NE(r.reason.find("timed out"), std::string::npos) << r.reason;
}

TEST(LammpsFailure, NoLmpInPathIsMissing) {
  const char* old = std::getenv("PATH");
  const std::string saved = old != nullptr ? old : "";
  const auto empty = std::filesystem::temp_directory_path() / "demwb-lammps-tests" / "empty-path";
  std::filesystem::create_directories(empty);
  ::setenv("PATH", empty.c_str(), 1);
  const auto r = reference::run_engine(reference::LammpsEngine{}, canonical("single_collision"),
                                       scratch("failure_missing"));
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_EQ(r.status, cases::RunStatus::missing);
  EXPECT_NE(r.reason.find("not installed"), std::string::npos) << r.reason;
}

}  // namespace
