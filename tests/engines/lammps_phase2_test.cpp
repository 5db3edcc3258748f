// SPDX-License-Identifier: MIT
// Phase-2 canonical cases through the real LAMMPS (Hertz, oblique wall impact with friction and
// rotation, JKR pull-off under prescribed motion, Tsuji-damped Hertz): native runs against the
// closed forms within the case tolerances, and the core on matched_scene(scene, "lammps")
// against LAMMPS within 1e-8 on every metric and on the position trace.
#include <cmath>
#include <iostream>
#include <set>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "compare/case_outcome.hpp"
#include "compare/metrics.hpp"
#include "lammps_test_support.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/lammps/lammps_engine.hpp"
#include "reference/matching.hpp"

namespace lammps_phase2_test {

using demwb_lammps_test::canonical;
using demwb_lammps_test::scratch;

/// Agreement the issue asks of matched numerics (relative; absolute on restitution).
constexpr double kMatched = 1e-8;

/// Native: inhouse, analytic and LAMMPS; every LAMMPS row passes, except `not_applicable`
/// metrics, which must be n/a with a reason.
void expect_native_passes(const cases::Scene& scene, const std::string& test,
                          const std::set<std::string>& not_applicable = {}) {
  std::vector<cases::RunResult> runs;
  runs.push_back(reference::run_engine(reference::InhouseEngine{}, scene, {}));
  runs.push_back(reference::run_engine(reference::AnalyticEngine{}, scene, {}));
  runs.push_back(reference::run_engine(reference::LammpsEngine{}, scene, scratch(test)));
  const comparison::CaseOutcome outcome = comparison::evaluate_runs(scene, std::move(runs));
  const cases::RunResult& lammps = outcome.runs.back();
  ASSERT_EQ(lammps.status, cases::RunStatus::ok) << lammps.reason << "\n" << lammps.log_tail;
  std::size_t checked = 0;
  for (const auto& c : outcome.comparisons) {
    if (c.engine != "lammps" || c.reference != scene.compare.reference) continue;
    ++checked;
    std::cout << fmt::format("  native {:<24} {:.9g} vs {:.9g} ({})\n", c.metric,
                             c.value.value_or(NAN), c.reference_value.value_or(NAN), c.note);
    if (not_applicable.contains(c.metric)) {
      EXPECT_EQ(c.status, comparison::Status::not_applicable) << c.metric;
      EXPECT_FALSE(c.note.empty()) << c.metric;
    } else {
      EXPECT_EQ(c.status, comparison::Status::pass)
          << c.metric << ": " << c.value.value_or(NAN) << " vs "
          << c.reference_value.value_or(NAN) << " " << c.note;
    }
  }
  EXPECT_EQ(checked, scene.compare.metrics.size());
}

/// Matched: the core on matched_scene vs LAMMPS. Every case metric (computed from both traces,
/// LAMMPS' inexpressible marks ignored: both follow LAMMPS' rule here) within kMatched, and
/// every position column within kMatched of the largest overlap.
void expect_matched(const cases::Scene& scene, const std::string& test) {
  cases::RunResult lammps =
      reference::run_engine(reference::LammpsEngine{}, scene, scratch(test));
  const cases::Scene matched = reference::matched_scene(scene, "lammps");
  const cases::RunResult inhouse = reference::run_engine(reference::InhouseEngine{}, matched, {});
  ASSERT_EQ(lammps.status, cases::RunStatus::ok) << lammps.reason << "\n" << lammps.log_tail;
  ASSERT_EQ(inhouse.status, cases::RunStatus::ok) << inhouse.reason;
  ASSERT_EQ(lammps.trace.columns(), inhouse.trace.columns());
  ASSERT_EQ(lammps.trace.rows(), inhouse.trace.rows());
  lammps.inexpressible_metrics.clear();
  const auto ours = comparison::compute_metrics(matched, inhouse, nullptr);
  const auto theirs = comparison::compute_metrics(matched, lammps, nullptr);
  for (const std::string& metric : scene.compare.metrics) {
    if (metric == "amplitude_error") continue;  // needs the analytic run; the trace covers it
    const auto& a = ours.at(metric);
    const auto& b = theirs.at(metric);
    ASSERT_TRUE(a.value && b.value) << metric << ": " << a.problem << " / " << b.problem;
    const double diff = std::abs(*a.value - *b.value);
    const double scale = metric == "restitution" ? 1.0 : std::abs(*b.value);
    std::cout << fmt::format("  matched {:<24} {:.12g} vs {:.12g}: {:.2e}\n", metric, *a.value,
                             *b.value, diff / scale);
    EXPECT_LE(diff, kMatched * scale) << metric;
  }
  for (const auto& [column, d] :
       demwb_lammps_test::scaled_differences(scene, inhouse.trace, lammps.trace)) {
    const std::string q = column.substr(column.find('.') + 1);
    if (q == "x" || q == "y" || q == "z" || q == "overlap") {
      EXPECT_LE(d, kMatched) << column;
    }
  }
}

/// oblique_wall_impact with fix wall/gran's lever arm r, which LAMMPS can express.
cases::Scene oblique_with_radius_lever() {
  cases::Scene scene = canonical("oblique_wall_impact");
  scene.model.wall_lever_arm = dem::WallLeverArm::radius;
  return scene;
}

TEST(LammpsPhase2, HertzCollisionMatchesTheClosedFormsWithinTheCaseTolerances) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_native_passes(canonical("hertz_collision"), "p2_hertz_native");
}

TEST(LammpsPhase2, HertzCollisionMatchedAgreesWithin1e8) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_matched(canonical("hertz_collision"), "p2_hertz_matched");
}

