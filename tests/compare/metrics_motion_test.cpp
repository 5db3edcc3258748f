// SPDX-License-Identifier: MIT
// Motion metrics (tangential restitution, rebound angle, spin after, end states, tangential force
// max, deceleration) on synthetic traces whose values are known by construction; problems
// instead of NaN.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "compare/metrics.hpp"
#include "compare/metrics_motion.hpp"

namespace metrics_motion_test {

constexpr double kRadius = 0.01;

/// A sphere (particle 0) and a floor (wall 0, normal +z), the compared wall contact.
cases::Scene floor_scene(std::vector<std::string> metrics) {
  cases::Scene s;
  s.name = "synthetic_floor";
  s.particles.resize(1);
  s.particles[0].radius = kRadius;
  s.walls.push_back(cases::WallSpec{"floor", {0, 0, 0}, {0, 0, 1}, {0, 0, 0}, 0});
  s.compare.subject = 0;
  s.compare.wall_contact = cases::ParticlePair{0, 0};
  s.compare.metrics = std::move(metrics);
  return s;
}

/// Trace columns of particle 0 and the wall contact (0, 0).
cases::Trace floor_trace_layout() {
  cases::Trace tr;
  tr.add_column("time");
  for (const auto q : cases::kParticleQuantities) tr.add_column(cases::particle_column(0, q));
  tr.add_column(cases::wall_column(0, 0, "overlap"));
  tr.add_column(cases::wall_column(0, 0, "fn"));
  return tr;
}

/// Free flight in, 10 rows of contact, free flight out with the given velocities and spin.
cases::Trace impact_trace(const std::array<double, 3>& v_in, const std::array<double, 3>& w_in,
                          const std::array<double, 3>& v_out, const std::array<double, 3>& w_out) {
  cases::Trace tr = floor_trace_layout();
  for (int k = 0; k < 30; ++k) {
    const bool before = k < 10, after = k >= 20;
    const auto& v = before ? v_in : v_out;
    const auto& w = before ? w_in : w_out;
    const double overlap = before ? -1e-4 * (10 - k) : after ? -1e-4 * (k - 19) : 1e-5;
    tr.append_row({1e-5 * k, 0, 0, kRadius - overlap, v[0], v[1], v[2], w[0], w[1], w[2], 0, 0, 0,
                   overlap, overlap > 0 ? 1.0 : 0.0});
  }
  return tr;
}

TEST(TangentialRestitution, IsMinusOneWithoutFrictionAndZeroWhenRollingAfter) {
  const cases::Scene scene = floor_scene({});
  const auto smooth = comparison::motion::tangential_restitution(
      scene, impact_trace({2, 0, -1}, {0, 0, 0}, {2, 0, 1}, {0, 0, 0}));
  ASSERT_TRUE(smooth.value) << smooth.problem;
  EXPECT_DOUBLE_EQ(*smooth.value, -1.0);
  // Rolling after: v_x = r ω_y at the contact point (a_p = −r n).
  const auto rolling = comparison::motion::tangential_restitution(
      scene, impact_trace({2, 0, -1}, {0, 0, 0}, {1.5, 0, 1}, {0, 150.0, 0}));
  ASSERT_TRUE(rolling.value);
  EXPECT_NEAR(*rolling.value, 0.0, 1e-12);
}

TEST(TangentialRestitution, UsesTheContactPointVelocityIncludingSpin) {
  // Incoming backspin adds to the slip: u_before = 2 + r·100 = 3; after u = 1 − r·50 = 0.5.
  const auto e_t = comparison::motion::tangential_restitution(
      floor_scene({}), impact_trace({2, 0, -1}, {0, -100.0, 0}, {1, 0, 1}, {0, 50.0, 0}));
  ASSERT_TRUE(e_t.value) << e_t.problem;
  EXPECT_NEAR(*e_t.value, -0.5 / 3.0, 1e-12);
}

TEST(ReboundAngle, IsTheAngleToTheNormalInDegrees) {
  const auto a = comparison::motion::rebound_angle(
      floor_scene({}), impact_trace({2, 0, -1}, {0, 0, 0}, {1, 0, 1}, {0, 0, 0}));
  ASSERT_TRUE(a.value);
  EXPECT_NEAR(*a.value, 45.0, 1e-12);
}

TEST(SpinAfter, IsPositiveForTheSpinSlidingFrictionImparts) {
  // Sliding along +x on a floor: friction spins the sphere about +y = x̂ × (−ẑ).
  const auto w = comparison::motion::spin_after(
      floor_scene({}), impact_trace({2, 0, -1}, {0, 0, 0}, {1.5, 0, 1}, {0, 123.0, 4.0}));
  ASSERT_TRUE(w.value) << w.problem;
  EXPECT_DOUBLE_EQ(*w.value, 123.0);
}

TEST(MotionMetrics, NormalImpactGivesAProblemNotNaN) {
  const cases::Scene scene = floor_scene({"tangential_restitution", "spin_after"});
  const cases::Trace tr = impact_trace({0, 0, -1}, {0, 0, 0}, {0, 0, 1}, {0, 0, 0});
  const auto e_t = comparison::motion::tangential_restitution(scene, tr);
  EXPECT_FALSE(e_t.value);
  EXPECT_NE(e_t.problem.find("normal impact"), std::string::npos);
  cases::RunResult run;
  run.status = cases::RunStatus::ok;
  run.trace = tr;
  const comparison::MetricSet m = comparison::compute_metrics(scene, run, nullptr);
  EXPECT_FALSE(m.at("spin_after").value);
  EXPECT_FALSE(m.at("spin_after").problem.empty());
}

TEST(MotionMetrics, AreDispatchedByComputeMetrics) {
  const cases::Scene scene = floor_scene({"tangential_restitution", "rebound_angle", "spin_after"});
  cases::RunResult run;
  run.status = cases::RunStatus::ok;
  run.trace = impact_trace({2, 0, -1}, {0, 0, 0}, {1, 0, 1}, {0, 50.0, 0});
  const comparison::MetricSet m = comparison::compute_metrics(scene, run, nullptr);
  EXPECT_NEAR(*m.at("tangential_restitution").value, -0.25, 1e-12);
  EXPECT_NEAR(*m.at("rebound_angle").value, 45.0, 1e-12);
  EXPECT_NEAR(*m.at("spin_after").value, 50.0, 1e-12);
}

TEST(EndState, IsTheSubjectsVelocityAndSpinAtTheFirstSampleAfterTheContact) {
  const char* names[] = {"velocity_after_x",         "velocity_after_y",         "velocity_after_z",
                         "angular_velocity_after_x", "angular_velocity_after_y", "angular_velocity_after_z"};
  const cases::Scene scene = floor_scene(std::vector<std::string>(std::begin(names), std::end(names)));
  cases::RunResult run;
  run.status = cases::RunStatus::ok;
  run.trace = impact_trace({2, 0.5, -1}, {1, 2, 3}, {1.25, -0.5, 0.75}, {-7, 80, 0.25});
  const comparison::MetricSet m = comparison::compute_metrics(scene, run, nullptr);
  const double expected[] = {1.25, -0.5, 0.75, -7, 80, 0.25};
  for (int k = 0; k < 6; ++k) {
    ASSERT_TRUE(m.at(names[k]).value) << names[k] << ": " << m.at(names[k]).problem;
    EXPECT_EQ(*m.at(names[k]).value, expected[k]) << names[k];
  }
  // In the case's frame: the wall's velocity is not subtracted (unlike rebound_angle).
  cases::Scene moving = scene;
  moving.walls[0].velocity = {0.5, 0.0, 0.0};
  EXPECT_EQ(*comparison::motion::state_after(moving, run.trace, false, 0).value, 1.25);
}

TEST(EndState, ARunThatNeverTouchesOrNeverLeavesGivesAProblem) {
  const cases::Scene scene = floor_scene({});
  cases::Trace apart = floor_trace_layout();
  for (int k = 0; k < 5; ++k) apart.append_row({1e-5 * k, 0, 0, 1.0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1.0, 0.0});
  const auto none = comparison::motion::state_after(scene, apart, false, 2);
  EXPECT_FALSE(none.value);
  EXPECT_NE(none.problem.find("never becomes positive"), std::string::npos) << none.problem;
  cases::Trace stuck = floor_trace_layout();
  for (int k = 0; k < 5; ++k) {
    stuck.append_row({1e-5 * k, 0, 0, 0.0, 0, 0, 0, 0, 0, 0, 0, 0, 0, k == 0 ? -1e-4 : 1e-5, k == 0 ? 0.0 : 1.0});
  }
  const auto held = comparison::motion::state_after(scene, stuck, true, 0);
  EXPECT_FALSE(held.value);
  EXPECT_NE(held.problem.find("does not end"), std::string::npos) << held.problem;
  EXPECT_FALSE(comparison::motion::end_state_metric("velocity_after_w", scene, stuck).has_value());
  EXPECT_FALSE(comparison::motion::end_state_metric("velocity_after", scene, stuck).has_value());
}

/// Sliding on the floor at its static overlap: v = v0 − a t until the slip stops, then rolling.
cases::Trace sliding_trace(double v0, double a, double dt, int rows) {
  cases::Trace tr = floor_trace_layout();
  const double delta = 1e-6, lever = kRadius - 0.5 * delta;
  const double spin_rate = 2.5 * a / lever;  // solid sphere: ω̇ = μ m g ℓ / I with a = μ g
  const double t_roll = v0 / (a + spin_rate * lever);
  for (int k = 0; k < rows; ++k) {
    const double t = std::min(k * dt, t_roll);
    const double v = v0 - a * t, w = spin_rate * t;
    tr.append_row({k * dt, v0 * t - 0.5 * a * t * t, 0, kRadius - delta, v, 0, 0, 0, w, 0, -a, 0, 0,
                   delta, 1.0});
  }
  return tr;
}

TEST(Deceleration, IsTheSlopeOfTheTangentialSpeedWhileSliding) {
  const double a = 0.2 * 9.81;
  cases::Scene scene = floor_scene({"deceleration"});
  const auto d = comparison::motion::deceleration(scene, sliding_trace(1.0, a, 1e-4, 3000));
  ASSERT_TRUE(d.value) << d.problem;
  EXPECT_NEAR(*d.value, a, 1e-9 * a);  // the rolling phase is excluded
}

TEST(Deceleration, TooFewSlidingRowsIsAProblem) {
  const auto d = comparison::motion::deceleration(floor_scene({}), sliding_trace(1.0, 2.0, 0.2, 10));
  EXPECT_FALSE(d.value);
  EXPECT_NE(d.problem.find("sliding rows"), std::string::npos);
}

TEST(MotionMetrics, MissingContactSettingIsAProblem) {
  cases::Scene scene = floor_scene({});
  scene.compare.wall_contact.reset();
  const auto r = comparison::motion::rebound_angle(scene, impact_trace({2, 0, -1}, {}, {1, 0, 1}, {}));
  EXPECT_FALSE(r.value);
  EXPECT_NE(r.problem.find("compare.pair"), std::string::npos);
}

}  // namespace

