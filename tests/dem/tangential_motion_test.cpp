// SPDX-License-Identifier: MIT
// Friction in motion through the whole core: a sliding sphere decelerates at μg and spins up
// from the torque a_p × F_t until it rolls; blocks and spheres on slopes stick, roll or slide as
// Coulomb's law says; energy never rises; trial evaluations never touch the committed slip; an
// oblique impact in gross sliding gives the rigid-body closed form.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/simulation/simulation.hpp"

namespace tangential_motion_test {

using dem::Vec3;

constexpr double kRadius = 0.01;
constexpr double kDensity = 1000.0;
constexpr double kStiffness = 1e5;
constexpr double kGravity = 9.81;
const double kMass = 4.0 / 3.0 * std::numbers::pi * kDensity * std::pow(kRadius, 3);
const double kInertia = 0.4 * kMass * kRadius * kRadius;

/// One sphere near (or on) a plane wall through the origin with unit normal `normal`.
struct WallScene {
  double friction = 0.2;
  double tangential_stiffness = 1e5;
  double damping_ratio = 0.0;
  double restitution = 1.0;
  bool rotation = true;
  dem::WallLeverArm lever = dem::WallLeverArm::contact_point;
  dem::FrictionLimit limit = dem::FrictionLimit::total;
  dem::SchemeId scheme = dem::SchemeId::velocity_verlet;
  double timestep = 1e-6;
  Vec3 normal = Vec3::UnitZ();
  Vec3 gravity = Vec3::Zero();
  double height = kRadius;  ///< initial centre distance from the wall
  Vec3 velocity = Vec3::Zero();

