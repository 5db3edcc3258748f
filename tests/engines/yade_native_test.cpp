// SPDX-License-Identifier: MIT
// YADE's own numerics (native comparison) against the closed forms.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "compare/case_outcome.hpp"
#include "dem/particles/particles.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "yade_test_support.hpp"

namespace yade_native_test {

using namespace demwb_yade_test;

TEST(YadeNative, SingleCollisionMeetsTheCaseTolerancesAgainstAnalytic) {
  DEMWB_REQUIRE_YADE();
  const cases::Scene scene = canonical("single_collision.toml");
  auto analytic = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  auto yade = reference::run_engine(reference::YadeEngine{}, scene, {scratch("native-single"), 120.0});
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  EXPECT_EQ(yade.version, "YADE 2023.02a");
  EXPECT_NE(yade.conventions.at("global damping").find("NewtonIntegrator(damping=0)"), std::string::npos);
  ASSERT_EQ(yade.snapshots.size(), 3u);
  const auto outcome = comparison::evaluate_runs(scene, {analytic, yade});
  ASSERT_FALSE(outcome.comparisons.empty());
  for (const auto& c : outcome.comparisons) {
    EXPECT_EQ(c.status, comparison::Status::pass) << c.metric << ": " << c.note;
  }
}

TEST(YadeNative, FreeFallFromTheHalfStepStartIsExact) {
  // With v(−Δt/2) = v(0) − Δt/2·g the leapfrog gives x_n = x_0 + v_0 t_n + g t_n²/2 exactly.
  DEMWB_REQUIRE_YADE();
  cases::Scene scene = canonical("single_collision.toml");
  scene.particles[1].position = {1.0, 0.0, 0.0};  // out of reach
  scene.gravity = {0.0, -9.81, 3.0};
  scene.particles[0].velocity = {0.5, 2.0, 0.0};
  const auto yade = reference::run_engine(reference::YadeEngine{}, scene, {scratch("free-fall"), 120.0});
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  const auto& t = *yade.trace.column("time");
  const auto& y = *yade.trace.column("p0.y");
  const auto& z = *yade.trace.column("p0.z");
  const auto& fy = *yade.trace.column("p0.fy");
  for (std::size_t r = 0; r < t.size(); ++r) {
    EXPECT_NEAR(y[r], 2.0 * t[r] - 0.5 * 9.81 * t[r] * t[r], 1e-15) << "row " << r;
    EXPECT_NEAR(z[r], 0.5 * 3.0 * t[r] * t[r], 1e-15) << "row " << r;
    EXPECT_EQ(fy[r], dem::sphere_mass(1000.0, 0.01) * -9.81);  // m g, the only force
  }
}

}  // namespace
