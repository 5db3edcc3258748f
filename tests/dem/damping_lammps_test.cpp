// SPDX-License-Identifier: MIT
// LAMMPS' own damping formulas (pair_granular.cpp, 2021) run in the core with LAMMPS' velocity
// Verlet, against the restitutions measured with the installed LAMMPS (29 Sep 2021).
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/dashpot_restitution.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "normal_hertz_fixture.hpp"

namespace damping_lammps_test {

TEST(LammpsTsujiFactor, IsTheTsujiPolynomial) {
  EXPECT_NEAR(dem::laws::lammps_tsuji_factor(0.5), 0.34074, 1e-5);   // LAMMPS' Tsuji α
  EXPECT_NEAR(dem::laws::lammps_tsuji_factor(0.9), 0.05290, 1e-5);
  EXPECT_NEAR(dem::laws::lammps_tsuji_factor(0.3666513616), std::sqrt(5.0) * 0.2154537619662468, 1e-9);
}

TEST(LammpsTsujiFactor, GivesPointSixOneSixForANominalOneHalfWithHertz) {
  // Exact Hertz-ODE rebound with that α: 0.61608 (0.5), 0.92836 (0.9).
  EXPECT_NEAR(dem::laws::hertz_tsuji_restitution(dem::laws::lammps_tsuji_factor(0.5), false), 0.61608, 1e-5);
  EXPECT_NEAR(dem::laws::hertz_tsuji_restitution(dem::laws::lammps_tsuji_factor(0.9), false), 0.92836, 1e-5);
  // With `limit_damping` (clamp_tensile): 0.646 (docs/physics-normal.md).
  EXPECT_NEAR(dem::laws::hertz_tsuji_restitution(dem::laws::lammps_tsuji_factor(0.5), true), 0.646, 5e-4);
}

/// Rebound of the Hertz impact measured with LAMMPS (E = 1e7, ν = 0.3, r = 0.01 onto a frozen
/// r = 0.1, ρ = 1000) at `speed` with LAMMPS' time step 1e-6 s and velocity Verlet. The measured
/// deck let the contact begin on a step boundary (gap = 10 v Δt here); other onset phases move the
/// tsuji rebound by up to −6e-5 (0.616031 … 0.616090 at 1 m/s).
double lammps_hertz_rebound(const std::string& damping, double speed,
                            const std::function<void(dem::SimulationSetup&)>& configure) {
  const double dt = 1e-6;
  const double tc = hertz_test::elastic_duration(speed);
  dem::SimulationSetup s = hertz_test::impact(dem::SchemeId::velocity_verlet, dt, damping, configure, speed);
  s.particles[1].position.x() -= 0.37 * speed * dt;  // onset on a step boundary
  dem::Simulation sim(s);
  while (sim.time() < 12.0 * dt + 1.5 * tc) sim.step();
  return -sim.state().velocity(0, 0) / speed;
}

TEST(LammpsTsujiCollision, ReproducesTheMeasuredReboundOfLammpsHertzTsuji) {
  const auto nominal = [](double e) {
    return [e](dem::SimulationSetup& s) { s.materials[0].restitution = e; };
  };
  // LAMMPS (dt = 1e-6): 0.616090 (v = 1), 0.616049 (v = 4); 0.928360 / 0.928366 for 0.9.
  EXPECT_NEAR(lammps_hertz_rebound("lammps_tsuji", 1.0, nominal(0.5)), 0.616090, 2e-6);
  EXPECT_NEAR(lammps_hertz_rebound("lammps_tsuji", 4.0, nominal(0.5)), 0.616049, 2e-6);
  EXPECT_NEAR(lammps_hertz_rebound("lammps_tsuji", 1.0, nominal(0.9)), 0.928360, 2e-6);
  // The workaround e_in = 0.3666513616 for a target 0.5: LAMMPS 0.499961 (v = 1), 0.499998 (v = 4).
  EXPECT_NEAR(lammps_hertz_rebound("lammps_tsuji", 1.0, nominal(0.3666513616)), 0.499961, 2e-6);
  EXPECT_NEAR(lammps_hertz_rebound("lammps_tsuji", 4.0, nominal(0.3666513616)), 0.499998, 2e-6);
}

TEST(LammpsViscoelasticCollision, ReproducesTheMeasuredSpeedDependentRebound) {
  // Measured with LAMMPS: `damping viscoelastic` η₀ = 1e4 → e = 0.98727 at 1 m/s, 0.98325 at
  // 4 m/s.
  const auto rate = [](dem::SimulationSetup& s) { s.materials[0].viscoelastic_damping = 1e4; };
  EXPECT_NEAR(lammps_hertz_rebound("lammps_viscoelastic", 1.0, rate), 0.98727, 1e-5);
  EXPECT_NEAR(lammps_hertz_rebound("lammps_viscoelastic", 4.0, rate), 0.98325, 1e-5);
}

TEST(LammpsViscoelasticDamping, CoefficientIsRateTimesContactRadiusTimesReducedMass) {
  dem::ContactGeometry g{};
  g.overlap = 2e-4;
  g.reduced_radius = 5e-3;
  g.reduced_mass = 3e-3;
  const dem::LammpsViscoelasticDamping d{1e4};
  EXPECT_NEAR(d.coefficient(g, {}), 1e4 * std::sqrt(5e-3 * 2e-4) * 3e-3, 1e-15);
  g.overlap = -1e-6;
  EXPECT_EQ(d.coefficient(g, {}), 0.0);
}

/// The linear impact measured with LAMMPS: linear spring k = 1e5, r = 0.01 at 4 m/s onto a
/// frozen r = 0.1 sphere whose surface is 2e-4 m away, ρ = 1000, η from eq 3.11 for ε; velocity
/// Verlet.
double lammps_linear_rebound(const std::string& damping, double e, double dt) {
  const double m = 4.0 / 3.0 * std::numbers::pi * 1000.0 * 1e-6;
  const double eta = dem::laws::restitution_damping_coefficient(e, m, 1e5);
  dem::SimulationSetup s;
  dem::MaterialProperties mat;
  mat.name = "sphere";
  mat.density = 1000.0;
  mat.normal_stiffness = 1e5;
  mat.damping_coefficient = eta;
  mat.damping_rate = eta / m;
  s.materials = {mat};
  s.model.damping = damping;
  s.particles = {
      dem::ParticleInit{0.01, 0.01, 1000.0, 0, dem::Vec3(-0.0102, 0, 0), dem::Vec3(4.0, 0, 0), dem::Vec3::Zero(), false},
      dem::ParticleInit{0.1, 0.1, 1000.0, 0, dem::Vec3(0.1, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), true}};
  s.scheme = dem::SchemeId::velocity_verlet;
  s.scheme_settings.rotation = false;
  s.scheme_settings.length_scale = 0.01;
  s.timestep = dt;
  dem::Simulation sim(s);
  const auto steps = static_cast<int>(std::lround(0.02 / dt));
  for (int n = 0; n < steps; ++n) sim.step();
  return -sim.state().velocity(0, 0) / 4.0;
}

TEST(LammpsVelocityCollision, ReproducesLammpsCaseTwoToAllPrintedDigits) {
  // Measured with `damping velocity` and `damping mass_velocity` (identical with fix freeze).
  for (const std::string damping : {"lammps_velocity", "lammps_mass_velocity"}) {
    EXPECT_NEAR(lammps_linear_rebound(damping, 0.5, 5e-5), 0.538947, 1e-6) << damping;
    EXPECT_NEAR(lammps_linear_rebound(damping, 0.5, 1e-5), 0.503641, 1e-6) << damping;
    EXPECT_NEAR(lammps_linear_rebound(damping, 0.9, 5e-5), 0.916263, 1e-6) << damping;
    EXPECT_NEAR(lammps_linear_rebound(damping, 0.9, 5e-6), 0.900930, 1e-6) << damping;
  }
}

}  // namespace
