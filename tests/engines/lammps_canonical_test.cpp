// SPDX-License-Identifier: MIT
// The canonical cases through the real LAMMPS binary, against the closed forms (native numerics).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "compare/case_outcome.hpp"
#include "compare/time_step_refinement.hpp"
#include "lammps_test_support.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/lammps/lammps_engine.hpp"

namespace lammps_canonical_test {

using demwb_lammps_test::canonical;
using demwb_lammps_test::scratch;

/// Runs the three engines on a canonical case and evaluates the case's own metrics.
comparison::CaseOutcome compare_three(const cases::Scene& scene, const std::string& test) {
  std::vector<cases::RunResult> runs;
  runs.push_back(reference::run_engine(reference::InhouseEngine{}, scene, {}));
  runs.push_back(reference::run_engine(reference::AnalyticEngine{}, scene, {}));
  runs.push_back(reference::run_engine(reference::LammpsEngine{}, scene, scratch(test)));
  return comparison::evaluate_runs(scene, std::move(runs));
}

/// Every comparison of LAMMPS against the analytic reference passes the case's tolerance.
void expect_lammps_passes(const comparison::CaseOutcome& outcome) {
  const cases::RunResult& lammps = outcome.runs.back();
  ASSERT_EQ(lammps.status, cases::RunStatus::ok) << lammps.reason << "\n" << lammps.log_tail;
  std::size_t checked = 0;
  for (const auto& c : outcome.comparisons) {
    if (c.engine != "lammps") continue;
    ++checked;
    EXPECT_EQ(c.status, comparison::Status::pass)
        << c.metric << ": " << c.value.value_or(NAN) << " vs " << c.reference_value.value_or(NAN)
        << " " << c.note;
  }
  EXPECT_EQ(checked, outcome.scene.compare.metrics.size());
}

TEST(LammpsCanonical, SingleCollisionMatchesTheClosedFormsWithinTheCaseTolerances) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_lammps_passes(compare_three(canonical("single_collision"), "canonical_single"));
}

TEST(LammpsCanonical, SandwichMatchesTheClosedFormsWithinTheCaseTolerances) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_lammps_passes(compare_three(canonical("sandwich"), "canonical_sandwich"));
}

TEST(LammpsCanonical, HertzDampedCollisionPassesAtTheTimeStepItsOwnErrorEstimateAsksFor) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  const cases::Scene scene = canonical("hertz_damped_collision");
  std::vector<cases::RunResult> runs;
  runs.push_back(reference::run_engine(reference::InhouseEngine{}, scene, {}));
  runs.push_back(reference::run_engine(reference::AnalyticEngine{}, scene, {}));
  runs.push_back(reference::run_engine(reference::LammpsEngine{}, scene, scratch("canonical_damped")));
  cases::RunResult& lammps = runs.back();
  ASSERT_EQ(lammps.status, cases::RunStatus::ok) << lammps.reason << "\n" << lammps.log_tail;
  // At the case's Δt LAMMPS's velocity Verlet misses the contact time by 0.27 % (tolerance 0.2 %).
  const comparison::CaseOutcome unrefined = comparison::evaluate_runs(scene, runs);
  bool failed_before = false;
  for (const auto& c : unrefined.comparisons) {
    failed_before = failed_before || (c.engine == "lammps" && c.metric == "contact_duration" &&
                                      c.status == comparison::Status::fail);
  }
  EXPECT_TRUE(failed_before);
  int level = 0;
  lammps.refinement = comparison::refine_time_step(
      scene, lammps,
      [&](const cases::Scene& finer) {
        return reference::run_engine(reference::LammpsEngine{}, finer, scratch(fmt::format("canonical_damped_{}", ++level)));
      },
      &runs[1]);
  const cases::TimeStepRefinement& f = *lammps.refinement;
  EXPECT_TRUE(f.problem.empty()) << f.problem;
  EXPECT_FALSE(f.limit_reached);
  EXPECT_GE(f.halvings, 1);
  const comparison::CaseOutcome outcome = comparison::evaluate_runs(scene, runs);
  std::size_t checked = 0;
  for (const auto& c : outcome.comparisons) {
    if (c.engine != "lammps") continue;
    ++checked;
    EXPECT_EQ(c.status, comparison::Status::pass) << c.metric << ": " << c.note;
    ASSERT_TRUE(c.error_estimate.has_value()) << c.metric;
    EXPECT_EQ(*c.timestep, f.timestep);
    // The estimate is an error bound the comparison can trust: within a tenth of the tolerance.
    EXPECT_LE(*c.error_estimate, 0.1 * (c.tolerance.abs + c.tolerance.rel * std::abs(*c.value))) << c.metric;
  }
  EXPECT_EQ(checked, scene.compare.metrics.size());
}

TEST(LammpsCanonical, TraceHasTheInhouseColumnsSampleTimesAndSnapshots) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  const cases::Scene scene = canonical("single_collision");
  const auto inhouse = reference::run_engine(reference::InhouseEngine{}, scene, {});
  const auto lammps =
      reference::run_engine(reference::LammpsEngine{}, scene, scratch("canonical_columns"));
  ASSERT_EQ(lammps.status, cases::RunStatus::ok) << lammps.reason << "\n" << lammps.log_tail;
  EXPECT_EQ(lammps.trace.columns(), inhouse.trace.columns());
  EXPECT_EQ(*lammps.trace.column("time"), *inhouse.trace.column("time"));
  ASSERT_EQ(lammps.snapshots.size(), inhouse.snapshots.size());
  for (std::size_t k = 0; k < lammps.snapshots.size(); ++k) {
    EXPECT_EQ(lammps.snapshots[k].time, inhouse.snapshots[k].time);
    EXPECT_EQ(lammps.snapshots[k].position.size(), scene.particles.size());
  }
  EXPECT_EQ(lammps.version, "LAMMPS 29 Sep 2021 - Update 2");
  EXPECT_EQ(lammps.conventions.at("LAMMPS version"), "LAMMPS 29 Sep 2021 - Update 2");
  EXPECT_TRUE(lammps.warnings.empty());
}

}  // namespace
