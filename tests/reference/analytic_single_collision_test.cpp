// SPDX-License-Identifier: MIT
// The single elastic collision of thesis §4.3 (table 4.2) against its closed forms.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "analytic_scenes.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/analytic/collinear_motion.hpp"
#include "reference/analytic/collinear_scene.hpp"
#include "reference/analytic/contact_episode.hpp"

namespace analytic_single_collision_test {

using demwb_test::at;
using demwb_test::CollisionParameters;
using demwb_test::mobile_mass;
using demwb_test::single_collision;

cases::RunResult run_analytic(const cases::Scene& scene) {
  const reference::AnalyticEngine engine;
  const cases::RunResult r = reference::run_engine(engine, scene, {});
  EXPECT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  return r;
}

TEST(AnalyticCollision, UndampedContactDurationIsPiTimesSqrtMassOverStiffness) {
  const CollisionParameters c;
  const cases::RunResult r = run_analytic(single_collision(c));
  const double expected = std::numbers::pi * std::sqrt(mobile_mass(c) / c.stiffness);
  EXPECT_NEAR(r.exact_metrics.at("contact_duration"), expected, 1e-12 * expected);
}

TEST(AnalyticCollision, UndampedMaxOverlapIsSpeedTimesSqrtMassOverStiffness) {
  const CollisionParameters c;
  const cases::RunResult r = run_analytic(single_collision(c));
  const double expected = c.speed * std::sqrt(mobile_mass(c) / c.stiffness);
  EXPECT_NEAR(r.exact_metrics.at("max_overlap"), expected, 1e-12 * expected);
}

TEST(AnalyticCollision, UndampedRestitutionIsOne) {
  const cases::RunResult r = run_analytic(single_collision());
  EXPECT_NEAR(r.exact_metrics.at("restitution"), 1.0, 1e-12);
}

TEST(AnalyticCollision, UndampedMaxForceIsStiffnessTimesMaxOverlap) {
  const CollisionParameters c;
  const cases::RunResult r = run_analytic(single_collision(c));
  const double expected = c.stiffness * c.speed * std::sqrt(mobile_mass(c) / c.stiffness);
  EXPECT_NEAR(r.exact_metrics.at("max_force"), expected, 1e-12 * expected);
}

TEST(AnalyticCollision, FreeFlightPositionIsSpeedTimesTime) {
  const CollisionParameters c;
  const cases::RunResult r = run_analytic(single_collision(c));
  const double contact_start = c.free_motion_steps * c.timestep;
  std::size_t checked = 0;
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    const double t = at(r.trace, "time", k);
    if (t >= contact_start) break;
    EXPECT_NEAR(at(r.trace, "p0.x", k), c.speed * t, 1e-15) << "t = " << t;
    EXPECT_EQ(at(r.trace, "p0.vx", k), c.speed);
    EXPECT_EQ(at(r.trace, "p0.fx", k), 0.0);
    ++checked;
  }
  EXPECT_EQ(checked, 10u);  // samples 0 … N_FM − 1
}

TEST(AnalyticCollision, EnergyIsConservedAlongTheTrace) {
  const CollisionParameters c;
  const cases::RunResult r = run_analytic(single_collision(c));
  const double m = mobile_mass(c);
  const double initial = 0.5 * m * c.speed * c.speed;
  double largest_spring_energy = 0.0;
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    const double v = at(r.trace, "p0.vx", k);
    const double overlap = std::max(0.0, at(r.trace, "c0-1.overlap", k));
    const double spring = 0.5 * c.stiffness * overlap * overlap;
    largest_spring_energy = std::max(largest_spring_energy, spring);
    EXPECT_NEAR(0.5 * m * v * v + spring, initial, 1e-13 * initial) << "row " << k;
  }
  EXPECT_GT(largest_spring_energy, 0.99 * initial);  // the trace does pass through the contact
}

TEST(AnalyticCollision, ParticleReturnsWithReversedVelocityAfterContact) {
  const CollisionParameters c;
  const cases::RunResult r = run_analytic(single_collision(c));
  const std::size_t last = r.trace.rows() - 1;
  const double t = at(r.trace, "time", last);
  const double t_contact = std::numbers::pi * std::sqrt(mobile_mass(c) / c.stiffness);
  const double t_end = c.free_motion_steps * c.timestep + t_contact;
  ASSERT_GT(t, t_end);
  EXPECT_NEAR(at(r.trace, "p0.vx", last), -c.speed, 1e-12 * c.speed);
  // Leaves the contact where it entered, then flies back at −u.
  const double entry = c.speed * c.free_motion_steps * c.timestep;
  EXPECT_NEAR(at(r.trace, "p0.x", last), entry - c.speed * (t - t_end), 1e-15);
  EXPECT_EQ(at(r.trace, "c0-1.fn", last), 0.0);
  EXPECT_LT(at(r.trace, "c0-1.overlap", last), 0.0);
}

