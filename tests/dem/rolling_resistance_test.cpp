// SPDX-License-Identifier: MIT
// Rolling resistance: the constant directional torque and LAMMPS' spring–dashpot–slider
// against their formulas, a rolling sphere's deceleration μ_r g m r ℓ/(I + m ℓ²), the bounded
// chatter of the constant torque at rest, and Newton's third law for the contact torques.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/rolling_resistance.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/simulation/simulation.hpp"

namespace rolling_resistance_test {

using dem::Vec3;

constexpr double kRadius = 0.01;
constexpr double kDensity = 1000.0;
constexpr double kGravity = 9.81;
const double kMass = 4.0 / 3.0 * std::numbers::pi * kDensity * std::pow(kRadius, 3);
const double kInertia = 0.4 * kMass * kRadius * kRadius;

dem::ContactGeometry floor_contact(double overlap, const Vec3& v, const Vec3& w) {
  const dem::SphereState p{Vec3(0, 0, kRadius - overlap), v, w, kRadius, kRadius, 1.0 / kMass};
  return dem::wall_geometry(p, dem::Wall{Vec3::Zero(), Vec3::UnitZ()}, 0.0, dem::WallLeverArm::contact_point);
}

dem::PairLaw rolling_law(const char* rolling, double mu_r, double k_r = 1e3, double gamma_r = 0.0) {
  dem::PairProperties p;
  p.normal_stiffness = 1e5;
  p.rolling_friction = mu_r;
  p.rolling_stiffness = k_r;
  p.rolling_damping = gamma_r;
  dem::ModelChoice c;
  c.rolling = rolling;
  return dem::make_pair_law(c, p);
}

TEST(RollingVelocity, PointsAlongTheTravelOfASphereRollingOnAFloor) {
  const Vec3 v_roll = dem::laws::rolling_velocity(kRadius, Vec3(0, 100.0, 0), Vec3::UnitZ());
  EXPECT_TRUE(v_roll.isApprox(Vec3(1.0, 0, 0), 1e-15));
  EXPECT_EQ(dem::laws::rolling_velocity(kRadius, Vec3(0, 0, 50.0), Vec3::UnitZ()), Vec3::Zero());
}

TEST(ConstantTorqueRolling, TorqueIsMuRTimesRStarTimesBasisAgainstTheRollingSpin) {
  const dem::PairLaw law = rolling_law("constant_torque", 0.1);
  const dem::ContactGeometry g = floor_contact(1e-4, Vec3(1, 0, 0), Vec3(3.0, 100.0, 40.0));  // F_n = 10 N
  const dem::ContactOutcome c = dem::evaluate_contact(law, g, dem::ContactHistory{}, 1e-6);
  const Vec3 rolling(3.0, 100.0, 0.0);  // the twisting part about n is left alone
  EXPECT_TRUE(c.torque_on_p.isApprox(-0.1 * kRadius * 10.0 * rolling.normalized(), 1e-14));
  EXPECT_TRUE(c.torque_on_q.isApprox(-c.torque_on_p, 1e-15));
  EXPECT_NEAR(c.dissipated_friction, 0.1 * kRadius * 10.0 * rolling.norm() * 1e-6, 1e-18);
}

TEST(ConstantTorqueRolling, NoTorqueWithoutRollingSpin) {
  const dem::PairLaw law = rolling_law("constant_torque", 0.1);
  const dem::ContactOutcome c =
      dem::evaluate_contact(law, floor_contact(1e-4, Vec3::Zero(), Vec3(0, 0, 7.0)), {}, 1e-6);
  EXPECT_EQ(c.torque_on_p, Vec3::Zero());
}

TEST(ConstantTorqueRolling, TheProjectedFormIsLiggghtsCdtOnTheElasticForce) {
  // LIGGGHTS rolling_friction cdt: μ_r R* F_el along the unit whole spin, its twist part dropped
  // afterwards. A linear spring 1e5 N/m at δ = 1e-4 m: F_el = 10 N; a dashpot of 2 N/(m/s) at an
  // approach of 0.5 m/s raises the friction-limit basis to 11 N, which the projected form ignores.
  dem::PairProperties p;
  p.normal_stiffness = 1e5;
  p.damping_coefficient = 2.0;
  p.rolling_friction = 0.1;
  dem::ModelChoice c;
  c.damping = "lammps_velocity";
  c.rolling = "constant_torque";
  c.constant_torque_form = dem::ConstantTorqueForm::projected;
  const dem::PairLaw projected = dem::make_pair_law(c, p);
  c.constant_torque_form = dem::ConstantTorqueForm::tangent;
  const dem::PairLaw tangent = dem::make_pair_law(c, p);
  const Vec3 spin(3.0, 100.0, 40.0);
  const dem::ContactGeometry g = floor_contact(1e-4, Vec3(1, 0, -0.5), spin);
  const dem::ContactOutcome a = dem::evaluate_contact(projected, g, dem::ContactHistory{}, 1e-6);
  const dem::ContactOutcome b = dem::evaluate_contact(tangent, g, dem::ContactHistory{}, 1e-6);
  ASSERT_NEAR(b.normal_force, 11.0, 1e-12);
  const Vec3 unit = spin.normalized();
  const Vec3 expected = -0.1 * kRadius * 10.0 * Vec3(unit.x(), unit.y(), 0.0);  // |·| = μ_r R* F_el sin θ
  EXPECT_TRUE(a.torque_on_p.isApprox(expected, 1e-14)) << a.torque_on_p.transpose();
  EXPECT_TRUE(b.torque_on_p.isApprox(-0.1 * kRadius * 11.0 * Vec3(3.0, 100.0, 0.0).normalized(), 1e-14));
  EXPECT_TRUE(a.torque_on_q.isApprox(-a.torque_on_p, 1e-15));
  // A spin in the tangent plane: the two forms differ by their force alone.
  const dem::ContactGeometry rolling = floor_contact(1e-4, Vec3(1, 0, 0), Vec3(0, 100.0, 0));
  const Vec3 t = dem::evaluate_contact(projected, rolling, {}, 1e-6).torque_on_p;
  EXPECT_TRUE(t.isApprox(Vec3(0, -0.1 * kRadius * 10.0, 0), 1e-14)) << t.transpose();
  // Pure twist: no torque in either form.
  EXPECT_EQ(dem::laws::projected_rolling_torque(0.1, kRadius, 10.0, Vec3(0, 0, 7.0), Vec3::UnitZ()), Vec3::Zero());
  EXPECT_EQ(dem::laws::projected_rolling_torque(0.1, kRadius, 10.0, Vec3::Zero(), Vec3::UnitZ()), Vec3::Zero());
}

TEST(SpringDashpotSliderRolling, StuckSpringGivesTorqueRStarNCrossPseudoForce) {
  const double k_r = 1e3, gamma_r = 0.02;
  const dem::PairLaw law = rolling_law("spring_dashpot_slider", 10.0, k_r, gamma_r);
  const dem::ContactGeometry g = floor_contact(1e-4, Vec3::Zero(), Vec3(0, 2.0, 0));
  dem::ContactHistory committed;
  committed.rolling_slip = Vec3(1e-6, 0, 0);
  const double dt = 1e-6;
  const dem::ContactOutcome c = dem::evaluate_contact(law, g, committed, dt);
  const Vec3 v_roll(kRadius * 2.0, 0, 0);
  const Vec3 xi = committed.rolling_slip + v_roll * dt;
  const Vec3 f_r = -k_r * xi - gamma_r * v_roll;
  EXPECT_TRUE(c.history.rolling_slip.isApprox(xi, 1e-15));
  EXPECT_TRUE(c.torque_on_p.isApprox(kRadius * Vec3::UnitZ().cross(f_r), 1e-14));
  EXPECT_LT(c.torque_on_p.y(), 0.0);  // opposes the rolling spin ω_y > 0
}

TEST(SpringDashpotSliderRolling, SlidingTorqueIsCappedAtMuRTimesRStarTimesBasis) {
  const double mu_r = 0.1, k_r = 1e3;
  const dem::PairLaw law = rolling_law("spring_dashpot_slider", mu_r, k_r);
  dem::ContactHistory committed;
  committed.rolling_slip = Vec3(1e-2, 0, 0);
  const dem::ContactOutcome c =
      dem::evaluate_contact(law, floor_contact(1e-4, Vec3::Zero(), Vec3(0, 2.0, 0)), committed, 1e-6);
  EXPECT_NEAR(c.torque_on_p.norm(), mu_r * kRadius * 10.0, 1e-15);
  EXPECT_NEAR(k_r * c.history.rolling_slip.norm(), mu_r * 10.0, 1e-12);
}

/// A sphere rolling without slip on the floor at v0, resting at its static overlap.
dem::SimulationSetup rolling_sphere(const char* rolling, double mu_r, double v0) {
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "ball";
  m.density = kDensity;
  m.normal_stiffness = 1e5;
  m.restitution = 0.5;
  m.tangential_stiffness = 1e5;
  m.friction = 0.5;
  m.tangential_damping_ratio = 1.0;
  m.rolling_friction = mu_r;
  m.rolling_stiffness = 1e3;
  m.rolling_damping = 0.0;
  s.materials = {m};
  s.model.damping = "restitution";
  s.model.tangential = "spring_coulomb";
  s.model.rolling = rolling;
  const double overlap = kMass * kGravity / 1e5;
  const double lever = kRadius - 0.5 * overlap;
  s.particles = {dem::ParticleInit{kRadius, kRadius, kDensity, 0, Vec3(0, 0, kRadius - overlap),
                                   Vec3(v0, 0, 0), Vec3(0, v0 / lever, 0), false}};
  s.walls = {dem::Wall{Vec3::Zero(), Vec3::UnitZ()}};
  s.fields.gravity = Vec3(0, 0, -kGravity);
  s.scheme = dem::SchemeId::velocity_verlet;
  s.scheme_settings.length_scale = kRadius;
  s.timestep = 2e-6;
  return s;
}

TEST(RollingResistance, RollingSphereDeceleratesAtMuRGTimesRLeverOverInertiaPlusMLeverSquared) {
  // LAMMPS 29 Sep 2021 measured 0.7007 m/s² for μ_r = 0.1 with lever R (= μ_r g / 1.4).
  const double mu_r = 0.1;
  const double lever = kRadius - 0.5 * kMass * kGravity / 1e5;
  const double expected = mu_r * kGravity * kMass * kRadius * lever / (kInertia + kMass * lever * lever);
  for (const char* model : {"constant_torque", "spring_dashpot_slider"}) {
    dem::Simulation sim(rolling_sphere(model, mu_r, 1.0));
    while (sim.time() < 0.02) sim.step();
    const double v1 = sim.state().velocity(0, 0), t1 = sim.time();
    while (sim.time() < 0.12) sim.step();
    const double deceleration = (v1 - sim.state().velocity(0, 0)) / (sim.time() - t1);
    EXPECT_NEAR(deceleration, expected, 2e-3 * expected) << model;
    EXPECT_NEAR(expected, 0.7007, 1e-3);
  }
}

TEST(RollingResistance, ConstantTorqueChatterAtRestStaysBelowTorqueTimesStepOverInertia) {
  const double mu_r = 0.1;
  dem::Simulation sim(rolling_sphere("constant_torque", mu_r, 0.05));
  const double stop = 0.05 / 0.7;  // time to come to rest
  while (sim.time() < stop + 0.02) sim.step();
  const double bound = mu_r * kRadius * kMass * kGravity * sim.timestep() / kInertia;
  double largest = 0.0;
  for (int n = 0; n < 2000; ++n) {
    sim.step();
    largest = std::max(largest, std::abs(sim.state().angular_velocity(1, 0)));
  }
  EXPECT_LE(largest, 2.0 * bound);
  EXPECT_LT(std::abs(sim.state().velocity(0, 0)), 2.0 * bound * kRadius);
}

TEST(ContactTorques, PairTorquesAndForcesConserveAngularMomentumAboutAnyPoint) {
  dem::PairProperties p;
  p.normal_stiffness = 1e5;
  p.tangential_stiffness = 2e4;
  p.friction = 0.3;
  p.tangential_damping_ratio = 0.0;
  p.rolling_friction = 0.1;
  p.rolling_stiffness = 1e3;
  p.rolling_damping = 0.01;
  for (const char* rolling : {"constant_torque", "spring_dashpot_slider"}) {
    dem::ModelChoice c;
    c.tangential = "spring_coulomb";
    c.rolling = rolling;
    const dem::PairLaw law = dem::make_pair_law(c, p);
    const dem::SphereState a{Vec3(0.001, 0.002, 0.0), Vec3(1, 0.5, 0), Vec3(3, -20, 7), 0.01, 0.01, 250.0};
    const dem::SphereState b{Vec3(0.002, 0.0195, 0.004), Vec3(-1, 0, 0.2), Vec3(0, 40, 1), 0.008, 0.008, 500.0};
    const dem::ContactGeometry g = dem::pair_geometry(a, b);
    ASSERT_GT(g.overlap, 0.0);
    dem::ContactHistory committed;
    committed.tangential_slip = Vec3(1e-5, 0, 0);
    const dem::ContactOutcome o = dem::evaluate_contact(law, g, committed, 1e-6);
    // Forces act at the centres; torque about the origin: x_p × F + x_q × (−F) + τ_p + τ_q = 0.
    const Vec3 total = a.position.cross(o.force_on_p) - b.position.cross(o.force_on_p) +
                       o.torque_on_p + o.torque_on_q;
    EXPECT_LT(total.norm(), 1e-15 * (1.0 + o.force_on_p.norm())) << rolling;
  }
}

}  // namespace
