// SPDX-License-Identifier: MIT
// The reference discretisation-error check (compare/time_step_refinement): halving Δt keeps the
// sample instants, the Richardson estimate tracks the true error, the level kept is the first
// within a tenth of every tolerance, failures and the limit are reported, and native rows carry
// the estimate. The "reference code" here is the in-house core run with velocity Verlet, whose
// dashpot error is first order like LAMMPS's; the real LAMMPS case is in tests/engines.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "cases/time_step.hpp"
#include "compare/case_outcome.hpp"
#include "compare/discrepancy.hpp"
#include "compare/time_step_refinement.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/inhouse/inhouse_engine.hpp"

namespace time_step_refinement_test {

/// hertz_damped_collision with velocity Verlet: −0.27 % contact time at the case's Δt.
cases::Scene damped_verlet() {
  cases::Scene s = cases::load_case(std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/canonical/hertz_damped_collision.toml");
  s.integration.scheme = dem::SchemeId::velocity_verlet;
  return s;
}

cases::RunResult core(const cases::Scene& s) { return reference::run_engine(reference::InhouseEngine{}, s, {}); }

TEST(TimeStepRefinement, HalvingKeepsTheSampleInstantsAndTheLastOne) {
  const cases::Scene s = damped_verlet();
  const cases::Scene finer = comparison::halved_time_step(s, 3);
  EXPECT_EQ(cases::run_timestep(finer), cases::run_timestep(s) / 8.0);
  EXPECT_EQ(finer.output.trace_every, 8 * s.output.trace_every);
  const auto a = core(s), b = core(finer);
  ASSERT_EQ(a.trace.rows(), b.trace.rows());
  const auto& ta = *a.trace.column("time");
  const auto& tb = *b.trace.column("time");
  for (std::size_t k = 0; k < ta.size(); ++k) EXPECT_NEAR(tb[k], ta[k], 1e-15) << k;
  // An automatic step is halved through steps_per_collision.
  cases::Scene automatic = s;
  automatic.integration.timestep.reset();
  EXPECT_EQ(cases::run_timestep(comparison::halved_time_step(automatic, 2)), cases::run_timestep(automatic) / 4.0);
}

TEST(TimeStepRefinement, KeepsTheFirstLevelWithinATenthOfEveryToleranceAndItsEstimateIsTheError) {
  const cases::Scene s = damped_verlet();
  const auto base = core(s);
  const auto analytic = reference::run_engine(reference::AnalyticEngine{}, s, {});
  ASSERT_EQ(analytic.status, cases::RunStatus::ok) << analytic.reason;
  int runs = 0;
  const auto f = comparison::refine_time_step(s, base, [&](const cases::Scene& finer) { ++runs; return core(finer); },
                                              &analytic);
  EXPECT_TRUE(f.problem.empty()) << f.problem;
  EXPECT_FALSE(f.limit_reached);
  EXPECT_GE(f.halvings, 3);  // 0.27 % at Δt, tolerance 0.2 %: far from a tenth of it
  EXPECT_EQ(runs, f.halvings + 1);
  EXPECT_EQ(f.timestep, cases::run_timestep(s) / std::ldexp(1.0, f.halvings));
  for (const auto& [metric, estimate] : f.estimates) {
    const cases::Tolerance tol = comparison::tolerance_for(s, metric);
    EXPECT_LE(estimate, 0.1 * (tol.abs + tol.rel * std::abs(f.metrics.at(metric)))) << metric;
  }
  // First-order convergence: the estimate is the true error against the closed form to ±50 %.
  const double exact = analytic.exact_metrics.at("contact_duration");
  const double error = std::abs(f.metrics.at("contact_duration") - exact);
  EXPECT_GT(f.estimates.at("contact_duration"), 0.5 * error);
  EXPECT_LT(f.estimates.at("contact_duration"), 1.5 * error);
}

TEST(TimeStepRefinement, ACoarseEnoughStepIsKeptAfterOneCheck) {
  // The elastic collision: velocity Verlet is second order there, well within a tenth at 100 steps.
  const cases::Scene s =
      cases::load_case(std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/canonical/hertz_collision.toml");
  int runs = 0;
  const auto f = comparison::refine_time_step(s, core(s), [&](const cases::Scene& finer) { ++runs; return core(finer); },
                                              nullptr);
  EXPECT_EQ(f.halvings, 0);
  EXPECT_EQ(runs, 1);
  EXPECT_FALSE(f.estimates.contains("amplitude_error"));  // needs the analytic run: no value, no estimate
  EXPECT_TRUE(f.estimates.contains("contact_duration"));
}

TEST(TimeStepRefinement, AFailedRunOrTheLimitIsReportedNeverHidden) {
  const cases::Scene s = damped_verlet();
  const auto base = core(s);
  int runs = 0;
  const auto failing = comparison::refine_time_step(s, base, [&](const cases::Scene& finer) {
    if (++runs == 2) {
      cases::RunResult r;
      r.status = cases::RunStatus::error;
      r.reason = "timed out";
      return r;
    }
    return core(finer);
  }, nullptr);
  EXPECT_NE(failing.problem.find("Δt/4 ended error: timed out"), std::string::npos) << failing.problem;
  EXPECT_EQ(failing.halvings, 0);  // the values kept are those whose estimate exists
  EXPECT_FALSE(failing.estimates.empty());
  const auto limited = comparison::refine_time_step(s, base, core, nullptr, {2, 0.1});
  EXPECT_TRUE(limited.limit_reached);
  EXPECT_EQ(limited.halvings, 1);
  EXPECT_EQ(limited.limit, 2);
}

TEST(TimeStepRefinement, NativeRowsCarryTheEstimateAndMatchedOnesDoNot) {
  const cases::Scene s = damped_verlet();
  cases::RunResult code = core(s);
  code.engine = "lammps";  // stands for a reference code's native run
  code.refinement = comparison::refine_time_step(s, code, core, nullptr, {1, 0.1});
  cases::RunResult matched = core(s);
  matched.engine = "inhouse@lammps";
  cases::Scene scene = s;
  scene.compare.matched = {"lammps"};
  const auto outcome = comparison::evaluate_runs(
      scene, {reference::run_engine(reference::AnalyticEngine{}, s, {}), code, matched});
  int native = 0;
  for (const auto& row : outcome.comparisons) {
    if (row.engine == "lammps" && row.metric == "contact_duration") {
      ++native;
      ASSERT_TRUE(row.error_estimate.has_value());
      EXPECT_EQ(*row.error_estimate, code.refinement->estimates.at("contact_duration"));
      EXPECT_EQ(*row.timestep, code.refinement->timestep);
      EXPECT_EQ(*row.value, code.refinement->metrics.at("contact_duration"));
      EXPECT_NE(row.note.find("the limit"), std::string::npos) << row.note;
    }
    if (row.engine == "inhouse@lammps") {
      EXPECT_FALSE(row.error_estimate.has_value()) << row.metric;
      // The matched run is compared with the code's run at the case's own Δt: identical here.
      if (row.metric == "contact_duration") {
        EXPECT_EQ(*row.abs_diff, 0.0);
      }
    }
  }
  EXPECT_EQ(native, 1);
}

}  // namespace time_step_refinement_test