namespace metrics_motion_test {

/// Mass of the test sphere (r = 0.01 m, ρ = 1000 kg/m³).
double dem_mass() { return 4.0 / 3.0 * std::numbers::pi * 1000.0 * kRadius * kRadius * kRadius; }

/// The floor scene with a material (ρ = 1000) and a tilted gravity, so that the weight has a
/// part along the wall.
cases::Scene weighted_floor_scene() {
  cases::Scene s = floor_scene({"tangential_force_max"});
  dem::MaterialProperties m;
  m.name = "sphere";
  m.density = 1000.0;
  s.materials = {m};
  s.gravity = {3.0, 0.0, -9.81};
  return s;
}

/// impact_trace with forces: the weight throughout, plus the contact force (−2 + 0.3 k, 0.2 k',
/// 5) on the rows in contact, and a large force on one row after the contact.
cases::Trace forced_trace(double mass) {
  cases::Trace tr = impact_trace({1, 0, -1}, {}, {1, 0, 1}, {});
  cases::Trace out = floor_trace_layout();
  for (std::size_t k = 0; k < tr.rows(); ++k) {
    std::vector<double> row;
    for (std::size_t c = 0; c < tr.columns().size(); ++c) row.push_back(tr.values(c)[k]);
    const double in_contact = row[13] > 0.0 ? 1.0 : 0.0;
    const double i = static_cast<double>(k) - 10.0;
    row[10] = mass * 3.0 + in_contact * (-2.0 + 0.3 * i) + (k == 25 ? 100.0 : 0.0);
    row[11] = in_contact * 0.2 * i;
    row[12] = -mass * 9.81 + in_contact * 5.0;
    out.append_row(row);
  }
  return out;
}

TEST(TangentialForceMax, IsTheLargestInPlaneContactForceLessTheWeight) {
  const cases::Scene scene = weighted_floor_scene();
  const double mass = dem_mass();
  const auto f = comparison::motion::tangential_force_max(scene, forced_trace(mass));
  ASSERT_TRUE(f.value) << f.problem;
  // Rows 10–19 are in contact: |(−2 + 0.3 i, 0.2 i)| is largest at i = 0 (2.0); the weight's
  // tangential part (3 m) and the 100 N after the contact do not count.
  EXPECT_NEAR(*f.value, 2.0, 1e-12);
  cases::RunResult run;
  run.status = cases::RunStatus::ok;
  run.trace = forced_trace(mass);
  const auto m = comparison::compute_metrics(scene, run, nullptr);
  ASSERT_TRUE(m.at("tangential_force_max").value) << m.at("tangential_force_max").problem;
  EXPECT_EQ(*m.at("tangential_force_max").value, *f.value);
}

TEST(TangentialForceMax, NeedsASceneOfTheSubjectAndItsPartnerAlone) {
  cases::Scene crowded = weighted_floor_scene();
  crowded.particles.push_back(crowded.particles[0]);
  const auto a = comparison::motion::tangential_force_max(crowded, forced_trace(dem_mass()));
  EXPECT_FALSE(a.value);
  EXPECT_NE(a.problem.find("partner alone"), std::string::npos) << a.problem;
  cases::Scene fluid = weighted_floor_scene();
  fluid.fluid.emplace();
  const auto b = comparison::motion::tangential_force_max(fluid, forced_trace(dem_mass()));
  EXPECT_FALSE(b.value);
  EXPECT_NE(b.problem.find("fluid"), std::string::npos) << b.problem;
}

}  // namespace metrics_motion_test