TEST(AnalyticCollision, FixedSphereReceivesTheOppositeForceAndStaysPut) {
  const CollisionParameters c;
  const cases::Scene scene = single_collision(c);
  const cases::RunResult r = run_analytic(scene);
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    EXPECT_EQ(at(r.trace, "p1.fx", k), -at(r.trace, "p0.fx", k));
    EXPECT_EQ(at(r.trace, "p1.x", k), scene.particles[1].position[0]);
    EXPECT_EQ(at(r.trace, "p1.vx", k), 0.0);
    // The normal force is repulsive: it pushes p back (−x) while the contact lasts.
    EXPECT_EQ(at(r.trace, "p0.fx", k), -at(r.trace, "c0-1.fn", k));
  }
}

TEST(AnalyticCollision, TraceUsesTheInhouseColumnsAndSampleTimes) {
  CollisionParameters c;
  cases::Scene scene = single_collision(c);
  scene.output.trace_every = 3;
  const cases::RunResult r = run_analytic(scene);
  const std::vector<std::string> expected_first{"time", "p0.x", "p0.y", "p0.z", "p0.vx",
                                                "p0.vy", "p0.vz", "p0.wx", "p0.wy", "p0.wz",
                                                "p0.fx", "p0.fy", "p0.fz"};
  ASSERT_EQ(r.trace.columns().size(), 1u + 2u * 12u + 2u);
  for (std::size_t i = 0; i < expected_first.size(); ++i) {
    EXPECT_EQ(r.trace.columns()[i], expected_first[i]);
  }
  EXPECT_EQ(r.trace.columns()[25], "c0-1.overlap");
  EXPECT_EQ(r.trace.columns()[26], "c0-1.fn");
  const std::size_t steps = 160;  // 8e-4 s / 5e-6 s
  ASSERT_EQ(r.trace.rows(), steps / 3 + 1);
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    EXPECT_EQ(at(r.trace, "time", k), static_cast<double>(3 * k) * c.timestep);
  }
  EXPECT_EQ(r.version, "closed-form 1");
  EXPECT_FALSE(r.conventions.at("solution").empty());
  EXPECT_FALSE(r.conventions.at("sampling").empty());
}

TEST(AnalyticCollision, ContactStartBetweenSamplesIsGapOverSpeed) {
  CollisionParameters c;
  c.free_motion_steps = 10.5;
  const cases::Scene scene = single_collision(c);
  const auto reduced = reference::analytic::reduce_scene(reference::PreparedScene(scene));
  const auto episode = reference::analytic::first_contact(reduced.problem, 0, 1.0, 1.0);
  ASSERT_TRUE(episode.has_value());
  const double gap = scene.particles[1].position[0] - (c.radius_p + c.radius_q);
  const double expected = gap / c.speed;
  EXPECT_NEAR(episode->start, expected, 1e-14 * expected);
  EXPECT_NEAR(episode->start, 10.5 * c.timestep, 1e-12 * expected);
  const double t_c = std::numbers::pi * std::sqrt(mobile_mass(c) / c.stiffness);
  EXPECT_NEAR(episode->end - episode->start, t_c, 1e-12 * t_c);
  EXPECT_TRUE(episode->single_spring);

  // The samples straddle the start: overlap negative at 10 Δt, positive at 11 Δt.
  const cases::RunResult r = run_analytic(scene);
  EXPECT_LT(at(r.trace, "c0-1.overlap", 10), 0.0);
  EXPECT_EQ(at(r.trace, "c0-1.fn", 10), 0.0);
  EXPECT_NEAR(at(r.trace, "c0-1.overlap", 11),
              c.speed / std::sqrt(c.stiffness / mobile_mass(c)) *
                  std::sin(std::sqrt(c.stiffness / mobile_mass(c)) * 0.5 * c.timestep),
              1e-17);
}

