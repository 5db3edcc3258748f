// SPDX-License-Identifier: MIT
// Pair kinematics by the common-normal method (thesis eq 3.2–3.8).
#include <gtest/gtest.h>

#include "dem/contact/contact_geometry.hpp"

namespace contact_geometry_test {

TEST(PairGeometry, NormalPointsFromQToPAndOverlapIsPositiveInContact) {
  const dem::Vec3 xp(0, 0, 0), xq(0.015, 0, 0), zero = dem::Vec3::Zero();
  const dem::Vec3 up(1, 0, 0);
  const auto g = dem::pair_geometry({xp, up, zero, 0.01, 0.012, 1.0 / 2.0}, {xq, zero, zero, 0.01, 0.012, 0.0});
  EXPECT_EQ(g.normal, dem::Vec3(-1, 0, 0));
  EXPECT_NEAR(g.overlap, 0.005, 1e-15);
  EXPECT_NEAR(g.effect_overlap, 0.009, 1e-15);
  EXPECT_NEAR(g.normal_speed, -1.0, 1e-15);  // approaching
  EXPECT_DOUBLE_EQ(g.reduced_mass, 2.0);      // fixed partner: m* = m
  EXPECT_NEAR(g.reduced_radius, 0.005, 1e-15);
  EXPECT_NEAR((g.branch_p - dem::Vec3(0.0075, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((g.branch_q - dem::Vec3(-0.0075, 0, 0)).norm(), 0.0, 1e-15);
}

TEST(PairGeometry, SpinAddsTangentialContactVelocity) {
  const dem::Vec3 xp(0, 0.02, 0), xq(0, 0, 0), zero = dem::Vec3::Zero();
  const dem::Vec3 wp(0, 0, 10.0);  // spin about z
  const auto g = dem::pair_geometry({xp, zero, wp, 0.01, 0.01, 1.0}, {xq, zero, zero, 0.01, 0.01, 1.0});
  // a_p = −r n = (0, −0.01, 0); ω × a_p = (10·0.01, 0, 0).
  EXPECT_NEAR(g.normal_speed, 0.0, 1e-15);
  EXPECT_NEAR(g.tangential_velocity.x(), 0.1, 1e-15);
  EXPECT_DOUBLE_EQ(g.reduced_mass, 0.5);
}

TEST(PairGeometry, LeverArmPoliciesSetTheVelocityAndTorqueArms) {
  // Overlapping by 2 mm, both spinning: contact_point uses r − δ/2 = 9 mm for both arms, radius
  // 10 mm for both, radius_velocity 10 mm for the velocity and 9 mm for the torque.
  const dem::Vec3 xp(0, 0.018, 0), xq(0, 0, 0), zero = dem::Vec3::Zero();
  const dem::Vec3 wp(0, 0, 10.0), wq(0, 0, -4.0);
  const dem::SphereState p{xp, zero, wp, 0.01, 0.01, 1.0};
  const dem::SphereState q{xq, zero, wq, 0.01, 0.01, 1.0};
  const auto cp = dem::pair_geometry(p, q, dem::PairLeverArm::contact_point);
  const auto r = dem::pair_geometry(p, q, dem::PairLeverArm::radius);
  const auto rv = dem::pair_geometry(p, q, dem::PairLeverArm::radius_velocity);
  // n = +y, a_p = −L n, a_q = +L n: ω_p × a_p = (10 L, 0, 0), ω_q × a_q = (4 L, 0, 0), so
  // u_c = ω_p × a_p − ω_q × a_q = (6 L, 0, 0).
  EXPECT_NEAR(cp.tangential_velocity.x(), 6.0 * 0.009, 1e-15);
  EXPECT_NEAR(r.tangential_velocity.x(), 6.0 * 0.01, 1e-15);
  EXPECT_NEAR(rv.tangential_velocity.x(), r.tangential_velocity.x(), 1e-15);  // velocity with r
  EXPECT_NEAR((rv.branch_p - cp.branch_p).norm(), 0.0, 1e-18);             // torque with r − δ/2
  EXPECT_NEAR((rv.branch_q - cp.branch_q).norm(), 0.0, 1e-18);
  EXPECT_NEAR(r.branch_p.norm(), 0.01, 1e-18);
}

}  // namespace
