// SPDX-License-Identifier: MIT
// The analytic linear-cohesion pair (cases/canonical/linear_cohesion_pair.toml): the exact
// piecewise motion satisfies its equations, the closed forms, and the in-house core follows it.
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "dem/particles/particles.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/inhouse/inhouse_engine.hpp"

namespace analytic_linear_cohesion_test {

const std::filesystem::path kCase =
    std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/canonical/linear_cohesion_pair.toml";

constexpr double kStiffness = 1e5, kCohesion = 1e2, kGap = 5e-3;

double mass() { return dem::sphere_mass(8000.0, 0.005); }

cases::RunResult analytic(const cases::Scene& scene) {
  const reference::AnalyticEngine engine;
  EXPECT_TRUE(engine.supports(scene).supported()) << engine.supports(scene).explain();
  const cases::RunResult r = reference::run_engine(engine, scene, {});
  EXPECT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  return r;
}

TEST(AnalyticLinearCohesion, EquilibriumIsTheBalanceOfRepulsionAndCohesion) {
  const cases::RunResult r = analytic(cases::load_case(kCase));
  const double delta_eq = kCohesion * kGap / (kStiffness - kCohesion);
  EXPECT_NEAR(r.exact_metrics.at("equilibrium_overlap"), delta_eq, 1e-20);
  EXPECT_NEAR(r.trace.column("c0-1.overlap")->back(), delta_eq, 1e-15);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(AnalyticLinearCohesion, ApproachIsTheCoshOfTheCohesiveAttraction) {
  // Released at rest with δ̂_0 = Δ/2: δ̂(t) = δ̂_0 cosh(ωt), ω = √(k_c/m), until δ̂ = Δ.
  const cases::RunResult r = analytic(cases::load_case(kCase));
  const double omega = std::sqrt(kCohesion / mass());
  const double t_contact = std::acosh(2.0) / omega;
  const auto& t = *r.trace.column("time");
  const auto& d = *r.trace.column("c0-1.overlap");
  const auto& f = *r.trace.column("c0-1.fn");
  const auto& v = *r.trace.column("p0.vx");
  for (std::size_t k = 0; t[k] < t_contact; ++k) {
    const double effect = 0.5 * kGap * std::cosh(omega * t[k]);
    ASSERT_NEAR(d[k] + kGap, effect, 1e-15) << t[k];
    ASSERT_NEAR(f[k], -kCohesion * effect, 1e-12);
    // Energy: ½ m v² = ½ k_c (δ̂² − δ̂_0²).
    ASSERT_NEAR(0.5 * mass() * v[k] * v[k], 0.5 * kCohesion * (effect * effect - 0.25 * kGap * kGap), 1e-14);
  }
}

TEST(AnalyticLinearCohesion, MotionSatisfiesTheEquationsInEveryRegion) {
  // m δ'' = −F_n along the whole run, checked by central differences of the exact trace.
  cases::Scene scene = cases::load_case(kCase);
  scene.output.trace_every = 1;
  scene.integration.duration = 0.03;
  const cases::RunResult r = analytic(scene);
  const auto& t = *r.trace.column("time");
  const auto& d = *r.trace.column("c0-1.overlap");
  const auto& f = *r.trace.column("c0-1.fn");
  const double h = t[1] - t[0];
  std::size_t checked = 0;
  for (std::size_t k = 1; k + 1 < t.size(); ++k) {
    if ((d[k - 1] > 0.0) != (d[k + 1] > 0.0)) continue;  // the dashpot jumps at δ = 0
    const double acceleration = (d[k + 1] - 2.0 * d[k] + d[k - 1]) / (h * h);
    ASSERT_NEAR(mass() * acceleration, -f[k], 2e-4 * (1.0 + std::abs(f[k]))) << t[k];
    ++checked;
  }
  EXPECT_GT(checked, 29000u);
}

TEST(AnalyticLinearCohesion, InhouseCoreSettlesAtTheExactEquilibrium) {
  const cases::Scene scene = cases::load_case(kCase);
  const cases::RunResult exact = analytic(scene);
  const cases::RunResult core = reference::run_engine(reference::InhouseEngine{}, scene, {});
  ASSERT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  ASSERT_EQ(core.trace.rows(), exact.trace.rows());
  EXPECT_EQ(*core.trace.column("time"), *exact.trace.column("time"));
  EXPECT_NEAR(core.trace.column("c0-1.overlap")->back(), exact.exact_metrics.at("equilibrium_overlap"),
              1e-10 * exact.exact_metrics.at("equilibrium_overlap"));  // a few ulps of x
  // Up to the first contact only cohesion acts (smooth): the core follows to O(Δt²).
  const double t_contact = std::acosh(2.0) / std::sqrt(kCohesion / mass());
  const auto& t = *exact.trace.column("time");
  for (std::size_t k = 0; t[k] < t_contact; ++k) {
    ASSERT_NEAR((*core.trace.column("p0.x"))[k], (*exact.trace.column("p0.x"))[k], 1e-10) << t[k];
  }
}

}  // namespace