TEST(AnalyticCollision, PiecewiseMeasureAgreesWithClosedForms) {
  const CollisionParameters c;
  const cases::Scene scene = single_collision(c);
  const auto reduced = reference::analytic::reduce_scene(reference::PreparedScene(scene));
  auto episode = reference::analytic::first_contact(reduced.problem, 0, 1.0, 1.0);
  ASSERT_TRUE(episode.has_value());
  const auto closed = reference::analytic::contact_figures(reduced.problem, *episode);
  episode->single_spring = false;
  const auto measured = reference::analytic::contact_figures(reduced.problem, *episode);
  EXPECT_TRUE(closed.closed_form);
  EXPECT_FALSE(measured.closed_form);
  EXPECT_NEAR(measured.duration, closed.duration, 1e-13 * closed.duration);
  EXPECT_NEAR(*measured.restitution, *closed.restitution, 1e-13);
  EXPECT_NEAR(measured.max_overlap, closed.max_overlap, 1e-14 * closed.max_overlap);
  EXPECT_NEAR(measured.max_force, closed.max_force, 1e-14 * closed.max_force);
}

TEST(AnalyticCollision, LineOfMotionNeedNotBeACoordinateAxis) {
  const CollisionParameters c;
  const cases::Scene straight = single_collision(c);
  cases::Scene oblique = straight;
  // Same collision along e = (2, 1, 2)/3; rounding of e stays far inside the 1e-12 collinearity.
  const double e[3] = {2.0 / 3.0, 1.0 / 3.0, 2.0 / 3.0};
  const double x_q = straight.particles[1].position[0];
  for (std::size_t k = 0; k < 3; ++k) {
    oblique.particles[0].velocity[k] = c.speed * e[k];
    oblique.particles[1].position[k] = x_q * e[k];
  }
  const cases::RunResult a = run_analytic(straight);
  const cases::RunResult b = run_analytic(oblique);
  for (const char* metric : {"contact_duration", "restitution", "max_overlap", "max_force"}) {
    EXPECT_NEAR(b.exact_metrics.at(metric), a.exact_metrics.at(metric),
                1e-12 * std::abs(a.exact_metrics.at(metric)))
        << metric;
  }
  for (std::size_t k = 0; k < a.trace.rows(); ++k) {
    const double s = at(a.trace, "p0.x", k);
    EXPECT_NEAR(at(b.trace, "p0.y", k), s / 3.0, 1e-15);
    EXPECT_NEAR(at(b.trace, "c0-1.overlap", k), at(a.trace, "c0-1.overlap", k), 1e-15);
    EXPECT_NEAR(at(b.trace, "p0.fz", k), at(a.trace, "p0.fx", k) * 2.0 / 3.0,
                1e-12 * c.stiffness * 1e-3);
  }
}

TEST(AnalyticCollision, FastSphereTunnelsThroughTheCentreAndLeavesAtFullSpeed) {
  // ½ m u² > ½ k (r_p + r_q)²: the sphere reaches q's centre, where the normal flips (thesis
  // §4.4: "instantaneous switch of normal direction"), and is pushed out on the far side.
  CollisionParameters c;
  c.speed = 600.0;
  const cases::Scene scene = single_collision(c);
  const double m = mobile_mass(c);
  const double reach = c.radius_p + c.radius_q;
  const auto reduced = reference::analytic::reduce_scene(reference::PreparedScene(scene));
  const reference::analytic::AxisSolution solution(reduced.problem, 0.0, 8e-4);
  const auto& segments = solution.segments();
  ASSERT_EQ(segments.size(), 4u);  // flight, near side, far side, flight
  EXPECT_EQ(segments[1].regime.side[0], -1);
  EXPECT_EQ(segments[2].regime.side[0], 1);
  const double t_centre = segments[1].end;
  const auto centre = solution.at(t_centre);
  EXPECT_NEAR(centre.coordinate.position, scene.particles[1].position[0], 1e-15);
  const double speed_at_centre = std::sqrt(c.speed * c.speed - c.stiffness / m * reach * reach);
  EXPECT_NEAR(centre.coordinate.velocity, speed_at_centre, 1e-12 * c.speed);
  // Symmetric passage: out as long after the centre as in before it, at full speed.
  EXPECT_NEAR(segments[2].end - t_centre, t_centre - segments[1].begin, 1e-15);
  EXPECT_NEAR(solution.at(8e-4).coordinate.velocity, c.speed, 1e-12 * c.speed);

  const cases::RunResult r = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  ASSERT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  EXPECT_NE(r.conventions.at("exact metrics").find("piecewise"), std::string::npos);
  EXPECT_NEAR(r.exact_metrics.at("max_overlap"), reach, 1e-15);
  EXPECT_NEAR(r.exact_metrics.at("max_force"), c.stiffness * reach, 1e-9);
  EXPECT_NEAR(r.exact_metrics.at("contact_duration"), segments[2].end - segments[1].begin, 1e-18);
}

}  // namespace
