// SPDX-License-Identifier: MIT
// Plane walls as infinite-mass partners, prescribed motion of fixed spheres, and the energy
// ledger (dissipated work accounts for every joule the collision loses).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/simulation/simulation.hpp"

namespace walls_motion_energy_test {

dem::SimulationSetup floor_drop(double restitution, dem::SchemeId scheme, double dt) {
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "ball";
  m.density = 1000.0;
  m.normal_stiffness = 1e5;
  m.restitution = restitution;
  s.materials = {m};
  s.model.damping = "restitution";
  // Sphere 1 mm above a floor at z = 0, falling at 2 m/s; no gravity so the rebound is clean.
  s.particles = {dem::ParticleInit{0.01, 0.01, 1000.0, 0, dem::Vec3(0, 0, 0.011),
                                   dem::Vec3(0, 0, -2.0), dem::Vec3::Zero(), false}};
  s.walls = {dem::Wall{dem::Vec3::Zero(), dem::Vec3(0, 0, 1), dem::Vec3::Zero(), 0}};
  s.scheme = scheme;
  s.scheme_settings.rotation = false;
  s.scheme_settings.length_scale = 0.01;
  s.timestep = dt;
  return s;
}

double mover_mass() { return 4.0 / 3.0 * std::numbers::pi * 1000.0 * 1e-6; }

TEST(Wall, ReboundsWithTheRequestedRestitutionAndM_StarEqualToM) {
  const double eta = dem::laws::restitution_damping_coefficient(0.6, mover_mass(), 1e5);
  const double tc = dem::laws::linear_contact_duration(1e5, mover_mass(), eta);
  dem::Simulation sim(floor_drop(0.6, dem::SchemeId::rk4, tc / 400.0));
  while (sim.time() < 5e-4 + 1.5 * tc) sim.step();
  EXPECT_NEAR(sim.state().velocity(2, 0) / 2.0, 0.6, 1e-4);
}

TEST(Wall, WatchedWallContactReportsOverlapAndForce) {
  dem::Simulation sim(floor_drop(1.0, dem::SchemeId::velocity_verlet, 1e-6));
  sim.watch({dem::ContactObservation{0, 0, true, 0.0, 0.0, false}});
  EXPECT_NEAR(sim.force_field().observations()[0].overlap, -0.001, 1e-15);
  double deepest = 0.0, strongest = 0.0;
  while (sim.time() < 1.5e-3) {
    sim.step();
    const auto& o = sim.force_field().observations()[0];
    deepest = std::max(deepest, o.overlap);
    strongest = std::max(strongest, o.normal_force);
    if (o.interacting) {
      EXPECT_NEAR(o.normal_force, 1e5 * o.overlap, 1e-9);
    }
  }
  const double expected = 2.0 * std::sqrt(mover_mass() / 1e5);  // u √(m/k)
  EXPECT_NEAR(deepest, expected, 1e-3 * expected);
  EXPECT_NEAR(strongest, 1e5 * expected, 1e-3 * 1e5 * expected);
}

TEST(EnergyLedger, DissipatedWorkAccountsForTheLostKineticEnergy) {
  const double eta = dem::laws::restitution_damping_coefficient(0.5, mover_mass(), 1e5);
  const double tc = dem::laws::linear_contact_duration(1e5, mover_mass(), eta);
  dem::Simulation sim(floor_drop(0.5, dem::SchemeId::rk4, tc / 1000.0));
  const double e0 = sim.energy().balance();
  double max_mechanical = sim.energy().kinetic;
  while (sim.time() < 5e-4 + 1.5 * tc) {
    sim.step();
    const dem::EnergyLedger e = sim.energy();
    const double mechanical = e.kinetic + e.elastic;
    EXPECT_LE(mechanical, max_mechanical * (1.0 + 1e-9)) << "mechanical energy rose at t = " << sim.time();
    max_mechanical = std::max(max_mechanical, mechanical);
  }
  const dem::EnergyLedger e = sim.energy();
  EXPECT_NEAR(e.kinetic, 0.25 * e0, 1e-3 * e0);            // e² of the impact energy remains
  EXPECT_NEAR(e.dissipated_damping, 0.75 * e0, 2e-3 * e0);  // the dashpot took the rest
  EXPECT_NEAR(e.balance(), e0, 2e-3 * e0);
}

TEST(EnergyLedger, GravitationalEnergyIsMinusMGDotX) {
  dem::SimulationSetup s = floor_drop(1.0, dem::SchemeId::rk4, 1e-5);
  s.walls.clear();
  s.fields.gravity = dem::Vec3(0, 0, -9.81);
  dem::Simulation sim(s);
  const double e0 = sim.energy().balance();
  for (int i = 0; i < 1000; ++i) sim.step();
  EXPECT_NEAR(sim.energy().balance(), e0, 1e-12 * e0);  // free fall: RK4 is exact for constant g
}

TEST(PrescribedMotion, MovesAFixedSphereAlongItsSegments) {
  dem::PrescribedMotion m{0, dem::Vec3(1, 0, 0), {{2.0, dem::Vec3(-1, 0, 0)}, {0.0, dem::Vec3(0, 3, 0)}}};
  EXPECT_EQ(m.position(1.0), dem::Vec3(0, 0, 0));
  EXPECT_EQ(m.position(2.0), dem::Vec3(-1, 0, 0));
  EXPECT_EQ(m.position(4.0), dem::Vec3(-1, 6, 0));
  EXPECT_EQ(m.velocity(1.5), dem::Vec3(-1, 0, 0));
  EXPECT_EQ(m.velocity(2.5), dem::Vec3(0, 3, 0));
}

TEST(PrescribedMotion, PushesAFreeSphereLikeAMovingWall) {
  // A fixed sphere driven at 1 m/s into a resting sphere: the free sphere leaves at 2 m/s
  // (elastic collision with an infinite mass moving at 1 m/s).
  dem::SimulationSetup s = floor_drop(1.0, dem::SchemeId::rk4, 1e-6);
  s.walls.clear();
  s.particles = {
      dem::ParticleInit{0.01, 0.01, 1000.0, 0, dem::Vec3(0, 0, 0), dem::Vec3(1, 0, 0), dem::Vec3::Zero(), true},
      dem::ParticleInit{0.01, 0.01, 1000.0, 0, dem::Vec3(0.0205, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), false}};
  s.motions = {dem::PrescribedMotion{0, dem::Vec3(0, 0, 0), {{0.0, dem::Vec3(1, 0, 0)}}}};
  dem::Simulation sim(s);
  for (int i = 0; i < 3000; ++i) sim.step();
  EXPECT_NEAR(sim.state().position(0, 0), sim.time(), 1e-15);
  EXPECT_NEAR(sim.state().velocity(0, 1), 2.0, 1e-6);
}

}  // namespace