  [[nodiscard]] dem::SimulationSetup setup() const {
    dem::SimulationSetup s;
    dem::MaterialProperties m;
    m.name = "ball";
    m.density = kDensity;
    m.normal_stiffness = kStiffness;
    m.restitution = restitution;
    m.tangential_stiffness = tangential_stiffness;
    m.friction = friction;
    m.tangential_damping_ratio = damping_ratio;
    s.materials = {m};
    s.model.damping = restitution < 1.0 ? "restitution" : "none";
    s.model.tangential = "spring_coulomb";
    s.model.wall_lever_arm = lever;
    s.model.friction_limit = limit;
    s.particles = {dem::ParticleInit{kRadius, kRadius, kDensity, 0, height * normal, velocity,
                                     Vec3::Zero(), false}};
    s.walls = {dem::Wall{Vec3::Zero(), normal}};
    s.fields.gravity = gravity;
    s.scheme = scheme;
    s.scheme_settings.rotation = rotation;
    s.scheme_settings.length_scale = kRadius;
    s.timestep = timestep;
    return s;
  }
};

/// A sphere resting at its static overlap on the floor, sliding at v0 along x without spin.
WallScene sliding_sphere(double mu, double v0) {
  WallScene w;
  w.friction = mu;
  w.gravity = Vec3(0, 0, -kGravity);
  w.height = kRadius - kMass * kGravity / kStiffness;
  w.velocity = Vec3(v0, 0, 0);
  w.timestep = 2e-6;
  return w;
}

TEST(SlidingSphere, DeceleratesAtMuGAndSpinsUpFromTheFrictionTorqueUntilItRolls) {
  const double mu = 0.2, v0 = 1.0;
  dem::Simulation sim(sliding_sphere(mu, v0).setup());
  const double lever = kRadius - 0.5 * kMass * kGravity / kStiffness;
  const double slip_rate = mu * kGravity * (1.0 + kMass * lever * lever / kInertia);
  const double t_roll = v0 / slip_rate;
  while (sim.time() < 0.5 * t_roll) sim.step();
  const double t = sim.time();
  // The first half kick sees the unstretched spring (no slip yet): a lag of at most one step.
  const double dt = sim.timestep();
  EXPECT_NEAR(sim.state().velocity(0, 0), v0 - mu * kGravity * t, mu * kGravity * dt);
  const double spin_rate = mu * kMass * kGravity * lever / kInertia;
  EXPECT_NEAR(sim.state().angular_velocity(1, 0), spin_rate * t, spin_rate * dt);
  while (sim.time() < 2.0 * t_roll) sim.step();
  // Rolling: v = v0 / (1 + m ℓ²/I) ≈ 5/7 v0, contact point at rest up to the spring's ring-down.
  const double v_roll = v0 / (1.0 + kInertia / (kMass * lever * lever));
  EXPECT_NEAR(sim.state().velocity(0, 0), v_roll, 5e-4);
  EXPECT_NEAR(v_roll, 5.0 / 7.0 * v0, 2e-4);
}

TEST(SlidingSphere, RungeKuttaStagesGiveTheSameDecelerationAsVelocityVerlet) {
  for (const auto scheme : {dem::SchemeId::rk4, dem::SchemeId::rk2, dem::SchemeId::leapfrog}) {
    WallScene w = sliding_sphere(0.3, 1.0);
    w.scheme = scheme;
    dem::Simulation sim(w.setup());
    while (sim.time() < 0.01) sim.step();
    const double v1 = sim.state().velocity(0, 0), t1 = sim.time();
    while (sim.time() < 0.05) sim.step();
    const double a = (v1 - sim.state().velocity(0, 0)) / (sim.time() - t1);
    EXPECT_NEAR(a, 0.3 * kGravity, 1e-9 * kGravity) << static_cast<int>(scheme);
  }
}

TEST(TrialEvaluation, NeverChangesTheCommittedSlip) {
  dem::Simulation sim(sliding_sphere(10.0, 0.1).setup());  // stuck: the slip grows every step
  for (int n = 0; n < 10; ++n) sim.step();
  const std::size_t before = sim.force_field().interacting_pairs();  // sphere pairs: none
  dem::ContactForceField& field = sim.force_field();
  dem::Accelerations acc;
  const dem::KinematicState state = sim.state();
  field.trial(state, 1e-6, acc);
  const Vec3 a1 = acc.linear.col(0);
  for (int k = 0; k < 5; ++k) field.trial(state, 1e-6, acc);
  field.trial(state, 0.5e-6, acc);
  field.trial(state, 1e-6, acc);
  EXPECT_EQ(acc.linear.col(0), a1);  // repeated trials see the same committed slip
  dem::Accelerations committed_acc;
  field.commit(state, 1e-6, committed_acc);
  EXPECT_EQ(committed_acc.linear.col(0), a1);
  EXPECT_EQ(sim.force_field().interacting_pairs(), before);
}

/// Block (no rotation) or sphere at rest on a slope of angle θ, at its static overlap.
WallScene on_slope(double theta, double mu, bool rotation) {
  WallScene w;
  w.friction = mu;
  w.rotation = rotation;
  w.restitution = 0.5;
  w.damping_ratio = 1.0;
  w.normal = Vec3(std::sin(theta), 0, std::cos(theta));
  w.gravity = Vec3(0, 0, -kGravity);
  w.height = kRadius - kMass * kGravity * std::cos(theta) / kStiffness;
  w.timestep = 2e-6;
  return w;
}

/// Displacement and velocity down the slope of angle θ.
std::pair<double, double> downhill(const dem::Simulation& sim, double theta) {
  const Vec3 d(std::cos(theta), 0, -std::sin(theta));
  return {sim.state().position.col(0).dot(d), sim.state().velocity.col(0).dot(d)};
}

TEST(BlockOnSlope, SticksWithinTheSpringCreepWhenMuExceedsTanTheta) {
  const double theta = 0.3, mu = 0.8;  // tan θ = 0.309; even the undamped overshoot 2 tan θ sticks
  dem::Simulation sim(on_slope(theta, mu, false).setup());
  while (sim.time() < 0.05) sim.step();
  const auto [s, v] = downhill(sim, theta);
  const double creep = kMass * kGravity * std::sin(theta) / 1e5;  // static spring deflection
  EXPECT_LE(std::abs(s), 2.0 * creep);
  EXPECT_NEAR(s, creep, 0.05 * creep);  // settled on the spring
  EXPECT_LT(std::abs(v), 1e-6);
}

TEST(BlockOnSlope, SlidesWithGTimesSinThetaMinusMuCosThetaWhenMuIsBelowTanTheta) {
  const double theta = 0.5, mu = 0.3;  // tan θ = 0.546
  dem::Simulation sim(on_slope(theta, mu, false).setup());
  while (sim.time() < 0.01) sim.step();
  const auto [s1, v1] = downhill(sim, theta);
  const double t1 = sim.time();
  while (sim.time() < 0.05) sim.step();
  const auto [s2, v2] = downhill(sim, theta);
  const double expected = kGravity * (std::sin(theta) - mu * std::cos(theta));
  EXPECT_NEAR((v2 - v1) / (sim.time() - t1), expected, 1e-6 * expected);
  static_cast<void>(s1);
  static_cast<void>(s2);
}

TEST(SphereOnSlope, RollsAtFiveSeventhsGSinThetaWhenMuExceedsTwoSeventhsTanTheta) {
  const double theta = 0.5, mu = 0.3;  // 2/7 tan θ = 0.156
  WallScene w = on_slope(theta, mu, true);
  w.lever = dem::WallLeverArm::radius;  // rigid-body rolling constraint v = r ω
  dem::Simulation sim(w.setup());
  while (sim.time() < 0.01) sim.step();
  const double v1 = downhill(sim, theta).second, t1 = sim.time();
  while (sim.time() < 0.05) sim.step();
  const double expected = 5.0 / 7.0 * kGravity * std::sin(theta);
  EXPECT_NEAR((downhill(sim, theta).second - v1) / (sim.time() - t1), expected, 2e-3 * expected);
}

TEST(SphereOnSlope, SlidesWithGTimesSinThetaMinusMuCosThetaWhenMuIsBelowTwoSeventhsTanTheta) {
  const double theta = 0.5, mu = 0.1;
  dem::Simulation sim(on_slope(theta, mu, true).setup());
  while (sim.time() < 0.01) sim.step();
  const double v1 = downhill(sim, theta).second, t1 = sim.time();
  while (sim.time() < 0.05) sim.step();
  const double expected = kGravity * (std::sin(theta) - mu * std::cos(theta));
  EXPECT_NEAR((downhill(sim, theta).second - v1) / (sim.time() - t1), expected, 1e-6 * expected);
}

/// Sphere approaching the floor at speed v0, angle θ from the normal.
WallScene oblique(double theta, double mu, double restitution, double v0 = 4.0) {
  WallScene w;
  w.friction = mu;
  w.restitution = restitution;
  w.height = kRadius + 1e-5;
  w.velocity = Vec3(v0 * std::sin(theta), 0, -v0 * std::cos(theta));
  w.tangential_stiffness = 1e6;
  return w;
}

TEST(FrictionEnergy, MechanicalEnergyNeverRisesWithCoulombFrictionAndTheLedgerBalances) {
  // With the elastic basis the cap μ k δ vanishes at separation, so no spring energy is left
  // when the contact (and its history) ends and the ledger closes. With the total basis the
  // dashpot keeps |F_n| > 0 at separation and up to ½ (μ|F_n,end|)²/k_f is dropped with the
  // history (not counted as dissipation: the sub-model is not called once the contact is over).
  for (const auto limit : {dem::FrictionLimit::elastic, dem::FrictionLimit::total}) {
    for (const double theta : {0.3, 0.7, 1.0, 1.3}) {
      WallScene w = oblique(theta, 0.3, 0.7);
      w.limit = limit;
      w.tangential_stiffness = 2.857e4;  // 2/7 k_e: stick–slip at small angles
      w.scheme = dem::SchemeId::rk4;
      w.timestep = 2e-7;
      dem::Simulation sim(w.setup());
      const double e0 = sim.energy().balance();
      double previous = e0;
      while (sim.time() < 1e-3) {
        sim.step();
        const dem::EnergyLedger e = sim.energy();
        const double mechanical = e.kinetic + e.elastic + e.gravitational;
        EXPECT_LE(mechanical, previous * (1.0 + 1e-9)) << "θ = " << theta << ", t = " << sim.time();
        previous = mechanical;
      }
      const dem::EnergyLedger e = sim.energy();
      EXPECT_GT(e.dissipated_friction, 0.0);
      const double tolerance = limit == dem::FrictionLimit::elastic ? 5e-4 : 5e-3;
      EXPECT_NEAR(e.balance(), e0, tolerance * e0) << "θ = " << theta;
      RecordProperty(std::string(dem::to_string(limit)) + "_balance_error_" + std::to_string(theta),
                     std::to_string((e.balance() - e0) / e0));
    }
  }
}

TEST(FrictionEnergy, TangentialDashpotOnlyEverRemovesEnergy) {
  for (const double theta : {0.3, 1.0, 1.3}) {
    WallScene w = oblique(theta, 0.3, 0.7);
    w.damping_ratio = 0.5;
    w.scheme = dem::SchemeId::rk4;
    w.timestep = 2e-7;
    dem::Simulation sim(w.setup());
    const double e0 = sim.energy().balance();
    double dissipated = 0.0;
    while (sim.time() < 1e-3) {
      sim.step();
      EXPECT_GE(sim.energy().dissipated_friction, dissipated);
      dissipated = sim.energy().dissipated_friction;
    }
    const dem::EnergyLedger e = sim.energy();
    EXPECT_EQ(e.elastic, 0.0);  // the contact is over
    EXPECT_LT(e.kinetic, 0.49 * e0 + 0.51 * e0 * std::pow(std::sin(theta), 2));  // e_n² of the normal part at most
    EXPECT_NEAR(e.balance(), e0, 2e-3 * e0) << "θ = " << theta;
  }
}

TEST(ObliqueImpact, GrossSlidingMatchesTheRigidBodyClosedForm) {
  // e = 1, lever r: Δv_t = −2 μ v_n, Δω = 5 μ v_n / r (solid sphere), in gross sliding
  // (tan θ = 1.73 > 7μ = 1.4).
  const double theta = std::numbers::pi / 3.0, mu = 0.2, v0 = 4.0;
  WallScene w = oblique(theta, mu, 1.0, v0);
  w.lever = dem::WallLeverArm::radius;
  dem::Simulation sim(w.setup());
  while (sim.time() < 1e-3) sim.step();
  const double v_n = v0 * std::cos(theta), v_t = v0 * std::sin(theta);
  EXPECT_NEAR(sim.state().velocity(0, 0), v_t - 2.0 * mu * v_n, 2e-5 * v_t);
  EXPECT_NEAR(sim.state().velocity(2, 0), v_n, 1e-5 * v_n);
  EXPECT_NEAR(sim.state().angular_velocity(1, 0), 5.0 * mu * v_n / kRadius, 2e-5 * 5.0 * mu * v_n / kRadius);
}

}  // namespace
