// SPDX-License-Identifier: MIT
// The Hertz normal law (thesis eq 3.12–3.13) against its closed forms, and the elastic Hertz
// collision through the whole core (pair table, force field, integrator).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/hertz.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/contact/registry.hpp"
#include "dem/timestep/timestep_control.hpp"
#include "normal_hertz_fixture.hpp"

namespace normal_hertz_test {

using namespace dem::laws;
using hertz_test::effective_modulus;
using hertz_test::mover_mass;
using hertz_test::reduced_radius;

constexpr double kE = 5.4945054945054945e6;  // E* [Pa] of the LAMMPS Hertz impact
constexpr double kR = 9.0909090909090909e-3;  // R* [m]

TEST(HertzLaw, ForceGrowsAsOverlapToTheThreeHalves) {
  for (const double delta : {1e-7, 3e-5, 2e-4}) {
    EXPECT_NEAR(hertz_force(kE, kR, 4.0 * delta) / hertz_force(kE, kR, delta), 8.0, 1e-12);
  }
  EXPECT_NEAR(hertz_force(kE, kR, 1e-4), 4.0 / 3.0 * kE * std::sqrt(kR) * 1e-6, 1e-15);
}

TEST(HertzLaw, MatchesTheLammpsStaticProbe) {
  // Static probe with LAMMPS 29 Sep 2021: hertz/material E = 1e7, ν = 0.3, r1 = r2 = 0.01 m,
  // δ = 1e-4 m.
  EXPECT_NEAR(hertz_force(1e7 / (2.0 * 0.91), 0.005, 1e-4), 0.518026945924, 1e-11);
}

TEST(HertzLaw, StiffnessIsTheDerivativeOfTheForce) {
  for (const double delta : {1e-6, 1e-4, 5e-4}) {
    const double h = 1e-5 * delta;
    const double fd = (hertz_force(kE, kR, delta + h) - hertz_force(kE, kR, delta - h)) / (2.0 * h);
    EXPECT_NEAR(hertz_stiffness(kE, kR, delta), fd, 1e-8 * fd) << "δ = " << delta;
    EXPECT_NEAR(hertz_stiffness(kE, kR, delta), 2.0 * kE * std::sqrt(kR * delta), 1e-9 * fd);
  }
}

TEST(HertzLaw, EnergyIsTheWorkOfTheForce) {
  for (const double delta : {1e-6, 1e-4, 5e-4}) {
    const double h = 1e-5 * delta;
    const double fd = (hertz_energy(kE, kR, delta + h) - hertz_energy(kE, kR, delta - h)) / (2.0 * h);
    EXPECT_NEAR(fd, hertz_force(kE, kR, delta), 1e-8 * fd);
    EXPECT_NEAR(hertz_energy(kE, kR, delta), 0.4 * hertz_force(kE, kR, delta) * delta, 1e-15);
  }
}

TEST(HertzLaw, NothingOutOfContact) {
  EXPECT_EQ(hertz_force(kE, kR, 0.0), 0.0);
  EXPECT_EQ(hertz_force(kE, kR, -1e-4), 0.0);
  EXPECT_EQ(hertz_stiffness(kE, kR, -1e-4), 0.0);
  EXPECT_EQ(hertz_energy(kE, kR, -1e-4), 0.0);
}

TEST(HertzLaw, MaxOverlapStoresTheImpactEnergy) {
  const double m = 4.2e-3, v = 3.0;
  const double peak = hertz_max_overlap(m, kE, kR, v);
  EXPECT_NEAR(hertz_energy(kE, kR, peak), 0.5 * m * v * v, 1e-13 * m * v * v);
}

TEST(HertzLaw, DurationConstantIsFourFifthsOfBetaTwoFifthsOneHalf) {
  EXPECT_NEAR(hertz_duration_constant(), 0.8 * std::beta(0.4, 0.5), 1e-14);
  EXPECT_NEAR(hertz_duration_constant(), 2.9432751843247047, 1e-14);
  // t_c = 2.868266 (m*² / (R* E*² v))^{1/5} and 3.218065 (m*/k_n)^{2/5} v^{−1/5}.
  EXPECT_NEAR(hertz_duration_constant() * std::pow(15.0 / 16.0, 0.4), 2.8682656991953315, 1e-13);
  EXPECT_NEAR(hertz_duration_constant() * std::pow(1.25, 0.4), 3.2180654597190435, 1e-13);
}

TEST(HertzLaw, DurationAgreesWithTheLammpsRun) {
  // LAMMPS 29 Sep 2021: elastic impact at 1 m/s, dt = 1e-6, measured t_c = 1.654862e-3 s and
  // δ_max = 5.622519e-4 m (the closed form with the constant 2.8678 gives 1.654594e-3).
  EXPECT_NEAR(hertz_test::elastic_duration(1.0), 1.654862e-3, 3e-9);
  EXPECT_NEAR(hertz_max_overlap(mover_mass(), effective_modulus(), reduced_radius(), 1.0), 5.622519e-4, 2e-10);
}

TEST(HertzNormal, RegistryRowNamesTheModulusAndBothReferenceCodes) {
  const dem::SubModelInfo* row = dem::find_sub_model(dem::Slot::normal, "hertz");
  ASSERT_NE(row, nullptr);
  ASSERT_EQ(row->properties.size(), 1U);
  EXPECT_EQ(row->properties[0], "effective_modulus");
  EXPECT_NE(row->lammps.find("hertz/material"), std::string_view::npos);
  EXPECT_NE(row->yade.find("MindlinPhys"), std::string_view::npos);
}

TEST(HertzNormal, NeedsTheEffectiveModulus) {
  dem::ModelChoice choice;
  choice.normal = "hertz";
  EXPECT_THROW(static_cast<void>(dem::make_pair_law(choice, dem::PairProperties{})), dem::ModelError);
}

TEST(HertzNormal, EvaluatesTheLawWithTheContactsReducedRadius) {
  dem::ModelChoice choice;
  choice.normal = "hertz";
  dem::PairProperties p;
  p.effective_modulus = kE;
  const dem::PairLaw law = dem::make_pair_law(choice, p);
  dem::SphereState a{dem::Vec3(0, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), 0.01, 0.01, 1.0};
  dem::SphereState b{dem::Vec3(0.11 - 2e-4, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), 0.1, 0.1, 0.0};
  const dem::ContactGeometry g = dem::pair_geometry(a, b);
  const dem::ContactOutcome c = dem::evaluate_contact(law, g, dem::ContactHistory{}, 1e-6);
  EXPECT_TRUE(c.contact);
  EXPECT_NEAR(c.normal_force, hertz_force(kE, kR, 2e-4), 1e-12);
  EXPECT_NEAR(c.elastic_energy, hertz_energy(kE, kR, 2e-4), 1e-16);
  EXPECT_NEAR(c.force_on_p.x(), -c.normal_force, 1e-15);  // n points from q to p: −x
  EXPECT_DOUBLE_EQ(dem::interaction_range(law, {0.11, 0.11, kR}), 0.11);
}

TEST(HertzNormal, CollisionStiffnessIsTheTangentAtTheImpactOverlap) {
  const dem::HertzNormal n{kE};
  const double peak = hertz_max_overlap(4e-3, kE, kR, 2.0);
  EXPECT_NEAR(n.collision_stiffness({4e-3, kR, 2.0}), hertz_stiffness(kE, kR, peak), 1e-9);
}

/// Elastic impact through the core at `steps` per collision.
hertz_test::ImpactFigures elastic_impact(dem::SchemeId scheme, double steps, double speed,
                                         bool wall = false) {
  const double tc = wall ? hertz_contact_duration(mover_mass(), effective_modulus(),
                                                  hertz_test::kRadius, speed)
                         : hertz_test::elastic_duration(speed);
  dem::Simulation sim(hertz_test::impact(scheme, tc / steps, "none", {}, speed, wall));
  return hertz_test::measure_impact(sim, speed, 12.0 * tc / steps + 1.5 * tc, wall);
}

TEST(HertzCollision, ContactTimeAndMaxOverlapWithinPointTwoPercentAt100Steps) {
  for (const auto scheme : {dem::SchemeId::velocity_verlet, dem::SchemeId::rk4, dem::SchemeId::leapfrog}) {
    for (const double v : {0.1, 1.0, 4.0}) {
      const hertz_test::ImpactFigures f = elastic_impact(scheme, 100.0, v);
      const double tc = hertz_test::elastic_duration(v);
      const double dmax = hertz_max_overlap(mover_mass(), effective_modulus(), reduced_radius(), v);
      const char* name = dem::scheme_info(scheme).name.data();
      EXPECT_NEAR(f.duration, tc, 2e-3 * tc) << name << " v = " << v;
      EXPECT_NEAR(f.max_overlap, dmax, 2e-3 * dmax) << name << " v = " << v;
      EXPECT_NEAR(f.max_force, hertz_force(effective_modulus(), reduced_radius(), dmax),
                  3e-3 * hertz_force(effective_modulus(), reduced_radius(), dmax))
          << name << " v = " << v;
      EXPECT_NEAR(f.restitution, 1.0, 1e-3) << name << " v = " << v;
    }
  }
}

TEST(HertzCollision, ContactTimeFollowsTheClosedFormAgainstAPlaneWallWithRStarEqualR) {
  // A plane wall of the same material: E* as for the pair, R* = r.
  const double v = 1.0;
  const hertz_test::ImpactFigures f = elastic_impact(dem::SchemeId::velocity_verlet, 100.0, v, true);
  const double tc = hertz_contact_duration(mover_mass(), effective_modulus(), hertz_test::kRadius, v);
  const double dmax = hertz_max_overlap(mover_mass(), effective_modulus(), hertz_test::kRadius, v);
  EXPECT_NEAR(f.duration, tc, 2e-3 * tc);
  EXPECT_NEAR(f.max_overlap, dmax, 2e-3 * dmax);
}

TEST(HertzCollision, TwoMobileSpheresCollideWithTheReducedMass) {
  // Two equal spheres at ±0.5 m/s: m* = m/2, R* = r/2, relative speed 1 m/s.
  const double v = 1.0, m_star = 0.5 * mover_mass(), r_star = 0.5 * hertz_test::kRadius;
  const double tc = hertz_contact_duration(m_star, effective_modulus(), r_star, v);
  const double dt = tc / 100.0;
  dem::SimulationSetup s = hertz_test::impact(dem::SchemeId::velocity_verlet, dt, "none");
  s.particles[0].velocity = dem::Vec3(0.5, 0, 0);
  s.particles[1] = dem::ParticleInit{hertz_test::kRadius, hertz_test::kRadius, hertz_test::kDensity, 0,
                                     dem::Vec3(0.02 + 10.37 * v * dt, 0, 0), dem::Vec3(-0.5, 0, 0), dem::Vec3::Zero(), false};
  dem::Simulation sim(s);
  const hertz_test::ImpactFigures f = hertz_test::measure_impact(sim, 0.5, 12.0 * dt + 1.5 * tc);
  const double dmax = hertz_max_overlap(m_star, effective_modulus(), r_star, v);
  EXPECT_NEAR(f.duration, tc, 2e-3 * tc);
  EXPECT_NEAR(f.max_overlap, dmax, 2e-3 * dmax);
  EXPECT_NEAR(sim.state().velocity(0, 1), 0.5, 1e-3);
}

/// Relative kinetic-energy change of an elastic velocity-Verlet impact whose onset lies `phase`
/// of a step after a step boundary, at `steps` per collision.
double verlet_energy_error(double steps, double phase) {
  const double v = 1.0;
  const double tc = hertz_test::elastic_duration(v);
  const double dt = tc / steps;
  dem::SimulationSetup s = hertz_test::impact(dem::SchemeId::velocity_verlet, dt, "none", {}, v);
  s.particles[1].position.x() += (phase - 0.37) * v * dt;  // the fixture's onset is at 10.37 Δt
  dem::Simulation sim(s);
  const double e0 = sim.kinetic_energy();
  while (sim.time() < 1.5 * tc) sim.step();
  return std::abs(sim.kinetic_energy() - e0) / e0;
}

// Velocity Verlet conserves the energy of the elastic impact up to its entry/exit error, which
// depends on where the contact starts within a step and falls as Δt^{5/2} (F'' ∝ δ^{−1/2} is
// singular at δ = 0). Over all onset phases: ≤ 2.5e-6 at 200 steps, ≤ 1e-6 from 300 steps.
TEST(HertzCollision, VelocityVerletConservesEnergyWithin1em6From300StepsPerCollision) {
  double worst200 = 0.0, worst300 = 0.0;
  for (int k = 0; k < 20; ++k) {
    worst200 = std::max(worst200, verlet_energy_error(200.0, 0.05 * k));
    worst300 = std::max(worst300, verlet_energy_error(300.0, 0.05 * k));
  }
  EXPECT_LT(worst200, 3e-6);
  EXPECT_LT(worst300, 1e-6);
  EXPECT_LT(verlet_energy_error(200.0, 0.5), 1e-7);  // onset half a step after a boundary
}

TEST(HertzCollision, VelocityVerletEnergyGapDuringContactIsSmall) {
  const double v = 1.0;
  const double tc = hertz_test::elastic_duration(v);
  dem::Simulation sim(hertz_test::impact(dem::SchemeId::velocity_verlet, tc / 200.0, "none", {}, v));
  const double e0 = sim.kinetic_energy();
  double worst = 0.0;
  while (sim.time() < 1.5 * tc) {
    sim.step();
    worst = std::max(worst, std::abs(sim.kinetic_energy() + sim.force_field().elastic_energy() - e0) / e0);
  }
  EXPECT_LT(worst, 1e-3);  // O((ωΔt)²) shadow-energy gap while in contact
}

TEST(HertzTimestep, AutomaticStepResolvesTheCollisionWithAtLeastTheAskedSteps) {
  const double v = 1.0;
  dem::SimulationSetup s = hertz_test::impact(dem::SchemeId::velocity_verlet, 1.0, "none", {}, v);
  dem::ParticleProperties props;
  dem::KinematicState state;
  dem::build_particles(s.particles, props, state);
  const dem::PairTable table(s.materials, s.mixing, s.pair_overrides, s.model);
  const dem::TimestepLimits limits = dem::timestep_limits(props, state, table, dem::Vec3::Zero(), false, 20.0);
  // The estimate uses the impact at twice the fastest speed and the linearised stiffness there:
  // it must not exceed the true duration of that impact.
  EXPECT_LT(limits.collision_duration, hertz_test::elastic_duration(2.0 * v));
  EXPECT_GT(limits.collision_duration, 0.7 * hertz_test::elastic_duration(2.0 * v));
  EXPECT_GE(hertz_test::elastic_duration(v) / dem::automatic_timestep(limits), 20.0);
}

}  // namespace
