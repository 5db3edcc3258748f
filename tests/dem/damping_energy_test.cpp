// SPDX-License-Identifier: MIT
// Every dissipative normal model with Hertz: mechanical energy never rises, the energy ledger
// accounts for the dashpot's work, and clamp_tensile keeps F_n ≥ 0.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/pair_table.hpp"
#include "normal_hertz_fixture.hpp"

namespace damping_energy_test {

/// Gives every damping model of this test what it reads, sized for a clearly dissipative impact.
void dissipative_properties(dem::SimulationSetup& s) {
  dem::MaterialProperties& m = s.materials[0];
  m.restitution = 0.5;
  m.normal_stiffness = 1e5;
  m.damping_coefficient = 5.0;  // lammps_velocity's η [kg/s]
  m.viscous_modulus = 200.0;    // kuwabara_kono's E' [Pa·s]
  m.damping_rate = 2000.0;       // [1/s]
  m.viscoelastic_damping = 1e6;  // [1/(m·s)]
}

class DissipativeHertz : public ::testing::TestWithParam<std::tuple<std::string, bool>> {};

TEST_P(DissipativeHertz, MechanicalEnergyNeverRisesAndTheLedgerBalances) {
  const auto& [damping, clamp] = GetParam();
  const double v = 1.0;
  const double tc = hertz_test::elastic_duration(v);
  const double dt = tc / 2000.0;
  dem::Simulation sim(hertz_test::impact(dem::SchemeId::rk4, dt, damping, [&](dem::SimulationSetup& s) {
    dissipative_properties(s);
    s.model.clamp_tensile = clamp;
  }, v));
  const double e0 = sim.energy().balance();
  double previous = sim.kinetic_energy();
  while (sim.time() < 12.0 * dt + 2.0 * tc) {
    sim.step();
    const double now = sim.kinetic_energy() + sim.force_field().elastic_energy();
    ASSERT_LE(now, previous * (1.0 + 1e-10)) << damping << ": energy rose at t = " << sim.time();
    previous = now;
  }
  EXPECT_LT(sim.kinetic_energy(), 0.99 * e0) << damping << " dissipates";
  // The ledger sums the dashpot power at the end of each step: exact to O(Δt) for dashpots that
  // vanish at δ = 0, off by up to η v² Δt per jump for the constant-η ones (0.2 % here).
  EXPECT_NEAR(sim.energy().balance(), e0, 5e-3 * e0) << damping << ": dissipated work is accounted";
}

INSTANTIATE_TEST_SUITE_P(
    AllDampingModels, DissipativeHertz,
    ::testing::Combine(::testing::Values("restitution", "tsuji", "kuwabara_kono", "lammps_velocity",
                                         "lammps_mass_velocity", "lammps_viscoelastic", "lammps_tsuji",
                                         "yade_viscel", "yade_mindlin"),
                       ::testing::Bool()),
    [](const auto& param_info) {
      return std::get<0>(param_info.param) + (std::get<1>(param_info.param) ? "_clamped" : "");
    });

TEST(ClampTensile, KeepsTheTotalNormalForceNonNegativeWhileSeparating) {
  dem::ModelChoice choice;
  choice.normal = "hertz";
  choice.damping = "lammps_velocity";
  dem::PairProperties p;
  p.effective_modulus = hertz_test::effective_modulus();
  p.damping_coefficient = 50.0;
  dem::SphereState a{dem::Vec3(0, 0, 0), dem::Vec3(-1, 0, 0), dem::Vec3::Zero(), 0.01, 0.01, 200.0};
  dem::SphereState b{dem::Vec3(0.11 - 1e-5, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), 0.1, 0.1, 0.0};
  const dem::ContactGeometry g = dem::pair_geometry(a, b);  // separating at 1 m/s, δ = 10 µm
  EXPECT_LT(dem::evaluate_contact(dem::make_pair_law(choice, p), g, {}, 1e-6).normal_force, 0.0);
  choice.clamp_tensile = true;
  EXPECT_EQ(dem::evaluate_contact(dem::make_pair_law(choice, p), g, {}, 1e-6).normal_force, 0.0);
}

}  // namespace
