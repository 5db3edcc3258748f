// SPDX-License-Identifier: MIT
// External fields (thesis §3.7, §6.5): drag correlation, Reynolds number, buoyancy, pressure
// gradient, virtual mass, plug-flow zones with a linear ramp.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/fields/drag_laws.hpp"
#include "dem/fields/external_fields.hpp"
#include "dem/simulation/simulation.hpp"

namespace fields_test {

using dem::Vec3;

TEST(BrennDrag, FollowsEachBranchOfEquation348) {
  EXPECT_DOUBLE_EQ(dem::laws::brenn_drag_coefficient(0.1), 240.0);
  EXPECT_DOUBLE_EQ(dem::laws::brenn_drag_coefficient(1.0), 24.0 * 1.1);
  EXPECT_DOUBLE_EQ(dem::laws::brenn_drag_coefficient(10.0), 2.4 * (1.0 + 0.11 * std::pow(10.0, 0.81)));
  EXPECT_DOUBLE_EQ(dem::laws::brenn_drag_coefficient(100.0), 0.24 * (1.0 + 0.189 * std::pow(100.0, 0.632)));
  EXPECT_DOUBLE_EQ(dem::laws::brenn_drag_coefficient(500.0), 0.048 * (1.0 + 0.15 * std::pow(500.0, 0.687)));
  EXPECT_DOUBLE_EQ(dem::laws::brenn_drag_coefficient(1e4), 0.44);
  EXPECT_DOUBLE_EQ(dem::laws::brenn_drag_coefficient(1e6), 0.1);
}

TEST(BrennDrag, BranchesAreNearlyContinuous) {
  // The published correlation is piecewise; its jumps are a few per cent at most.
  for (const double re : {0.2, 2.0, 21.0, 200.0, 1000.0}) {
    const double below = dem::laws::brenn_drag_coefficient(re * (1 - 1e-9));
    const double above = dem::laws::brenn_drag_coefficient(re * (1 + 1e-9));
    EXPECT_LT(std::abs(above / below - 1.0), 0.06) << "Re = " << re;
  }
}

TEST(Drag, StokesLimitIsSixPiEtaRU) {
  // Re ≤ 0.2: F = ½ρ u² (24/Re) π r² = 6π η r u.
  const double r = 10e-6, u = 0.01, rho = 1.205, eta = 1.81e-5;
  ASSERT_LT(dem::laws::particle_reynolds(rho, u, 2 * r, eta), 0.2);
  const Vec3 f = dem::laws::sphere_drag(Vec3(u, 0, 0), r, rho, eta);
  EXPECT_NEAR(f.x(), 6.0 * std::numbers::pi * eta * r * u, 1e-12 * 6.0 * std::numbers::pi * eta * r * u);
  EXPECT_EQ(dem::laws::sphere_drag(Vec3::Zero(), r, rho, eta), Vec3::Zero());
}

TEST(Buoyancy, UsesTheDensityDifference) {
  dem::Fluid fluid;
  fluid.density = 1000.0;
  fluid.buoyancy = true;
  const double r = 0.01, rho = 2500.0;
  const double volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const dem::FieldInput in{Vec3::Zero(), Vec3::Zero(), r, rho, rho * volume, 0.0};
  const Vec3 f = fluid.gravity_force(in, Vec3(0, 0, -9.81));
  EXPECT_NEAR(f.z(), -volume * 1500.0 * 9.81, 1e-15);
}

TEST(PressureGradient, PushesDownTheGradient) {
  const Vec3 f = dem::laws::pressure_gradient_force(Vec3(1000.0, 0, 0), 0.01);
  EXPECT_NEAR(f.x(), -4.0 / 3.0 * std::numbers::pi * 1e-6 * 1000.0, 1e-15);
}

TEST(PlugFlow, RampsLinearlyThenHoldsInsideItsZones) {
  dem::FluidVelocity v;
  v.zones = {{Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(0, -1, 0)},
             {Vec3(0, 0, 1), Vec3(1, 1, 2), Vec3(0, 0, 1)}};
  v.speed = 30.0;
  v.ramp_time = 13e-3;
  EXPECT_EQ(v.at(Vec3(0.5, 0.5, 0.5), 0.0), Vec3::Zero());
  EXPECT_NEAR(v.at(Vec3(0.5, 0.5, 0.5), 6.5e-3).y(), -15.0, 1e-12);
  EXPECT_NEAR(v.at(Vec3(0.5, 0.5, 0.5), 1.0).y(), -30.0, 1e-12);
  EXPECT_NEAR(v.at(Vec3(0.5, 0.5, 1.5), 1.0).z(), 30.0, 1e-12);
  EXPECT_EQ(v.at(Vec3(5, 5, 5), 1.0), Vec3::Zero());  // outside every zone: at rest
}

/// One sphere released at rest in a uniform air stream.
dem::SimulationSetup in_air_stream(bool virtual_mass) {
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "lactose";
  m.density = 1550.0;
  m.normal_stiffness = 1e3;
  s.materials = {m};
  s.particles = {dem::ParticleInit{50e-6, 50e-6, 1550.0, 0, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), false}};
  dem::Fluid air;
  air.velocity.uniform = Vec3(1.0, 0, 0);
  air.virtual_mass = virtual_mass;
  s.fields.fluid = air;
  s.scheme = dem::SchemeId::rk4;
  s.timestep = 1e-5;
  return s;
}

TEST(Drag, AcceleratesAParticleTowardsTheFluidVelocity) {
  dem::Simulation sim(in_air_stream(false));
  double previous = 0.0;
  for (int i = 0; i < 20000; ++i) {
    sim.step();
    const double u = sim.state().velocity(0, 0);
    ASSERT_GE(u, previous);  // monotone approach
    previous = u;
  }
  EXPECT_GT(previous, 0.99);  // relaxation time ρ_p d²/(18 η) ≈ 0.05 s ≪ 0.2 s
  EXPECT_LT(previous, 1.0);
  EXPECT_LT(sim.energy().fluid_work, 0.5 * sim.particles().mass[0] * 1.0 + 1e-15);
  // KE comes from drag work. The ledger integrates drag power with the rectangle rule at commit
  // times (first order in Δt), so the balance holds to O(Δt/τ), τ = ρ_p d²/(18 η) = 0.048 s.
  const double tau = 1550.0 * std::pow(100e-6, 2) / (18.0 * 1.81e-5);
  EXPECT_NEAR(sim.energy().balance(), 0.0, 1e-5 / tau * sim.energy().kinetic);
}

TEST(VirtualMass, SlowsTheInitialAccelerationByTheAddedInertia) {
  dem::Simulation plain(in_air_stream(false));
  dem::Simulation added(in_air_stream(true));
  plain.step();
  added.step();
  const double m = plain.particles().mass[0];
  const double added_mass = 0.5 * 1.205 * 4.0 / 3.0 * std::numbers::pi * std::pow(50e-6, 3);
  EXPECT_NEAR(added.state().velocity(0, 0) / plain.state().velocity(0, 0), m / (m + added_mass), 1e-6);
}

}  // namespace
