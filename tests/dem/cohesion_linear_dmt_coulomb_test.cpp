// SPDX-License-Identifier: MIT
// Linear cohesion (thesis eq 3.33, E.5), DMT adhesion and the Coulomb force (eq 3.36) against
// their closed forms; a settling cohesive pair conserves what it must and ends at δ_eq.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/coulomb.hpp"
#include "dem/contact/laws/dmt.hpp"
#include "dem/contact/laws/hertz.hpp"
#include "dem/contact/laws/linear_cohesion.hpp"
#include "dem/contact/registry.hpp"
#include "dem/simulation/simulation.hpp"

namespace cohesion_linear_dmt_coulomb_test {

constexpr double kPi = std::numbers::pi;

/// A head-on pair of 5 mm spheres with effect radii 7.5 mm at body overlap δ, charges q_p q_q.
dem::ContactGeometry pair_at(double overlap, double charge_product = 0.0) {
  dem::ContactGeometry g{};
  g.normal = dem::Vec3::UnitX();
  g.overlap = overlap;
  g.distance = 0.01 - overlap;
  g.effect_overlap = 0.015 - g.distance;
  g.reduced_radius = 2.5e-3;
  g.reduced_mass = 4.0e-3;
  g.contact_distance = 0.01;
  g.effect_distance = 0.015;
  g.branch_p = -(0.005 - 0.5 * overlap) * g.normal;
  g.branch_q = (0.005 - 0.5 * overlap) * g.normal;
  g.contact_velocity = dem::Vec3::Zero();
  g.tangential_velocity = dem::Vec3::Zero();
  g.relative_angular_velocity = dem::Vec3::Zero();
  g.normal_speed = 0.0;
  g.charge_product = charge_product;
  return g;
}

/// Evaluates a cohesion sub-model at geometry g with no normal force.
template <class Model>
dem::CohesionResponse cohesion(const Model& m, const dem::ContactGeometry& g,
                               const dem::NormalResponse& elastic = {}) {
  const dem::ContactHistory committed;
  const dem::ContactPolicies policies;
  const dem::ContactInput in{g, committed, 1e-6, policies};
  dem::ContactHistory next;
  return m.evaluate(in, elastic, next);
}

TEST(LinearCohesion, ForceIsMinusKcTimesEffectOverlapAndEnergyHalfKcSquared) {
  const dem::LinearCohesion model{100.0};
  for (const double delta : {-0.0049, -2e-3, 0.0, 1e-5}) {
    const dem::ContactGeometry g = pair_at(delta);
    const auto r = cohesion(model, g);
    EXPECT_TRUE(r.active);
    EXPECT_FALSE(r.contact) << "cohesion alone is not a contact";
    EXPECT_NEAR(r.force, -100.0 * g.effect_overlap, 1e-15);
    EXPECT_NEAR(r.energy, -50.0 * g.effect_overlap * g.effect_overlap, 1e-18);
  }
  const auto apart = cohesion(model, pair_at(-0.006));
  EXPECT_FALSE(apart.active);
  EXPECT_EQ(apart.force, 0.0);
  EXPECT_DOUBLE_EQ(model.range({0.01, 0.015, 2.5e-3}), 0.015);
}

TEST(LinearCohesion, TotalForceIsEquationE5) {
  const dem::PairLaw law{dem::LinearNormal{1e5}, dem::NoDamping{}, dem::NoTangential{},
                         dem::LinearCohesion{100.0}, dem::NoRolling{}, {}};
  for (const double delta : {-3e-3, -1e-4, 2e-6, 1e-4}) {
    const dem::ContactGeometry g = pair_at(delta);
    const dem::ContactOutcome c = dem::evaluate_contact(law, g, {}, 1e-6);
    EXPECT_TRUE(c.interacting);
    EXPECT_EQ(c.contact, delta > 0.0);
    EXPECT_NEAR(c.normal_force, 1e5 * std::max(delta, 0.0) - 100.0 * g.effect_overlap, 1e-12);
  }
  EXPECT_NEAR(dem::laws::linear_cohesion_equilibrium_overlap(1e5, 100.0, 5e-3), 5e-3 / 999.0, 1e-20);
  EXPECT_NEAR(dem::evaluate_contact(law, pair_at(5e-3 / 999.0), {}, 1e-6).normal_force, 0.0, 1e-12);
}

TEST(DmtCohesion, PullOffIsFourPiGammaR) {
  const double gamma = 0.5, r = 2.5e-3, e_star = 1e8;
  const dem::DmtCohesion model{gamma};
  const double pulloff = 4.0 * kPi * gamma * r;
  EXPECT_NEAR(dem::laws::dmt_pulloff_force(gamma, r), pulloff, 1e-15);
  for (const double delta : {0.0, 1e-7, 1e-5}) {
    const auto c = cohesion(model, pair_at(delta));
    EXPECT_TRUE(c.active);
    EXPECT_NEAR(c.force, -pulloff, 1e-15);
    EXPECT_NEAR(c.energy, -pulloff * delta, 1e-20);
    EXPECT_NEAR(c.pulloff_force, pulloff, 1e-15);
  }
  EXPECT_FALSE(cohesion(model, pair_at(-1e-9)).active);
  // With Hertz the total is F_H − 4πγR*: its largest tension, at δ → 0⁺, is the pull-off force.
  const dem::PairLaw law{dem::HertzNormal{e_star}, dem::NoDamping{}, dem::NoTangential{},
                         dem::DmtCohesion{gamma}, dem::NoRolling{}, {}};
  double tension = 0.0;
  for (double delta = 1e-12; delta < 1e-5; delta *= 1.5) {
    const double f = dem::evaluate_contact(law, pair_at(delta), {}, 1e-6).normal_force;
    EXPECT_NEAR(f, dem::laws::hertz_force(e_star, r, delta) - pulloff, 1e-14);
    tension = std::max(tension, -f);
  }
  EXPECT_NEAR(tension, pulloff, 1e-9 * pulloff);
}

TEST(CoulombCohesion, ForceFollowsEquation336AndStopsAtTheCutoff) {
  const double eps_r = 2.0, cutoff = 0.02;
  const dem::CoulombCohesion model{eps_r, cutoff};
  const double q = 1e-9 * 2e-9;
  for (const double delta : {-0.009, -1e-3, 1e-4}) {
    const dem::ContactGeometry g = pair_at(delta, q);
    const auto c = cohesion(model, g);
    const double expected = q / (4.0 * kPi * eps_r * 8.8541878128e-12 * g.distance * g.distance);
    EXPECT_NEAR(c.force, expected, 1e-14 * expected);
    EXPECT_GT(c.force, 0.0) << "like charges repel";
    EXPECT_FALSE(c.contact);
    const double energy = expected * g.distance * g.distance * (1.0 / g.distance - 1.0 / cutoff);
    EXPECT_NEAR(dem::laws::coulomb_energy(q, eps_r, g.distance, cutoff), energy, 1e-14 * energy);
  }
  EXPECT_LT(cohesion(model, pair_at(-1e-3, -q)).force, 0.0) << "unlike charges attract";
  EXPECT_FALSE(cohesion(model, pair_at(0.01 - 0.0201, q)).active) << "beyond the cut-off";
  EXPECT_FALSE(cohesion(model, pair_at(-1e-3, 0.0)).active) << "uncharged (walls)";
  EXPECT_DOUBLE_EQ(model.range({0.01, 0.015, 2.5e-3}), cutoff);
  // F = −dU/d|x|: the energy is the potential of the force, zero at the cut-off.
  const double d = 0.012, h = 1e-7;
  const double dU = dem::laws::coulomb_energy(q, eps_r, d + h, cutoff) -
                    dem::laws::coulomb_energy(q, eps_r, d - h, cutoff);
  EXPECT_NEAR(-dU / (2.0 * h), dem::laws::coulomb_force(q, eps_r, d),
              1e-7 * dem::laws::coulomb_force(q, eps_r, d));
  EXPECT_EQ(dem::laws::coulomb_energy(q, eps_r, cutoff, cutoff), 0.0);
}

TEST(CohesionRegistry, EveryCohesionModelHasARegistryRow) {
  for (const char* keyword : {"none", "linear", "jkr", "dmt", "coulomb"}) {
    const auto* row = dem::find_sub_model(dem::Slot::cohesion, keyword);
    ASSERT_NE(row, nullptr) << keyword;
    EXPECT_FALSE(row->lammps.empty());
    EXPECT_FALSE(row->yade.empty());
  }
  EXPECT_EQ(dem::find_sub_model(dem::Slot::cohesion, "jkr")->properties.size(), 2u);
}

/// A 5 mm sphere released at rest 2.5 mm from a fixed one, linear cohesion with λ = 1.5
/// (thesis table 5.1), restitution damping ε = 0.8.
dem::SimulationSetup cohesive_pair() {
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "linear";
  m.density = 8000.0;
  m.normal_stiffness = 1e5;
  m.cohesive_stiffness = 100.0;
  m.restitution = 0.8;
  s.materials = {m};
  s.model.normal = "linear";
  s.model.damping = "restitution";
  s.model.cohesion = "linear";
  s.particles = {
      dem::ParticleInit{0.005, 0.0075, 8000.0, 0, dem::Vec3(0.0125, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), false},
      dem::ParticleInit{0.005, 0.0075, 8000.0, 0, dem::Vec3(0, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), true}};
  s.scheme = dem::SchemeId::velocity_verlet;
  s.scheme_settings.rotation = false;
  s.scheme_settings.length_scale = 0.005;
  s.timestep = 2e-6;
  return s;
}

TEST(LinearCohesionSimulation, MechanicalEnergyNeverRisesAndThePairSettlesAtTheBalance) {
  dem::SimulationSetup setup = cohesive_pair();
  setup.scheme = dem::SchemeId::rk4;
  dem::Simulation sim(setup);
  const auto mechanical = [&] {
    const dem::EnergyLedger e = sim.energy();
    return e.kinetic + e.elastic + e.cohesive;
  };
  const double start = mechanical();
  EXPECT_NEAR(start, -0.5 * 100.0 * 2.5e-3 * 2.5e-3, 1e-15) << "released at rest: U = −½ k_c δ̂²";
  double previous = start;
  for (int n = 0; n < 100000; ++n) {  // 0.2 s
    sim.step();
    const double now = mechanical();
    ASSERT_LE(now, previous + 1e-12 * std::abs(start)) << "step " << n;
    previous = now;
  }
  const double delta_eq = 100.0 * 5e-3 / (1e5 - 100.0);
  EXPECT_NEAR(0.01 - sim.state().position(0, 0), delta_eq, 1e-15);
  const dem::EnergyLedger e = sim.energy();
  EXPECT_NEAR(e.elastic + e.cohesive,
              0.5 * 1e5 * delta_eq * delta_eq - 0.5 * 100.0 * std::pow(5e-3 + delta_eq, 2), 1e-15);
  // The ledger books the dashpot power at step ends: off by ~η v² Δt at each contact onset.
  EXPECT_NEAR(e.balance(), start, 5e-3 * std::abs(start));
}

}  // namespace
