// SPDX-License-Identifier: MIT
// The sandwich of thesis fig. 4.15: a sphere always in contact with one of two fixed neighbours.
#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "analytic_scenes.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/analytic/collinear_motion.hpp"
#include "reference/analytic/collinear_scene.hpp"

namespace analytic_sandwich_test {

using demwb_test::at;
using demwb_test::CollisionParameters;
using demwb_test::mobile_mass;
using demwb_test::sandwich;

double angular_frequency(const CollisionParameters& c) {
  return std::sqrt(c.stiffness / mobile_mass(c));
}

TEST(AnalyticSandwich, TraceIsOneHarmonicOscillation) {
  const CollisionParameters c;
  const cases::RunResult r = reference::run_engine(reference::AnalyticEngine{}, sandwich(c), {});
  ASSERT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  const double omega = angular_frequency(c);
  const double amplitude = c.speed / omega;
  ASSERT_GT(r.trace.rows(), 500u);  // more than two periods
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    const double t = at(r.trace, "time", k);
    EXPECT_NEAR(at(r.trace, "p0.x", k), amplitude * std::sin(omega * t), 1e-13 * amplitude)
        << "t = " << t;
    EXPECT_NEAR(at(r.trace, "p0.vx", k), c.speed * std::cos(omega * t), 1e-13 * c.speed)
        << "t = " << t;
  }
}

TEST(AnalyticSandwich, OnlyTheNeighbourOnTheSideOfMotionPushes) {
  const CollisionParameters c;
  const cases::RunResult r = reference::run_engine(reference::AnalyticEngine{}, sandwich(c), {});
  ASSERT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    const double x = at(r.trace, "p0.x", k);
    // Right neighbour (2) overlaps by x, left neighbour (1) by −x.
    EXPECT_NEAR(at(r.trace, "c0-2.overlap", k), x, 1e-18);
    EXPECT_NEAR(at(r.trace, "c0-1.overlap", k), -x, 1e-18);
    EXPECT_TRUE(at(r.trace, "c0-1.fn", k) == 0.0 || at(r.trace, "c0-2.fn", k) == 0.0);
    EXPECT_NEAR(at(r.trace, "p0.fx", k), -c.stiffness * x, 1e-12 * c.stiffness * 1e-3);
  }
}

TEST(AnalyticSandwich, ExactStatesBeforeTheStartContinueTheOscillation) {
  const CollisionParameters c;
  const cases::Scene scene = sandwich(c);
  const double omega = angular_frequency(c);
  const double amplitude = c.speed / omega;
  const std::vector<double> times{-c.timestep, -2.0 * c.timestep, -1e-3};
  const auto states = reference::exact_states(reference::PreparedScene(scene), times);
  ASSERT_EQ(states.size(), times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double t = times[k];
    EXPECT_EQ(states[k].time, t);
    ASSERT_EQ(states[k].position.size(), 3u);
    EXPECT_NEAR(states[k].position[0][0], amplitude * std::sin(omega * t), 1e-13 * amplitude);
    EXPECT_NEAR(states[k].velocity[0][0], c.speed * std::cos(omega * t), 1e-13 * c.speed);
    EXPECT_EQ(states[k].position[1], scene.particles[1].position);
    EXPECT_EQ(states[k].position[2], scene.particles[2].position);
  }
  // Just before t = 0 the sphere is pressed into its LEFT neighbour.
  EXPECT_LT(states[0].position[0][0], 0.0);
}

TEST(AnalyticSandwich, ContactWithTheRightNeighbourIsASingleSpringHalfPeriod) {
  const CollisionParameters c;
  const cases::RunResult r = reference::run_engine(reference::AnalyticEngine{}, sandwich(c), {});
  ASSERT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  const double omega = angular_frequency(c);
  EXPECT_NEAR(r.exact_metrics.at("contact_duration"), std::numbers::pi / omega, 1e-12 / omega);
  EXPECT_NEAR(r.exact_metrics.at("max_overlap"), c.speed / omega, 1e-12 * c.speed / omega);
  EXPECT_NEAR(r.exact_metrics.at("restitution"), 1.0, 1e-12);
  EXPECT_NE(r.conventions.at("exact metrics").find("single spring"), std::string::npos);
}

