// SPDX-License-Identifier: MIT
// The single collision with a restitution dashpot (thesis eq 3.10–3.11) against closed forms.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "analytic_scenes.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/analytic/collinear_scene.hpp"
#include "reference/analytic/contact_episode.hpp"

namespace analytic_damped_collision_test {

using demwb_test::at;
using demwb_test::CollisionParameters;
using demwb_test::mobile_mass;
using demwb_test::single_collision;

class AnalyticDampedCollision : public ::testing::TestWithParam<double> {
 protected:
  [[nodiscard]] CollisionParameters parameters() const {
    CollisionParameters c;
    c.restitution = GetParam();
    return c;
  }
  [[nodiscard]] cases::RunResult run() const {
    const reference::AnalyticEngine engine;
    const cases::RunResult r = reference::run_engine(engine, single_collision(parameters()), {});
    EXPECT_EQ(r.status, cases::RunStatus::ok) << r.reason;
    return r;
  }
  [[nodiscard]] double dashpot() const {
    const CollisionParameters c = parameters();
    return dem::laws::restitution_damping_coefficient(*c.restitution, mobile_mass(c), c.stiffness);
  }
};

TEST_P(AnalyticDampedCollision, RestitutionEqualsEpsilon) {
  EXPECT_NEAR(run().exact_metrics.at("restitution"), GetParam(), 1e-10);
}

TEST_P(AnalyticDampedCollision, ReboundSpeedInTheTraceIsEpsilonTimesApproachSpeed) {
  const cases::RunResult r = run();
  const double speed = parameters().speed;
  EXPECT_NEAR(at(r.trace, "p0.vx", r.trace.rows() - 1), -GetParam() * speed, 1e-10 * speed);
}

TEST_P(AnalyticDampedCollision, DurationIsTheLinearContactDuration) {
  const CollisionParameters c = parameters();
  const double expected = dem::laws::linear_contact_duration(c.stiffness, mobile_mass(c), dashpot());
  EXPECT_NEAR(run().exact_metrics.at("contact_duration"), expected, 1e-12 * expected);
  // The located regime changes give the same duration.
  const cases::Scene scene = single_collision(c);
  const auto reduced = reference::analytic::reduce_scene(reference::PreparedScene(scene));
  const auto episode = reference::analytic::first_contact(reduced.problem, 0, 1.0, 1.0);
  ASSERT_TRUE(episode.has_value());
  EXPECT_NEAR(episode->end - episode->start, expected, 1e-12 * expected);
}

TEST_P(AnalyticDampedCollision, ClosedFormsAgreeWithThePiecewiseSolution) {
  const cases::Scene scene = single_collision(parameters());
  const auto reduced = reference::analytic::reduce_scene(reference::PreparedScene(scene));
  auto episode = reference::analytic::first_contact(reduced.problem, 0, 1.0, 1.0);
  ASSERT_TRUE(episode.has_value());
  const auto closed = reference::analytic::contact_figures(reduced.problem, *episode);
  episode->single_spring = false;
  const auto measured = reference::analytic::contact_figures(reduced.problem, *episode);
  EXPECT_NEAR(*measured.restitution, *closed.restitution, 1e-12);
  EXPECT_NEAR(measured.max_overlap, closed.max_overlap, 1e-13 * closed.max_overlap);
  EXPECT_NEAR(measured.max_force, closed.max_force, 1e-13 * closed.max_force);
}

TEST_P(AnalyticDampedCollision, PeaksBoundEverySampleAndAreApproachedByThem) {
  const cases::RunResult r = run();
  const double max_overlap = r.exact_metrics.at("max_overlap");
  const double max_force = r.exact_metrics.at("max_force");
  double sampled_overlap = 0.0;
  double sampled_force = 0.0;
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    sampled_overlap = std::max(sampled_overlap, at(r.trace, "c0-1.overlap", k));
    sampled_force = std::max(sampled_force, at(r.trace, "c0-1.fn", k));
  }
  EXPECT_LE(sampled_overlap, max_overlap * (1 + 1e-15));
  EXPECT_LE(sampled_force, max_force * (1 + 1e-15));
  EXPECT_GT(sampled_overlap, max_overlap * (1 - 1e-3));
  EXPECT_GT(sampled_force, max_force * (1 - 1e-2));
}

TEST_P(AnalyticDampedCollision, EnergyNeverRises) {
  const CollisionParameters c = parameters();
  const cases::RunResult r = run();
  const double m = mobile_mass(c);
  double previous = 0.5 * m * c.speed * c.speed;
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    const double v = at(r.trace, "p0.vx", k);
    const double overlap = std::max(0.0, at(r.trace, "c0-1.overlap", k));
    const double energy = 0.5 * m * v * v + 0.5 * c.stiffness * overlap * overlap;
    EXPECT_LE(energy, previous * (1 + 1e-14)) << "row " << k;
    previous = energy;
  }
}

TEST_P(AnalyticDampedCollision, NormalForceIsSpringPlusDashpot) {
  const cases::RunResult r = run();
  const double k = parameters().stiffness;
  const double eta = dashpot();
  for (std::size_t row = 0; row < r.trace.rows(); ++row) {
    const double overlap = at(r.trace, "c0-1.overlap", row);
    if (overlap <= 0.0) {
      EXPECT_EQ(at(r.trace, "c0-1.fn", row), 0.0);
      continue;
    }
    // dδ/dt = −(u_c·n) = v_x for p moving towards q on +x.
    const double expected = k * overlap + eta * at(r.trace, "p0.vx", row);
    EXPECT_NEAR(at(r.trace, "c0-1.fn", row), expected, 1e-12 * k * 1e-3);
  }
}

INSTANTIATE_TEST_SUITE_P(Restitutions, AnalyticDampedCollision,
                         ::testing::Values(0.3, 0.5, 0.8, 0.95));

}  // namespace
