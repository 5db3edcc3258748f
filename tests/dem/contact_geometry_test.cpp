// SPDX-License-Identifier: MIT
// Pair kinematics by the common-normal method (thesis eq 3.2–3.8).
#include <gtest/gtest.h>

#include "dem/contact/contact_geometry.hpp"

namespace {

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

}  // namespace