TEST(AnalyticSandwich, PreloadedSphereOscillatesOnBothSpringsAtOnce) {
  CollisionParameters c;
  c.speed = 0.5;
  cases::Scene scene = sandwich(c);
  const double preload = 1e-3;  // > amplitude u/√(2k/m) ≈ 1.4e-4 m: both contacts hold
  scene.particles[1].position[0] += preload;
  scene.particles[2].position[0] -= preload;
  const double omega = std::sqrt(2.0 * c.stiffness / mobile_mass(c));
  const double amplitude = c.speed / omega;
  const cases::RunResult r = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  ASSERT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    const double t = at(r.trace, "time", k);
    EXPECT_NEAR(at(r.trace, "p0.x", k), amplitude * std::sin(omega * t), 1e-12 * amplitude);
    EXPECT_GT(at(r.trace, "c0-1.fn", k), 0.0);
    EXPECT_GT(at(r.trace, "c0-2.fn", k), 0.0);
  }
  // The compared contact never ends: no exact metrics, and a warning says why.
  EXPECT_TRUE(r.exact_metrics.empty());
  EXPECT_FALSE(r.warnings.empty());
}

/// Independent check of the piecewise solution: classical RK4 with a small step, the set of
/// acting contacts frozen over each step, and steps shortened by bisection to end just past
/// every change of that set (so no step integrates across a force discontinuity).
class EventAwareRk4 {
 public:
  explicit EventAwareRk4(const reference::analytic::AxisProblem& p)
      : p_(p), s_(p.position), v_(p.velocity) {}

  /// Advances to time t_end with steps of at most h.
  void advance_to(double t_end, double h) {
    while (t_ < t_end) {
      const std::vector<int> active = acting(s_, v_);
      const bool last = t_end - t_ <= h;
      double step = last ? t_end - t_ : h;
      auto next = rk4(s_, v_, step, active);
      bool landed = last;
      if (changes(active, next.first)) {
        double lo = 0.0;
        double hi = step;
        for (int k = 0; k < 200; ++k) {
          const double mid = 0.5 * (lo + hi);
          if (mid <= lo || mid >= hi) break;
          (changes(active, rk4(s_, v_, mid, active).first) ? hi : lo) = mid;
        }
        landed = landed && hi == step;
        step = hi;
        next = rk4(s_, v_, step, active);
      }
      std::tie(s_, v_) = next;
      t_ = landed ? t_end : t_ + step;
    }
  }
  [[nodiscard]] double position() const { return s_; }

 private:
  [[nodiscard]] double overlap(std::size_t i, double s, int side) const {
    return p_.partners[i].reach - static_cast<double>(side) * (s - p_.partners[i].position);
  }
  /// Side (±1) of each acting partner, 0 for the others, just after the current instant.
  [[nodiscard]] std::vector<int> acting(double s, double v) const {
    std::vector<int> out(p_.partners.size(), 0);
    for (std::size_t i = 0; i < out.size(); ++i) {
      const int side = s >= p_.partners[i].position ? 1 : -1;
      const double d = overlap(i, s, side);
      if (d > 1e-17 || (d >= -1e-17 && -side * v > 0.0)) out[i] = side;
    }
    return out;
  }
  [[nodiscard]] bool changes(const std::vector<int>& active, double s) const {
    for (std::size_t i = 0; i < active.size(); ++i) {
      const int side = s >= p_.partners[i].position ? 1 : -1;
      const bool touching = overlap(i, s, side) > 0.0;
      if (touching != (active[i] != 0)) return true;
    }
    return false;
  }
  [[nodiscard]] double acceleration(double s, double v, const std::vector<int>& active) const {
    double f = 0.0;
    for (std::size_t i = 0; i < active.size(); ++i) {
      if (active[i] == 0) continue;
      const double n = static_cast<double>(active[i]);
      const auto& q = p_.partners[i];
      f += n * (q.stiffness * overlap(i, s, active[i]) - q.damping * n * v);
    }
    return f / p_.mass;
  }
  [[nodiscard]] std::pair<double, double> rk4(double s, double v, double dt,
                                              const std::vector<int>& active) const {
    const double a1 = acceleration(s, v, active);
    const double s2 = s + 0.5 * dt * v;
    const double v2 = v + 0.5 * dt * a1;
    const double a2 = acceleration(s2, v2, active);
    const double s3 = s + 0.5 * dt * v2;
    const double v3 = v + 0.5 * dt * a2;
    const double a3 = acceleration(s3, v3, active);
    const double s4 = s + dt * v3;
    const double v4 = v + dt * a3;
    const double a4 = acceleration(s4, v4, active);
    return {s + dt / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4),
            v + dt / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4)};
  }

  const reference::analytic::AxisProblem& p_;
  double t_ = 0.0;
  double s_;
  double v_;
};

