// SPDX-License-Identifier: MIT
// Two mobile spheres colliding head-on: relative coordinate with m*, uniform centre of mass.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "analytic_scenes.hpp"
#include "dem/particles/particles.hpp"
#include "reference/analytic/analytic_engine.hpp"

namespace analytic_head_on_test {

using demwb_test::at;
using demwb_test::head_on;

constexpr double kRadiusA = 0.01;
constexpr double kRadiusB = 0.015;

double mass(double radius) { return dem::sphere_mass(1000.0, radius); }

cases::RunResult run(const cases::Scene& scene) {
  const cases::RunResult r = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  EXPECT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  return r;
}

TEST(AnalyticHeadOn, MomentumIsConserved) {
  const cases::RunResult r = run(head_on(kRadiusA, kRadiusB, 3.0, -1.0, 2e-4, 0.7));
  const double m_a = mass(kRadiusA);
  const double m_b = mass(kRadiusB);
  const double initial = m_a * 3.0 + m_b * -1.0;
  const double scale = m_a * 3.0;
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    EXPECT_NEAR(m_a * at(r.trace, "p0.vx", k) + m_b * at(r.trace, "p1.vx", k), initial,
                1e-14 * scale)
        << "row " << k;
    // Action and reaction.
    EXPECT_EQ(at(r.trace, "p0.fx", k), -at(r.trace, "p1.fx", k));
  }
  // The collision did happen: both velocities changed.
  EXPECT_LT(at(r.trace, "p0.vx", r.trace.rows() - 1), 3.0 - 1.0);
}

TEST(AnalyticHeadOn, CentreOfMassMovesUniformly) {
  const cases::RunResult r = run(head_on(kRadiusA, kRadiusB, 3.0, -1.0, 2e-4, 0.7));
  const double m_a = mass(kRadiusA);
  const double m_b = mass(kRadiusB);
  const double total = m_a + m_b;
  const double x0 = m_b * (kRadiusA + kRadiusB + 2e-4) / total;
  const double v = (m_a * 3.0 - m_b * 1.0) / total;
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    const double t = at(r.trace, "time", k);
    const double com = (m_a * at(r.trace, "p0.x", k) + m_b * at(r.trace, "p1.x", k)) / total;
    EXPECT_NEAR(com, x0 + v * t, 1e-16) << "t = " << t;
  }
}

TEST(AnalyticHeadOn, RelativeMotionIsTheFixedPartnerCaseWithReducedMass) {
  const double gap = 2e-4;
  const double restitution = 0.7;
  const cases::RunResult two = run(head_on(kRadiusA, kRadiusB, 3.0, -1.0, gap, restitution));

  // One sphere of mass m* = m_a m_b/(m_a + m_b) at 4 m/s against a fixed sphere, same reach.
  const double m_a = mass(kRadiusA);
  const double m_b = mass(kRadiusB);
  const double reduced = m_a * m_b / (m_a + m_b);
  cases::Scene fixed = head_on(kRadiusA, kRadiusB, 4.0, 0.0, gap, restitution);
  fixed.materials[0].density = reduced / (4.0 / 3.0 * std::numbers::pi * std::pow(kRadiusA, 3));
  fixed.particles[1].fixed = true;
  const cases::RunResult one = run(fixed);

  ASSERT_EQ(one.trace.rows(), two.trace.rows());
  for (std::size_t k = 0; k < one.trace.rows(); ++k) {
    const double separation_two = at(two.trace, "p1.x", k) - at(two.trace, "p0.x", k);
    const double separation_one = at(one.trace, "p1.x", k) - at(one.trace, "p0.x", k);
    EXPECT_NEAR(separation_two, separation_one, 1e-15) << "row " << k;
    EXPECT_NEAR(at(two.trace, "c0-1.overlap", k), at(one.trace, "c0-1.overlap", k), 1e-15);
    EXPECT_NEAR(at(two.trace, "c0-1.fn", k), at(one.trace, "c0-1.fn", k), 1e-9);
  }
  for (const char* metric : {"contact_duration", "restitution", "max_overlap", "max_force"}) {
    EXPECT_NEAR(two.exact_metrics.at(metric), one.exact_metrics.at(metric),
                1e-12 * std::abs(one.exact_metrics.at(metric)))
        << metric;
  }
  EXPECT_NEAR(two.exact_metrics.at("restitution"), restitution, 1e-10);
}

TEST(AnalyticHeadOn, BothSpheresKeepTheirSidewaysDriftIn3D) {
  // Head-on along the diagonal (1, 1, 0)/√2 while both drift along z at 0.5 m/s.
  cases::Scene scene = head_on(kRadiusA, kRadiusA, 0.0, 0.0, 2e-4, std::nullopt);
  const double reach = 2.0 * kRadiusA + 2e-4;
  const double c = 1.0 / std::sqrt(2.0);
  scene.particles[1].position = {reach * c, reach * c, 0.0};
  scene.particles[0].velocity = {2.0 * c, 2.0 * c, 0.5};
  scene.particles[1].velocity = {-2.0 * c, -2.0 * c, 0.5};
  const cases::RunResult r = run(scene);
  bool touched = false;
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    const double t = at(r.trace, "time", k);
    EXPECT_NEAR(at(r.trace, "p0.z", k), 0.5 * t, 1e-16);
    EXPECT_NEAR(at(r.trace, "p1.z", k), 0.5 * t, 1e-16);
    EXPECT_NEAR(at(r.trace, "p0.x", k), at(r.trace, "p0.y", k), 1e-16);
    touched = touched || at(r.trace, "c0-1.fn", k) > 0.0;
  }
  EXPECT_TRUE(touched);
  // Equal spheres, elastic: they swap velocities along the line of centres.
  const std::size_t last = r.trace.rows() - 1;
  EXPECT_NEAR(at(r.trace, "p0.vx", last), -2.0 * c, 1e-12);
  EXPECT_NEAR(at(r.trace, "p1.vx", last), 2.0 * c, 1e-12);
}

}  // namespace
