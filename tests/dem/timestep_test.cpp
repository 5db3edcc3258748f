// SPDX-License-Identifier: MIT
// Time-step limits (thesis eq 4.6, 4.7, 4.9) on the thesis' single collision.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/contact/pair_table.hpp"
#include "dem/timestep/timestep_control.hpp"
#include "two_body_fixture.hpp"

namespace timestep_test {

dem::TimestepLimits limits_of(const dem::SimulationSetup& s, bool rotation) {
  dem::ParticleProperties props;
  dem::KinematicState state;
  dem::build_particles(s.particles, props, state);
  const dem::PairTable table(s.materials, s.mixing, s.pair_overrides, s.model);
  return dem::timestep_limits(props, state, table, dem::Vec3::Zero(), rotation, 20.0);
}

TEST(TimestepLimits, FollowCundallStrackAndOSullivanBray) {
  const auto s = test_support::head_on_collision(dem::SchemeId::rk2, 5e-5, 1.0);
  const double sqrt_mk = std::sqrt(test_support::mover_mass() / 1e5);
  const auto no_rot = limits_of(s, false);
  EXPECT_NEAR(no_rot.cundall_strack, sqrt_mk, 1e-18);
  EXPECT_NEAR(no_rot.osullivan_bray, 0.34 * sqrt_mk, 1e-18);
  EXPECT_NEAR(limits_of(s, true).osullivan_bray, 0.22 * sqrt_mk, 1e-18);
}

TEST(TimestepLimits, CollisionTimeUsesTheMoverMassAgainstAFixedPartner) {
  // One mobile sphere: only the mobile–fixed pair can collide, so m* = m, not m/2.
  const auto l = limits_of(test_support::head_on_collision(dem::SchemeId::rk2, 5e-5, 1.0), false);
  EXPECT_NEAR(l.collision_duration, std::numbers::pi * std::sqrt(test_support::mover_mass() / 1e5), 1e-15);
  EXPECT_NEAR(l.collision_resolution, l.collision_duration / 20.0, 1e-18);
  EXPECT_DOUBLE_EQ(dem::automatic_timestep(l), std::min(l.osullivan_bray, l.collision_resolution));
}

TEST(TimestepWarnings, NameTheViolatedCriterion) {
  const auto l = limits_of(test_support::head_on_collision(dem::SchemeId::rk2, 5e-5, 1.0), false);
  // Thesis default Δt = 5e-5 s: stable (0.34√(m/k) = 6.96e-5 s) but only 12.9 steps per collision.
  const auto w = dem::timestep_warnings(5e-5, l);
  ASSERT_EQ(w.size(), 1U);
  EXPECT_NE(w[0].find("12.9 steps"), std::string::npos) << w[0];
  EXPECT_EQ(dem::timestep_warnings(5e-6, l).size(), 0U);
  EXPECT_EQ(dem::timestep_warnings(1e-4, l).size(), 2U);
}

}  // namespace

namespace timestep_test {

TEST(TimestepLimits, APlaneWallIsAFixedPartnerWithTheSphereRadius) {
  // The mover alone with a wall of its own material: the limits are those of m* = m against k.
  auto s = test_support::head_on_collision(dem::SchemeId::rk2, 5e-5, 1.0);
  dem::ParticleProperties props;
  dem::KinematicState state;
  s.particles.pop_back();  // drop the fixed partner: only the wall remains
  dem::build_particles(s.particles, props, state);
  const dem::PairTable table(s.materials, s.mixing, s.pair_overrides, s.model);
  const auto none = dem::timestep_limits(props, state, table, dem::Vec3::Zero(), false, 20.0);
  EXPECT_FALSE(std::isfinite(none.collision_duration)) << "no partner, no collision";
  const auto wall = dem::timestep_limits(props, state, table, dem::Vec3::Zero(), false, 20.0, {0});
  EXPECT_NEAR(wall.collision_duration, std::numbers::pi * std::sqrt(test_support::mover_mass() / 1e5), 1e-15);
  EXPECT_NEAR(wall.cundall_strack, std::sqrt(test_support::mover_mass() / 1e5), 1e-18);
  EXPECT_TRUE(std::isfinite(dem::automatic_timestep(wall)));
}

}  // namespace
