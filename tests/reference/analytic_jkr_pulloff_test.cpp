// SPDX-License-Identifier: MIT
// The analytic JKR pull-off rig (cases/canonical/jkr_pulloff.toml): the exact curve with its
// hysteresis on the core's time points, the closed-form metrics, and the in-house core on it.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <filesystem>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "dem/contact/laws/jkr.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/inhouse/inhouse_engine.hpp"

namespace analytic_jkr_pulloff_test {

const std::filesystem::path kCase =
    std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/canonical/jkr_pulloff.toml";

/// The benchmark pair of the case: E* = 8.4e7/(2(1 − 0.3²)), R* = 2.5 mm, γ = 121.5 J/m².
dem::laws::JkrParameters benchmark() { return {8.4e7 / 1.82, 2.5e-3, 121.5}; }

cases::RunResult analytic(const cases::Scene& scene) {
  const reference::AnalyticEngine engine;
  EXPECT_TRUE(engine.supports(scene).supported()) << engine.supports(scene).explain();
  const cases::RunResult r = reference::run_engine(engine, scene, {});
  EXPECT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  return r;
}

TEST(AnalyticJkrPulloff, ExactMetricsAreTheClosedForms) {
  const cases::RunResult r = analytic(cases::load_case(kCase));
  const auto p = benchmark();
  const double f_po = 3.0 * std::numbers::pi * p.surface_energy * p.reduced_radius;
  EXPECT_NEAR(r.exact_metrics.at("pulloff_force"), f_po, 1e-12 * f_po);
  EXPECT_NEAR(r.exact_metrics.at("rupture_separation"), -dem::laws::jkr_rupture_overlap(p), 1e-18);
  EXPECT_NEAR(r.exact_metrics.at("force_at_rupture"), -5.0 / 9.0 * f_po, 1e-10 * f_po);
  const double work = dem::laws::jkr_energy(dem::laws::jkr_contact_radius(1.6e-4, p), p) -
                      dem::laws::jkr_energy(dem::laws::jkr_critical_radius(p), p);
  EXPECT_NEAR(r.exact_metrics.at("separation_work"), work, 1e-9 * std::abs(work));
  EXPECT_TRUE(r.warnings.empty());
}

TEST(AnalyticJkrPulloff, TraceFollowsTheJkrCurveWithItsHysteresis) {
  const cases::RunResult r = analytic(cases::load_case(kCase));
  const auto p = benchmark();
  const auto& t = *r.trace.column("time");
  const auto& d = *r.trace.column("c0-1.overlap");
  const auto& f = *r.trace.column("c0-1.fn");
  ASSERT_EQ(t.size(), 22001u);
  bool touched = false, broken = false;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double expected_overlap = t[k] <= 0.18 ? -2e-5 + 1e-3 * t[k] : 1.6e-4 - 1e-3 * (t[k] - 0.18);
    ASSERT_NEAR(d[k], expected_overlap, 1e-15) << t[k];
    touched = touched || d[k] >= 0.0;
    if (touched && d[k] < dem::laws::jkr_rupture_overlap(p)) broken = true;
    const bool attached = touched && !broken;
    const double expected = attached ? dem::laws::jkr_force(dem::laws::jkr_contact_radius(d[k], p), p) : 0.0;
    ASSERT_NEAR(f[k], expected, 1e-12) << "t = " << t[k] << ", δ = " << d[k];
  }
  EXPECT_TRUE(broken);
}

TEST(AnalyticJkrPulloff, LoadPolicyBreaksAtThePullOffPoint) {
  cases::Scene scene = cases::load_case(kCase);
  scene.model.jkr_rupture = dem::JkrRupture::load;
  const cases::RunResult r = analytic(scene);
  const auto p = benchmark();
  EXPECT_NEAR(r.exact_metrics.at("rupture_separation"), -dem::laws::jkr_pulloff_overlap(p), 1e-18);
  EXPECT_NEAR(r.exact_metrics.at("force_at_rupture"), -dem::laws::jkr_pulloff_force(p), 1e-10);
}

TEST(AnalyticJkrPulloff, ShallowRetractionNeverReachesThePullOffPoint) {
  // Retract only to δ = −2e-5 m (above δ_f): the largest tension is |F(−2e-5)| < F_po and no
  // rupture happens.
  cases::Scene scene = cases::load_case(kCase);
  scene.integration.duration = 0.18 + 1.8e-4 / 1e-3;
  const cases::RunResult r = analytic(scene);
  const auto p = benchmark();
  const double tension = -dem::laws::jkr_force(dem::laws::jkr_contact_radius(-2e-5, p), p);
  EXPECT_NEAR(r.exact_metrics.at("pulloff_force"), tension, 1e-9 * tension);
  EXPECT_LT(tension, dem::laws::jkr_pulloff_force(p));
  EXPECT_EQ(r.exact_metrics.count("rupture_separation"), 0u);
}

TEST(AnalyticJkrPulloff, NeedsTheJkrCohesionWithHertzAndADisplacementControlledRig) {
  cases::Scene scene = cases::load_case(kCase);
  scene.model.normal = "linear";
  EXPECT_FALSE(reference::AnalyticEngine{}.supports(scene).supported());
  scene = cases::load_case(kCase);
  scene.particles[0].fixed = false;
  EXPECT_FALSE(reference::AnalyticEngine{}.supports(scene).supported());
}

TEST(InhouseJkrPulloff, CoreFollowsTheExactCurveThroughPullOffAndRupture) {
  // The core evaluates the JKR law on the prescribed overlap, hysteresis included: its trace is
  // the exact one, so the largest sampled tension and the last attached overlap bracket F_po
  // and δ_c as tightly as the exact trace does.
  const cases::Scene scene = cases::load_case(kCase);
  const cases::RunResult core = reference::run_engine(reference::InhouseEngine{}, scene, {});
  const cases::RunResult exact = analytic(scene);
  ASSERT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  const auto& f = *core.trace.column("c0-1.fn");
  const auto& d = *core.trace.column("c0-1.overlap");
  const auto& f_exact = *exact.trace.column("c0-1.fn");
  ASSERT_EQ(f.size(), f_exact.size());
  double tension = 0.0, last_attached = 0.0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    ASSERT_NEAR(f[k], f_exact[k], 1e-9) << "row " << k;
    tension = std::max(tension, -f[k]);
    if (f[k] != 0.0) last_attached = d[k];
  }
  const auto p = benchmark();
  EXPECT_NEAR(tension, dem::laws::jkr_pulloff_force(p), 1e-3 * dem::laws::jkr_pulloff_force(p));
  EXPECT_NEAR(last_attached, dem::laws::jkr_rupture_overlap(p),
              5e-3 * std::abs(dem::laws::jkr_rupture_overlap(p)));
}

}  // namespace
