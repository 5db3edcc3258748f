// SPDX-License-Identifier: MIT
// The linear spring–dashpot laws against their closed forms (thesis eq 3.10, 3.11, 3.40).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/laws/linear_spring.hpp"

namespace linear_law_test {

using namespace dem::laws;

TEST(LinearSpring, ForceIsStiffnessTimesOverlap) {
  EXPECT_DOUBLE_EQ(linear_spring_force(1e5, 1e-3), 100.0);
  EXPECT_DOUBLE_EQ(linear_spring_energy(1e5, 1e-3), 0.05);
}

TEST(LinearDashpot, NoDampingForUnitRestitution) {
  EXPECT_DOUBLE_EQ(restitution_damping_factor(1.0), 0.0);
  EXPECT_DOUBLE_EQ(restitution_damping_coefficient(1.0, 2.0, 3.0), 0.0);
}

TEST(LinearDashpot, DampingCoefficientMatchesEquation311) {
  const double e = 0.5, m = 4.2e-3, k = 1e5;
  const double ln_e = std::log(e);
  const double expected = -2.0 * ln_e * std::sqrt(m * k / (std::numbers::pi * std::numbers::pi + ln_e * ln_e));
  EXPECT_NEAR(restitution_damping_coefficient(e, m, k), expected, 1e-15 * expected);
}

TEST(LinearDashpot, RestitutionInvertsTheDampingCoefficient) {
  for (const double e : {0.05, 0.3, 0.5, 0.8, 0.95, 0.999}) {
    const double eta = restitution_damping_coefficient(e, 4.2e-3, 1e5);
    EXPECT_NEAR(linear_restitution(1e5, 4.2e-3, eta), e, 1e-13) << "e = " << e;
  }
}

TEST(LinearDashpot, ForceOpposesTheNormalRelativeVelocity) {
  EXPECT_GT(dashpot_force(2.0, -1.0), 0.0);  // approaching: repulsive
  EXPECT_LT(dashpot_force(2.0, 1.0), 0.0);   // separating: attractive (not clamped)
}

TEST(LinearDashpot, UndampedDurationIsPiTimesSqrtMassOverStiffness) {
  const double m = 4.0 / 3.0 * std::numbers::pi * 1000.0 * 1e-6;
  EXPECT_NEAR(linear_contact_duration(1e5, m, 0.0), std::numbers::pi * std::sqrt(m / 1e5), 1e-18);
  EXPECT_NEAR(linear_contact_duration(1e5, m, 0.0), 6.429751e-4, 1e-9);
}

TEST(LinearDashpot, DampedDurationUsesTheDampedFrequency) {
  const double m = 1e-3, k = 1e4, eta = 0.1;
  const double omega_d = std::sqrt(k / m - std::pow(eta / (2.0 * m), 2));
  EXPECT_NEAR(linear_contact_duration(k, m, eta), std::numbers::pi / omega_d, 1e-15);
}

}  // namespace
