// SPDX-License-Identifier: MIT
// Restitution obtained by the whole core (slots, pair table, force field, integrator) against
// the one requested, for the linear spring–dashpot (thesis eq 3.10–3.11).
#include <cmath>

#include <gtest/gtest.h>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "two_body_fixture.hpp"

namespace restitution_test {

/// Rebound speed / impact speed after one collision at `steps` steps per contact duration.
double obtained_restitution(dem::SchemeId scheme, double restitution, double steps) {
  const double m = test_support::mover_mass();
  const double eta = dem::laws::restitution_damping_coefficient(restitution, m, 1e5);
  const double tc = dem::laws::linear_contact_duration(1e5, m, eta);
  dem::Simulation sim(test_support::head_on_collision(scheme, tc / steps, restitution));
  const double t_end = 1e-4 / 4.0 + 1.5 * tc;
  while (sim.time() < t_end) sim.step();
  return -sim.state().velocity(0, 0) / 4.0;
}

class RequestedRestitution : public ::testing::TestWithParam<std::tuple<dem::SchemeId, double>> {};

TEST_P(RequestedRestitution, IsObtainedWithin1em3At200StepsPerCollision) {
  const auto [scheme, e] = GetParam();
  EXPECT_NEAR(obtained_restitution(scheme, e, 200.0), e, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(
    LinearDashpot, RequestedRestitution,
    ::testing::Combine(::testing::Values(dem::SchemeId::rk2, dem::SchemeId::rk4, dem::SchemeId::bd2,
                                         dem::SchemeId::ab2, dem::SchemeId::ab4, dem::SchemeId::abm),
                       ::testing::Values(0.3, 0.5, 0.8, 0.95)),
    [](const auto& param_info) {
      return std::string(dem::scheme_info(std::get<0>(param_info.param)).keyword) + "_e" +
             std::to_string(static_cast<int>(std::get<1>(param_info.param) * 100));
    });

// The half-step schemes of the reference codes evaluate the dashpot with v(t + Δt/2) and the
// dashpot force jumps from −ηv to 0 when the contact ends inside a step, so one step may carry
// up to η v Δt of spurious impulse: |Δe| ≤ (η/m*) Δt = 2ζω₀Δt, first order, of either sign.
TEST(HalfStepSchemes, RestitutionErrorIsBoundedByOneStepOfDashpotImpulse) {
  const double m = test_support::mover_mass();
  for (const auto scheme : {dem::SchemeId::velocity_verlet, dem::SchemeId::leapfrog}) {
    for (const double e : {0.3, 0.5, 0.8, 0.95}) {
      for (const double steps : {100.0, 200.0, 400.0, 800.0}) {
        const double eta = dem::laws::restitution_damping_coefficient(e, m, 1e5);
        const double dt = dem::laws::linear_contact_duration(1e5, m, eta) / steps;
        EXPECT_LE(std::abs(obtained_restitution(scheme, e, steps) - e), eta / m * dt)
            << dem::scheme_info(scheme).keyword << " e = " << e << " steps = " << steps;
      }
    }
  }
}

TEST(ElasticCollision, Rk4ReboundsWithUnitRestitution) {
  EXPECT_NEAR(obtained_restitution(dem::SchemeId::rk4, 1.0, 200.0), 1.0, 1e-8);
}

TEST(ElasticCollision, VelocityVerletConservesEnergyWithin1em6At200Steps) {
  const double m = test_support::mover_mass();
  const double tc = dem::laws::linear_contact_duration(1e5, m, 0.0);
  dem::Simulation sim(test_support::head_on_collision(dem::SchemeId::velocity_verlet, tc / 200.0, 1.0));
  const double e0 = sim.kinetic_energy();
  double worst = 0.0;
  while (sim.time() < 1.5 * tc) {
    sim.step();
    // Velocity Verlet's velocities are on-step after the closing half kick, so KE + spring energy
    // is the conserved quantity up to O(Δt²).
    worst = std::max(worst, std::abs(sim.kinetic_energy() + sim.force_field().elastic_energy() - e0) / e0);
  }
  EXPECT_LT(worst, 1e-4);  // within the collision, O((ωΔt)²) = 2.5e-4 bounds the shadow-energy gap
  EXPECT_NEAR(sim.kinetic_energy(), e0, 1e-6 * e0);  // after it: conserved to 1e-6
}

TEST(DampedCollision, EnergyNeverRises) {
  const double m = test_support::mover_mass();
  const double eta = dem::laws::restitution_damping_coefficient(0.5, m, 1e5);
  const double tc = dem::laws::linear_contact_duration(1e5, m, eta);
  dem::Simulation sim(test_support::head_on_collision(dem::SchemeId::rk4, tc / 200.0, 0.5));
  double previous = sim.kinetic_energy() + sim.force_field().elastic_energy();
  while (sim.time() < 1.5 * tc) {
    sim.step();
    const double e = sim.kinetic_energy() + sim.force_field().elastic_energy();
    EXPECT_LE(e, previous * (1.0 + 1e-12));
    previous = e;
  }
}

}  // namespace