TEST(LammpsPhase2, ObliqueWallImpactWithRadiusLeverMatchesTheClosedForms) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_native_passes(oblique_with_radius_lever(), "p2_oblique_native");
}

TEST(LammpsPhase2, ObliqueWallImpactContactPointLeverIsNotApplicableForSpin) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_native_passes(canonical("oblique_wall_impact"), "p2_oblique_native_cp",
                       {"spin_after", "tangential_restitution"});
}

/// `scene` judged on the six end-state metrics instead of its own.
cases::Scene with_end_state_metrics(cases::Scene scene) {
  scene.compare.metrics = {"velocity_after_x",         "velocity_after_y",         "velocity_after_z",
                           "angular_velocity_after_x", "angular_velocity_after_y", "angular_velocity_after_z"};
  return scene;
}

TEST(LammpsPhase2, EndStateOfTheObliqueImpactMatchesTheClosedFormAndTheMatchedCore) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  // With LAMMPS' wall lever arm every component is expressible; with the case's contact-point
  // lever arm the spin components are n/a, as spin_after is.
  expect_native_passes(with_end_state_metrics(oblique_with_radius_lever()), "p2_end_state_native");
  expect_native_passes(with_end_state_metrics(canonical("oblique_wall_impact")), "p2_end_state_native_cp",
                       {"angular_velocity_after_x", "angular_velocity_after_y", "angular_velocity_after_z"});
  expect_matched(with_end_state_metrics(canonical("oblique_wall_impact")), "p2_end_state_matched");
}

TEST(LammpsPhase2, ObliqueWallImpactMatchedAgreesWithin1e8) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_matched(canonical("oblique_wall_impact"), "p2_oblique_matched");
}

TEST(LammpsPhase2, JkrPulloffForceMatchesAndRuptureMetricsAreNotApplicable) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_native_passes(canonical("jkr_pulloff"), "p2_jkr_native",
                       {"rupture_separation", "force_at_rupture", "separation_work"});
}

TEST(LammpsPhase2, JkrPulloffMatchedWithLoadRuptureAgreesWithin1e8) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_matched(canonical("jkr_pulloff"), "p2_jkr_matched");
}

TEST(LammpsPhase2, TsujiDampedHertzReboundsWithTheCaseRestitution) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  // Velocity Verlet (LAMMPS' only integrator) evaluates the dashpot at v(t + Δt/2): contact
  // time and peak are off by ~0.3 % at 110 steps per collision (the case's comment), so only
  // the restitution — the quantity the Tsuji e_in inversion fixes — is checked natively.
  const cases::Scene scene = canonical("hertz_damped_collision");
  const cases::RunResult lammps =
      reference::run_engine(reference::LammpsEngine{}, scene, scratch("p2_tsuji_native"));
  ASSERT_EQ(lammps.status, cases::RunStatus::ok) << lammps.reason << "\n" << lammps.log_tail;
  const auto metrics = comparison::compute_metrics(scene, lammps, nullptr);
  ASSERT_TRUE(metrics.at("restitution").value);
  EXPECT_NEAR(*metrics.at("restitution").value, 0.5, 1e-3);
}

TEST(LammpsPhase2, TsujiDampedHertzMatchedAgreesWithin1e8) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_matched(canonical("hertz_damped_collision"), "p2_tsuji_matched");
}

TEST(LammpsPhase2, TsujiMapsOverTheWholeRestitutionRangeUpToTheUndampedOne) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  // e_in below 0 (ε = 0.1), inside (0, 1), above 1 (ε = 0.9999: α below α_L(1) = 3e-4) and no
  // dashpot at all (ε = 1). The mapping is exact: the core with LAMMPS' numerics agrees with LAMMPS
  // within 1e-8. Natively LAMMPS rebounds with ε up to its own time-stepping error (velocity
  // Verlet evaluates the dashpot half a step late): within 1e-3 at the case's Δt (measured 2.2e-4
  // for ε = 0.5, 1.6e-6 for ε = 1), and where the heavy damping of ε = 0.1 puts it above that, it
  // shrinks with Δt (measured 2.04e-3 at Δt, 6.2e-4 at Δt/4) to below 1e-3.
  const auto rebound = [](const cases::Scene& scene, const std::string& dir) {
    const cases::RunResult lammps = reference::run_engine(reference::LammpsEngine{}, scene, scratch(dir));
    EXPECT_EQ(lammps.status, cases::RunStatus::ok) << lammps.reason << "\n" << lammps.log_tail;
    const auto metrics = comparison::compute_metrics(scene, lammps, nullptr);
    return metrics.at("restitution").value.value_or(NAN);
  };
  for (const double e : {0.1, 0.5, 0.9, 0.999, 0.9999, 1.0}) {
    SCOPED_TRACE(e);
    cases::Scene scene = canonical("hertz_damped_collision");
    scene.materials[0].restitution = e;
    const double error = std::abs(rebound(scene, fmt::format("p2_tsuji_range_{}", e)) - e);
    std::cout << fmt::format("  tsuji e = {}: LAMMPS misses by {:.3g} at dt = {:.3g} s\n", e, error,
                             *scene.integration.timestep);
    if (!(error <= 1e-3)) {
      cases::Scene fine = scene;
      *fine.integration.timestep /= 4.0;
      const double fine_error = std::abs(rebound(fine, fmt::format("p2_tsuji_range_fine_{}", e)) - e);
      std::cout << fmt::format("  tsuji e = {}: LAMMPS misses by {:.3g} at dt / 4\n", e, fine_error);
      EXPECT_LT(fine_error, 1e-3);
      EXPECT_LT(fine_error, error / 2.0);  // converging (3.3× for Δt/4 here)
    }
    expect_matched(scene, fmt::format("p2_tsuji_range_matched_{}", e));
  }
}

}  // namespace
