// SPDX-License-Identifier: MIT
// Oblique impacts of a solid sphere on a plane wall swept from 5° to 85° through the core, against
// the regimes of the spring–Coulomb contact (Maw, Barber & Fawcett 1976 in its linear-spring
// form): with k_t/k_n = 2/7 and e = 1 the stuck tangential spring and the normal spring share the
// frequency, so
//   tan θ ≤ 7/2 μ          : the contact never slips and the slip velocity reverses, e_t = +1;
//   tan θ ≥ 7/2 μ (1 + e)  : gross sliding, e_t = −1 + 7/2 μ (1 + e) / tan θ (rigid-body Coulomb);
//   in between             : stick–slip, e_t falls monotonically from +1 to the sliding value.
// e_t = −u_t,after/u_t,before of the contact point, lever arm r so that the rigid-body theory holds.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "dem/simulation/simulation.hpp"

namespace tangential_oblique_sweep_test {

using dem::Vec3;

constexpr double kRadius = 0.01;
constexpr double kDensity = 1000.0;
constexpr double kStiffness = 1e5;
constexpr double kFriction = 0.2;
constexpr double kSpeed = 4.0;

/// Impact result: tangential restitution of the contact point and the spin after.
struct Rebound {
  double tangential_restitution;
  double spin;
  double normal_restitution;
};

Rebound impact(double theta_deg, double tangential_ratio) {
  const double theta = theta_deg * std::numbers::pi / 180.0;
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "ball";
  m.density = kDensity;
  m.normal_stiffness = kStiffness;
  m.tangential_stiffness = tangential_ratio * kStiffness;
  m.friction = kFriction;
  m.tangential_damping_ratio = 0.0;
  s.materials = {m};
  s.model.tangential = "spring_coulomb";
  s.model.wall_lever_arm = dem::WallLeverArm::radius;
  const Vec3 v(kSpeed * std::sin(theta), 0, -kSpeed * std::cos(theta));
  s.particles = {dem::ParticleInit{kRadius, kRadius, kDensity, 0, Vec3(0, 0, kRadius + 1e-6), v,
                                   Vec3::Zero(), false}};
  s.walls = {dem::Wall{Vec3::Zero(), Vec3::UnitZ()}};
  s.scheme = dem::SchemeId::velocity_verlet;
  s.scheme_settings.length_scale = kRadius;
  s.timestep = 2e-7;
  dem::Simulation sim(s);
  while (sim.state().position(2, 0) <= kRadius + 2e-6 || sim.time() < 1e-5) sim.step();
  const double u_after = sim.state().velocity(0, 0) - kRadius * sim.state().angular_velocity(1, 0);
  return {-u_after / v.x(), sim.state().angular_velocity(1, 0), sim.state().velocity(2, 0) / -v.z()};
}

TEST(ObliqueImpactSweep, RegimesFollowTheSpringCoulombTheoryFrom5To85Degrees) {
  const double stick_limit = std::atan(3.5 * kFriction) * 180.0 / std::numbers::pi;      // 35.0°
  const double sliding_limit = std::atan(7.0 * kFriction) * 180.0 / std::numbers::pi;    // 54.5°
  std::vector<double> e_t;
  for (int deg = 5; deg <= 85; deg += 5) {
    const Rebound r = impact(deg, 2.0 / 7.0);
    const double tan_theta = std::tan(deg * std::numbers::pi / 180.0);
    EXPECT_NEAR(r.normal_restitution, 1.0, 1e-5) << deg << "°";
    if (deg < stick_limit) {
      EXPECT_NEAR(r.tangential_restitution, 1.0, 2e-3) << deg << "°: no-slip limit";
    } else if (deg > sliding_limit) {
      EXPECT_NEAR(r.tangential_restitution, -1.0 + 7.0 * kFriction / tan_theta, 2e-4)
          << deg << "°: gross sliding";
      const double v_n = kSpeed * std::cos(deg * std::numbers::pi / 180.0);
      EXPECT_NEAR(r.spin, 5.0 * kFriction * v_n / kRadius, 1e-4 * 5.0 * kFriction * v_n / kRadius) << deg;
    }
    if (!e_t.empty()) {
      EXPECT_LE(r.tangential_restitution, e_t.back() + 2e-3) << deg << "°: monotonic";
    }
    e_t.push_back(r.tangential_restitution);
    RecordProperty("e_t_" + std::to_string(deg), std::to_string(r.tangential_restitution));
  }
}

}  // namespace
