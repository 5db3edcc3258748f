// SPDX-License-Identifier: MIT
// Matched numerics: the in-house core with YADE's leapfrog (given velocities = v(−Δt/2))
// reproduces YADE's traces to round-off on the canonical undamped cases.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "compare/metrics.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/matching.hpp"
#include "yade_test_support.hpp"

namespace yade_matched_test {

using namespace demwb_yade_test;

/// Runs the matched in-house engine and YADE on `scene` and checks every trace column.
void expect_matched_agreement(const cases::Scene& original, const std::string& name, double tolerance) {
  const cases::Scene scene = reference::matched_scene(original, "yade");
  const auto inhouse = reference::run_engine(reference::InhouseEngine{}, scene, {});
  const auto yade = reference::run_engine(reference::YadeEngine{}, scene, {scratch(name), 120.0});
  ASSERT_EQ(inhouse.status, cases::RunStatus::ok) << inhouse.reason;
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  ASSERT_EQ(inhouse.trace.columns(), yade.trace.columns());
  ASSERT_EQ(inhouse.trace.rows(), yade.trace.rows());
  const ColumnScales scales = collision_scales(scene, inhouse);
  for (const auto& [column, diff] : column_differences(inhouse, yade, scales)) {
    std::printf("  %-14s max |inhouse - yade| / scale = %.3g\n", column.c_str(), diff);
    EXPECT_LE(diff, tolerance) << column;
  }
  ASSERT_EQ(inhouse.snapshots.size(), yade.snapshots.size());
  for (std::size_t k = 0; k < yade.snapshots.size(); ++k) {
    EXPECT_NEAR(yade.snapshots[k].time, inhouse.snapshots[k].time, 1e-12 * scales.time);
    for (std::size_t i = 0; i < scene.particles.size(); ++i) {
      for (std::size_t c = 0; c < 3; ++c) {
        EXPECT_NEAR(yade.snapshots[k].position[i][c], inhouse.snapshots[k].position[i][c],
                    tolerance * scales.length);
        EXPECT_NEAR(yade.snapshots[k].velocity[i][c], inhouse.snapshots[k].velocity[i][c],
                    tolerance * scales.speed);
      }
    }
  }
}

TEST(YadeMatched, SingleCollisionAgreesWithLeapfrogCoreToRoundOff) {
  DEMWB_REQUIRE_YADE();
  expect_matched_agreement(canonical("single_collision.toml"), "matched-single", 1e-12);
}

TEST(YadeMatched, SandwichAgreesWithLeapfrogCoreToRoundOff) {
  DEMWB_REQUIRE_YADE();
  expect_matched_agreement(canonical("sandwich.toml"), "matched-sandwich", 1e-12);
}

TEST(YadeMatched, GravitySparseTraceAndRotationAgreeToRoundOff) {
  // Gravity across the collision axis makes the contact oblique; rotation is integrated (no
  // torque: frictionless); every 7th step is traced, so the PyRunner's period is exercised.
  DEMWB_REQUIRE_YADE();
  cases::Scene scene = canonical("single_collision.toml");
  scene.gravity = {0.0, -9.81, 2.0};
  scene.integration.rotation = true;
  scene.output.trace_every = 7;
  scene.output.trace_particles = {0, 1};
  expect_matched_agreement(scene, "matched-gravity", 1e-12);
}

TEST(YadeMatched, AContactPresentAtTheStartGetsYadesFirstStepOfSlip) {
  // sliding_block starts on the floor: YADE's iteration 0 integrates the shear increment over Δt
  // and applies the capped friction at once; the matched core commits its t = 0 forces with Δt
  // elapsed for given_is_half_step. Row 0's friction and the deceleration then agree to round-off
  // (before, the core trailed YADE by one step: 2.9e-7 in deceleration). The stick phase still
  // differs by YADE's α = 2r/(2r − δ) on the shear increment (docs/engines.md), so the trace is
  // not compared here.
  DEMWB_REQUIRE_YADE();
  cases::Scene scene = reference::matched_scene(canonical("sliding_block.toml"), "yade");
  scene.compare.metrics = {"deceleration"};
  const auto inhouse = reference::run_engine(reference::InhouseEngine{}, scene, {});
  const auto yade = reference::run_engine(reference::YadeEngine{}, scene, {scratch("matched-slide"), 120.0});
  ASSERT_EQ(inhouse.status, cases::RunStatus::ok) << inhouse.reason;
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  const double f_yade = yade.trace.column("p0.fx")->front();
  const double f_core = inhouse.trace.column("p0.fx")->front();
  EXPECT_LT(f_yade, 0.0);  // friction acts from the first row
  EXPECT_NEAR(f_core, f_yade, 1e-14 * std::abs(f_yade));
  const auto a = comparison::compute_metrics(scene, inhouse, nullptr).at("deceleration");
  const auto b = comparison::compute_metrics(scene, yade, nullptr).at("deceleration");
  ASSERT_TRUE(a.value && b.value) << a.problem << b.problem;
  EXPECT_NEAR(*a.value, *b.value, 1e-12 * *b.value);
  // The default start (half_kick) keeps t = 0 history-free: no friction in row 0.
  cases::Scene plain = scene;
  plain.integration.leapfrog_start = dem::LeapfrogStart::half_kick;
  EXPECT_EQ(reference::run_engine(reference::InhouseEngine{}, plain, {}).trace.column("p0.fx")->front(), 0.0);
}

}  // namespace