/// Restitution and preload of a sandwich whose sphere keeps changing between one and two contacts.
struct Alternating {
  double restitution;
  double preload;
};

class AnalyticPiecewiseSolution : public ::testing::TestWithParam<Alternating> {};

TEST_P(AnalyticPiecewiseSolution, AgreesWithEventAwareRk4AcrossManyRegimeChanges) {
  // A lightly preloaded sandwich: the sphere alternates between one and two contacts.
  CollisionParameters c;
  c.restitution = GetParam().restitution;
  cases::Scene scene = sandwich(c);
  scene.particles[1].position[0] += GetParam().preload;
  scene.particles[2].position[0] -= GetParam().preload;
  const auto reduced = reference::analytic::reduce_scene(reference::PreparedScene(scene));
  const double t_end = 3e-3;
  const reference::analytic::AxisSolution exact(reduced.problem, 0.0, t_end);
  std::size_t double_contact_regimes = 0;
  for (const auto& seg : exact.segments()) {
    if (seg.regime.active[0] && seg.regime.active[1]) ++double_contact_regimes;
  }
  EXPECT_GE(double_contact_regimes, 3u);
  EXPECT_GE(exact.segments().size(), 8u);
  EventAwareRk4 fine(reduced.problem);
  const double amplitude = c.speed / angular_frequency(c);
  // RK4's own round-off (velocity increments summed over 1.5e5 steps) is about 1e-14 m here.
  for (int k = 1; k <= 300; ++k) {
    const double t = 1e-5 * k;
    fine.advance_to(t, 2e-8);
    EXPECT_NEAR(exact.at(t).coordinate.position, fine.position(), 5e-11 * amplitude)
        << "t = " << t;
  }
}

INSTANTIATE_TEST_SUITE_P(Sandwiches, AnalyticPiecewiseSolution,
                         ::testing::Values(Alternating{1.0, 2e-4}, Alternating{0.8, 5e-5}));

TEST(AnalyticPiecewiseContact, DampedSandwichContactIsMeasuredPiecewiseWhenSpringsOverlap) {
  CollisionParameters c;
  c.restitution = 0.8;
  cases::Scene scene = sandwich(c);
  scene.particles[1].position[0] += 5e-5;
  scene.particles[2].position[0] -= 5e-5;
  const cases::RunResult r = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  ASSERT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  // Pair (0, 2) is already in contact at t = 0 together with (0, 1).
  ASSERT_TRUE(r.exact_metrics.count("max_overlap"));
  EXPECT_NE(r.conventions.at("exact metrics").find("piecewise"), std::string::npos);
  double sampled = 0.0;
  for (std::size_t k = 0; k < r.trace.rows() && at(r.trace, "c0-2.overlap", k) > 0.0; ++k) {
    sampled = std::max(sampled, at(r.trace, "c0-2.overlap", k));
  }
  EXPECT_LE(sampled, r.exact_metrics.at("max_overlap") * (1 + 1e-15));
  EXPECT_GT(sampled, r.exact_metrics.at("max_overlap") * (1 - 1e-3));
}

}  // namespace
