// SPDX-License-Identifier: MIT
// The Walton–Braun hysteretic normal law (thesis eq 3.20–3.21; docs/physics-normal.md): branches,
// continuity, the reloading rule, restitution √(k_l/k_u) and the energy of one loop.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/walton_braun.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/simulation/simulation.hpp"

namespace normal_hysteretic_test {

using dem::laws::walton_braun;

constexpr double kLoad = 1e5;     // k_l [N/m]
constexpr double kUnload = 4e5;   // k_u [N/m]: ε = 0.5

TEST(WaltonBraunLaw, LoadsOnTheLoadingSpring) {
  const auto r = walton_braun(kLoad, kUnload, 2e-4, 2e-4);
  EXPECT_DOUBLE_EQ(r.force, kLoad * 2e-4);
  EXPECT_DOUBLE_EQ(r.stiffness, kLoad);
}

TEST(WaltonBraunLaw, UnloadingLineMeetsTheLoadingLineAtTheLargestOverlap) {
  const double peak = 3e-4;
  const double below = std::nextafter(peak, 0.0);
  EXPECT_NEAR(walton_braun(kLoad, kUnload, below, peak).force, kLoad * peak, 1e-9);
  EXPECT_NEAR(walton_braun(kLoad, kUnload, below, peak).energy,
              walton_braun(kLoad, kUnload, peak, peak).energy, 1e-12);
}

TEST(WaltonBraunLaw, UnloadingReachesZeroAtDeltaZeroAndStaysClipped) {
  const double peak = 3e-4;
  const double unloaded = peak * (1.0 - kLoad / kUnload);
  EXPECT_NEAR(walton_braun(kLoad, kUnload, unloaded + 1e-9, peak).force, kUnload * 1e-9, 1e-12);
  EXPECT_EQ(walton_braun(kLoad, kUnload, unloaded - 1e-9, peak).force, 0.0);
  EXPECT_EQ(walton_braun(kLoad, kUnload, 0.5 * unloaded, peak).energy, 0.0);
  EXPECT_EQ(walton_braun(kLoad, kUnload, -1e-6, peak).force, 0.0);
}

TEST(WaltonBraunLaw, RestitutionIsTheSquareRootOfTheStiffnessRatio) {
  EXPECT_DOUBLE_EQ(dem::laws::walton_braun_unloading_stiffness(kLoad, 0.5), kUnload);
}

/// Drives one pair law along a prescribed overlap path (a kinematic rig: push in, pull back,
/// push further), committing the history as the force field does; returns the forces. Spheres of
/// radius 0.01 with the given effect radius (larger: the pair interacts beyond contact).
std::vector<double> rig(const dem::PairLaw& law, const std::vector<double>& path, double effect_radius = 0.01) {
  dem::ContactHistory history;
  std::vector<double> forces;
  for (const double delta : path) {
    dem::SphereState p{dem::Vec3(0, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), 0.01, effect_radius, 1.0};
    dem::SphereState q{dem::Vec3(0.02 - delta, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), 0.01, effect_radius, 1.0};
    const dem::ContactOutcome c = dem::evaluate_contact(law, dem::pair_geometry(p, q), history, 1e-6);
    forces.push_back(c.normal_force);
    history = c.interacting ? c.history : dem::ContactHistory{};
  }
  return forces;
}

dem::PairLaw hysteretic_law(double restitution) {
  dem::ModelChoice choice;
  choice.normal = "hysteretic";
  dem::PairProperties p;
  p.normal_stiffness = kLoad;
  p.restitution = restitution;
  return dem::make_pair_law(choice, p);
}

TEST(HystereticNormal, ReloadingRetracesTheUnloadingLineUntilTheLargestOverlap) {
  // Load to 4e-4, unload to 3.5e-4 (above δ_0 = 3e-4), reload to 5e-4, unload to 4.5e-4.
  const std::vector<double> path{1e-4, 2e-4, 4e-4, 3.5e-4, 3.8e-4, 4e-4, 5e-4, 4.5e-4, 1e-4, -1e-5, 1e-4};
  const std::vector<double> f = rig(hysteretic_law(0.5), path);
  EXPECT_NEAR(f[2], kLoad * 4e-4, 1e-9);
  EXPECT_NEAR(f[3], kUnload * (3.5e-4 - 3e-4), 1e-9);  // δ_0 = 4e-4 · (1 − 1/4)
  EXPECT_NEAR(f[4], kUnload * (3.8e-4 - 3e-4), 1e-9);  // reloading on the unloading line
  EXPECT_NEAR(f[5], kLoad * 4e-4, 1e-9);
  EXPECT_NEAR(f[6], kLoad * 5e-4, 1e-9);               // beyond δ_max: loading again
  EXPECT_NEAR(f[7], kUnload * (4.5e-4 - 3.75e-4), 1e-9);
  EXPECT_EQ(f[8], 0.0);                                 // below δ_0: clipped
  EXPECT_EQ(f[9], 0.0);                                 // apart: the history is dropped
  EXPECT_NEAR(f[10], kLoad * 1e-4, 1e-9);               // a new contact loads afresh
}

TEST(HystereticNormal, ASeparationUnderALongRangeCohesionStillStartsTheNextContactAfresh) {
  dem::ModelChoice choice;
  choice.normal = "hysteretic";
  choice.cohesion = "linear";
  dem::PairProperties p;
  p.normal_stiffness = kLoad;
  p.restitution = 0.5;
  p.cohesive_stiffness = 1e3;
  const dem::PairLaw law = dem::make_pair_law(choice, p);
  // Loaded to 4e-4, apart (δ < 0, still attracting), then touching again at 1e-4: the same
  // force as a first touch at 1e-4, not the old unloading line (which is zero below δ_0 = 3e-4).
  const std::vector<double> again = rig(law, {1e-4, 4e-4, -1e-5, 1e-4}, 0.015);
  const std::vector<double> first = rig(law, {1e-4}, 0.015);
  EXPECT_LT(again[2], 0.0) << "apart but within the effect radius: the pair still attracts";
  EXPECT_DOUBLE_EQ(again[3], first[0]);
  // Loading spring k_l δ plus the linear cohesion k_c (2·0.015 − distance) pulling inwards.
  EXPECT_NEAR(again[3], kLoad * 1e-4 - 1e3 * (0.03 - (0.02 - 1e-4)), 1e-9);
}

/// Impact of a 10 mm sphere (ρ = 1000) on a fixed one at 1 m/s, Walton–Braun with ε.
dem::SimulationSetup impact(double restitution, dem::SchemeId scheme, double dt) {
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "plastic";
  m.density = 1000.0;
  m.normal_stiffness = kLoad;
  m.restitution = restitution;
  s.materials = {m};
  s.model.normal = "hysteretic";
  s.particles = {
      dem::ParticleInit{0.01, 0.01, 1000.0, 0, dem::Vec3(0, 0, 0), dem::Vec3(1, 0, 0), dem::Vec3::Zero(), false},
      dem::ParticleInit{0.1, 0.1, 1000.0, 0, dem::Vec3(0.11 + 10.37 * dt, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), true}};
  s.scheme = scheme;
  s.scheme_settings.rotation = false;
  s.scheme_settings.length_scale = 0.01;
  s.timestep = dt;
  return s;
}

double mass() { return 4.0 / 3.0 * std::numbers::pi * 1000.0 * 1e-6; }

/// Contact duration π/2 (√(m/k_l) + √(m/k_u)) of the Walton–Braun impact.
double duration(double restitution) {
  return 0.5 * std::numbers::pi * std::sqrt(mass() / kLoad) * (1.0 + restitution);
}

TEST(HystereticCollision, ReboundsWithRestitutionSqrtKlOverKu) {
  for (const double e : {0.3, 0.5, 0.8, 0.95}) {
    for (const auto scheme : {dem::SchemeId::rk4, dem::SchemeId::velocity_verlet}) {
      const double dt = duration(e) / 2000.0;
      dem::Simulation sim(impact(e, scheme, dt));
      while (sim.time() < 20.0 * dt + 1.5 * duration(e)) sim.step();
      EXPECT_NEAR(-sim.state().velocity(0, 0), std::sqrt(kLoad / (kLoad / (e * e))), 2e-3)
          << dem::scheme_info(scheme).keyword << " ε = " << e;
    }
  }
}

TEST(HystereticCollision, OneLoopDissipatesHalfKlDeltaMaxSquaredTimesOneMinusKlOverKu) {
  const double e = 0.5, dt = duration(e) / 4000.0;
  dem::Simulation sim(impact(e, dem::SchemeId::rk4, dt));
  sim.watch({dem::ContactObservation{0, 1, false, 0.0, 0.0, false}});
  const double e0 = sim.kinetic_energy();
  double peak = 0.0;
  double previous = e0;
  while (sim.time() < 20.0 * dt + 1.5 * duration(e)) {
    sim.step();
    peak = std::max(peak, sim.force_field().observations()[0].overlap);
    const double now = sim.kinetic_energy() + sim.force_field().elastic_energy();
    EXPECT_LE(now, previous * (1.0 + 1e-10)) << "t = " << sim.time();  // never rises
    previous = now;
  }
  const double lost = e0 - sim.kinetic_energy();
  const double expected = 0.5 * kLoad * peak * peak * (1.0 - kLoad / (kLoad / (e * e)));
  EXPECT_NEAR(lost, expected, 1e-3 * expected);
  EXPECT_NEAR(peak, std::sqrt(mass() / kLoad), 1e-4 * peak);  // loading branch: δ_max = v √(m/k_l)
}

}  // namespace
