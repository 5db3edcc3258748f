// SPDX-License-Identifier: MIT
// YADE's own damping formulas (FrictViscoPhys, ViscElPhys, MindlinPhys) run in the core with
// YADE's leapfrog, against the restitutions measured with the installed YADE 2023.02a and
// against closed forms.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/dashpot_restitution.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "dem/simulation/simulation.hpp"

namespace damping_yade_test {

TEST(ThorntonDampingRatio, MatchesYadesMindlinPhysBetan) {
  // betan read back from YADE 2023.02a's MindlinPhys for en = 0.9 / 0.5 / 0.1.
  EXPECT_NEAR(dem::laws::thornton_damping_ratio(0.9), 0.0313066, 1e-7);
  EXPECT_NEAR(dem::laws::thornton_damping_ratio(0.5), 0.2330249, 1e-7);
  EXPECT_NEAR(dem::laws::thornton_damping_ratio(0.1), 1.1342511, 1e-7);
}

TEST(ThorntonDampingRatio, FitsTheClippedHertzDashpotRestitutionWithin3em4) {
  // c_n = 2 β_n √(m* 1.5 k_no √δ) is Tsuji's form with α = 2√1.5 β_n; clipped closed form. The
  // fit is within 1e-4 at 0.1, 0.5, 0.9 (where YADE was measured) and 2.3e-4 at 0.3, 0.7.
  for (const double e : {0.1, 0.5, 0.9}) {
    const double alpha = 2.0 * std::sqrt(1.5) * dem::laws::thornton_damping_ratio(e);
    EXPECT_NEAR(dem::laws::hertz_tsuji_restitution(alpha, true), e, 1e-4) << "ε = " << e;
  }
  for (int k = 1; k <= 18; ++k) {
    const double e = 0.05 * k;
    const double alpha = 2.0 * std::sqrt(1.5) * dem::laws::thornton_damping_ratio(e);
    EXPECT_NEAR(dem::laws::hertz_tsuji_restitution(alpha, true), e, 3e-4) << "ε = " << e;
  }
}

TEST(ThorntonDampingRatio, DegradesAboveZeroPointNineTwoAndDampsAtUnitRestitution) {
  // As YADE: en = 0.95 rebounds at 0.9481, en = 0.99 at 0.9789, en = 1 at 0.9846 (β_n = 0.0045).
  const auto rebound = [](double e) {
    return dem::laws::hertz_tsuji_restitution(
        2.0 * std::sqrt(1.5) * dem::laws::thornton_damping_ratio(e), true);
  };
  EXPECT_NEAR(rebound(0.95), 0.948082, 1e-6);
  EXPECT_NEAR(rebound(0.99), 0.978949, 1e-6);
  EXPECT_NEAR(rebound(1.0), 0.984591, 1e-6);
}

TEST(ClippedRestitution, IsContinuousThroughCriticalDamping) {
  using dem::laws::linear_clipped_restitution;
  EXPECT_NEAR(linear_clipped_restitution(1.0 - 1e-7), std::exp(-2.0), 1e-6);
  EXPECT_NEAR(linear_clipped_restitution(1.0 + 1e-7), std::exp(-2.0), 1e-6);
  EXPECT_NEAR(linear_clipped_restitution(0.0), 1.0, 1e-15);
  EXPECT_GT(linear_clipped_restitution(3.0), 0.0);
}

/// YADE's sphere–sphere set-up: mover r1 at −(r1 + r2 + gap) moving +x at v0 towards a fixed r2
/// at the origin, ρ = 1000, leapfrog with the given velocity taken as v(−Δt/2).
dem::SimulationSetup yade_impact(double r2, double gap, double v0, double dt) {
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "mat";
  m.density = 1000.0;
  s.materials = {m};
  s.particles = {
      dem::ParticleInit{0.01, 0.01, 1000.0, 0, dem::Vec3(-(0.01 + r2 + gap), 0, 0), dem::Vec3(v0, 0, 0), dem::Vec3::Zero(), false},
      dem::ParticleInit{r2, r2, 1000.0, 0, dem::Vec3(0, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), true}};
  s.scheme = dem::SchemeId::leapfrog;
  s.scheme_settings.rotation = false;
  s.scheme_settings.length_scale = 0.01;
  s.scheme_settings.leapfrog_start = dem::LeapfrogStart::given_is_half_step;
  s.model.clamp_tensile = true;
  s.timestep = dt;
  return s;
}

TEST(YadeMindlinCollision, ReproducesTheMeasuredReboundOfYadeHertzMindlin) {
  // Measured with YADE 2023.02a's Hertz–Mindlin: E = 1e8, ν = 0.3, v = 1, dt = 5e-7, gap
  // 0.37 v dt, 3000 steps: e = 0.89992 / 0.49994 / 0.09992 for en = 0.9 / 0.5 / 0.1.
  for (const auto& [en, measured] : {std::pair{0.9, 0.89992}, {0.5, 0.49994}, {0.1, 0.09992}}) {
    dem::SimulationSetup s = yade_impact(0.1, 0.37 * 1.0 * 5e-7, 1.0, 5e-7);
    s.materials[0].youngs_modulus = 1e8;
    s.materials[0].poisson_ratio = 0.3;
    s.materials[0].restitution = en;
    s.model.normal = "hertz";
    s.model.damping = "yade_mindlin";
    dem::Simulation sim(s);
    for (int n = 0; n < 3000; ++n) sim.step();
    EXPECT_NEAR(-sim.state().velocity(0, 0), measured, 2e-5) << "en = " << en;
  }
}

TEST(YadeViscElCollision, ReproducesTheMeasuredClippedReboundOfTheKnCnDeck) {
  // Measured with a YADE 2023.02a ViscElMat(kn, cn) deck: k = 1e5, v = 4, gap 2.37e-4,
  // dt = 5e-6, 3 (t_c + gap/v)/dt + 5 steps: e = 0.90149 / 0.54747 / 0.24827 for
  // ε = 0.9 / 0.5 / 0.1.
  const double m = 4.0 / 3.0 * std::numbers::pi * 1000.0 * 1e-6;
  const int steps = static_cast<int>(std::lround(3.0 * (std::numbers::pi * std::sqrt(m / 1e5) + 2.37e-4 / 4.0) / 5e-6)) + 5;
  for (const auto& [e, measured] : {std::pair{0.9, 0.90149}, {0.5, 0.54747}, {0.1, 0.24827}}) {
    dem::SimulationSetup s = yade_impact(0.1, 2.37e-4, 4.0, 5e-6);
    s.materials[0].normal_stiffness = 1e5;
    s.materials[0].restitution = e;
    s.model.damping = "yade_viscel";
    dem::Simulation sim(s);
    for (int n = 0; n < steps; ++n) sim.step();
    EXPECT_NEAR(-sim.state().velocity(0, 0) / 4.0, measured, 1e-5) << "ε = " << e;
  }
}

TEST(YadeViscElCollision, ConvergesToTheSchwagerPoeschelClippedRestitution) {
  for (const double e : {0.9, 0.5, 0.1}) {
    dem::SimulationSetup s = yade_impact(0.1, 2.37e-4, 4.0, 2e-7);
    s.materials[0].normal_stiffness = 1e5;
    s.materials[0].restitution = e;
    s.model.damping = "yade_viscel";
    s.scheme = dem::SchemeId::rk4;
    dem::Simulation sim(s);
    while (sim.time() < 1.5e-3) sim.step();
    const double zeta = 0.5 * dem::laws::restitution_damping_factor(e);
    EXPECT_NEAR(-sim.state().velocity(0, 0) / 4.0, dem::laws::linear_clipped_restitution(zeta), 2e-4)
        << "ε = " << e;
  }
}

TEST(YadeViscElDamping, CoefficientIsEquation311OnTheGivenLinearStiffness) {
  dem::PairProperties p;
  p.normal_stiffness = 1e5;
  p.restitution = 0.5;
  const dem::YadeViscElDamping d = dem::YadeViscElDamping::from_pair(p);
  dem::ContactGeometry g{};
  g.reduced_mass = 4.18879e-3;
  dem::NormalResponse n;
  n.stiffness = 7e5;  // the normal model's own stiffness plays no role
  EXPECT_NEAR(d.coefficient(g, n), dem::laws::restitution_damping_coefficient(0.5, 4.18879e-3, 1e5), 1e-12);
}

}  // namespace
