// SPDX-License-Identifier: MIT
// Matched numerics: the in-house core with YADE's leapfrog (given velocities = v(−Δt/2))
// reproduces YADE's traces to round-off on the canonical undamped cases.
#include <cstdio>

#include <gtest/gtest.h>

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

}  // namespace
