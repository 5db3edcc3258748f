// SPDX-License-Identifier: MIT
// Langston's continuous potential (thesis eq 3.17–3.19): force and energy formulas, the
// cut-off at d_crit, action before contact, and an elastic rebound through the core.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/langston_potential.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/simulation/simulation.hpp"

namespace normal_potential_test {

using dem::laws::langston_energy_scale;
using dem::laws::langston_potential;

constexpr double kA = 36.0;
constexpr double kD = 0.02;                      // d = r_p + r_q [m]
constexpr double kCrit = 0.02 * std::numbers::sqrt2;  // d_crit = √2 d
constexpr double kMass = 4.0 / 3.0 * std::numbers::pi * 1000.0 * 1e-6 / 2.0;  // m* of two spheres
constexpr double kG = 9.81;

double scale() { return langston_energy_scale(kD, kMass, kG, kA); }

TEST(LangstonLaw, ForceIsEquation318) {
  const double x = 0.019;
  const double expected = kA * scale() / x * std::pow(kD / x, kA);
  EXPECT_NEAR(langston_potential(kA, scale(), kD, kCrit, x).force, expected, 1e-14 * expected);
}

TEST(LangstonLaw, ForceAtTheContactDistanceIsTheWeight) {
  EXPECT_NEAR(langston_potential(kA, scale(), kD, kCrit, kD).force, kMass * kG, 1e-15);
}

TEST(LangstonLaw, ForceAndStiffnessAreDerivativesOfTheEnergy) {
  for (const double x : {0.018, 0.02, 0.024}) {
    const double h = 1e-7 * x;
    const auto at = [&](double y) { return langston_potential(kA, scale(), kD, kCrit, y); };
    const double force = -(at(x + h).energy - at(x - h).energy) / (2.0 * h);
    const double stiffness = -(at(x + h).force - at(x - h).force) / (2.0 * h);
    EXPECT_NEAR(at(x).force, force, 1e-6 * force) << "|x| = " << x;
    EXPECT_NEAR(at(x).stiffness, stiffness, 1e-6 * stiffness) << "|x| = " << x;
  }
}

TEST(LangstonLaw, EnergyIsContinuousAndForceJumpsAtTheCutOff) {
  const auto inside = langston_potential(kA, scale(), kD, kCrit, std::nextafter(kCrit, 0.0));
  EXPECT_NEAR(inside.energy, 0.0, 1e-18);
  EXPECT_NEAR(inside.force, kA * scale() / kCrit * std::pow(kD / kCrit, kA), 1e-18);
  EXPECT_EQ(langston_potential(kA, scale(), kD, kCrit, kCrit).force, 0.0);
}

dem::PairLaw potential_law() {
  dem::ModelChoice choice;
  choice.normal = "potential";
  dem::PairProperties p;
  p.potential_exponent = kA;
  p.potential_critical_ratio = std::numbers::sqrt2;
  p.potential_gravity = kG;
  return dem::make_pair_law(choice, p);
}

TEST(PotentialNormal, ActsBeforeContactOutToTheCriticalDistance) {
  const dem::PairLaw law = potential_law();
  EXPECT_NEAR(dem::interaction_range(law, {kD, kD, 0.005}), kCrit, 1e-15);
  dem::SphereState p{dem::Vec3(0, 0, 0), dem::Vec3(1, 0, 0), dem::Vec3::Zero(), 0.01, 0.01, 1.0 / (2.0 * kMass)};
  dem::SphereState q{dem::Vec3(0.025, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), 0.01, 0.01, 1.0 / (2.0 * kMass)};
  const dem::ContactOutcome c = dem::evaluate_contact(law, dem::pair_geometry(p, q), {}, 1e-6);
  EXPECT_TRUE(c.interacting);
  EXPECT_FALSE(c.contact);
  EXPECT_NEAR(c.normal_force, langston_potential(kA, scale(), kD, kCrit, 0.025).force, 1e-20);
  EXPECT_GT(c.normal_force, 0.0);
  q.position.x() = 0.029;
  EXPECT_FALSE(dem::evaluate_contact(law, dem::pair_geometry(p, q), {}, 1e-6).interacting);
}

TEST(PotentialCollision, ReboundsElasticallyAtTheDistanceWhereThePotentialHoldsTheImpactEnergy) {
  // Two equal spheres at ±0.05 m/s head-on, RK4: closest approach where φ − φ(d_crit) = ½ m* v².
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "soft";
  m.density = 1000.0;
  m.potential_exponent = kA;
  m.potential_critical_ratio = std::numbers::sqrt2;
  m.potential_gravity = kG;
  s.materials = {m};
  s.model.normal = "potential";
  s.particles = {
      dem::ParticleInit{0.01, 0.01, 1000.0, 0, dem::Vec3(0, 0, 0), dem::Vec3(0.05, 0, 0), dem::Vec3::Zero(), false},
      dem::ParticleInit{0.01, 0.01, 1000.0, 0, dem::Vec3(0.0285, 0, 0), dem::Vec3(-0.05, 0, 0), dem::Vec3::Zero(), false}};
  s.scheme = dem::SchemeId::rk4;
  s.scheme_settings.rotation = false;
  s.scheme_settings.length_scale = 0.01;
  s.timestep = 2e-6;
  dem::Simulation sim(s);
  double closest = 1.0;
  while (sim.time() < 0.2) {
    sim.step();
    closest = std::min(closest, sim.state().position(0, 1) - sim.state().position(0, 0));
  }
  const double kinetic = 0.5 * kMass * 0.1 * 0.1;
  const double expected = kD * std::pow(kinetic / scale() + std::pow(1.0 / std::numbers::sqrt2, kA), -1.0 / kA);
  EXPECT_NEAR(closest, expected, 1e-9);
  EXPECT_NEAR(sim.state().velocity(0, 0), -0.05, 1e-6);  // no dissipation: rebound at ε = 1
}

}  // namespace
