// SPDX-License-Identifier: MIT
// Damping sub-model `yade_frictvisco`: YADE FrictViscoPhys's dashpot −α η (u_c·n) with
// α = (r_p + r_q)/(r_p + r_q − δ), 2r/(2r − δ) against a wall (ScGeom::getIncidentVel;
// verified with YADE 2023.02a).
#include <cmath>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"

namespace damping_yade_frictvisco_test {

dem::SphereState sphere(double x, double vx, double r, double inverse_mass) {
  return {dem::Vec3(x, 0, 0), dem::Vec3(vx, 0, 0), dem::Vec3::Zero(), r, r, inverse_mass};
}

TEST(YadeFrictViscoDamping, CoefficientIsAlphaTimesRestitutionDashpot) {
  const dem::YadeFrictViscoDamping d{0.5, dem::laws::restitution_damping_factor(0.5)};
  const double m = 4.18879e-3;
  const auto g = dem::pair_geometry(sphere(-0.10999, 4.0, 0.01, 1.0 / m), sphere(0.0, 0.0, 0.1, 0.0));
  ASSERT_NEAR(g.overlap, 1e-5, 1e-15);
  dem::NormalResponse n;
  n.stiffness = 1e5;
  const double alpha = 0.11 / (0.11 - g.overlap);
  const double eta = dem::laws::restitution_damping_coefficient(0.5, m, 1e5);
  EXPECT_NEAR(d.coefficient(g, n), alpha * eta, 1e-15 * eta);
  EXPECT_GT(alpha, 1.0);
}

TEST(YadeFrictViscoDamping, WallUsesTwiceTheSphereRadius) {
  const dem::YadeFrictViscoDamping d{0.8, dem::laws::restitution_damping_factor(0.8)};
  const double m = 4.18879e-3;
  dem::SphereState p = sphere(0.0, 0.0, 0.01, 1.0 / m);
  p.position = dem::Vec3(0, 0, 0.0099);
  p.velocity = dem::Vec3(3.0, 0, -2.0);
  const dem::Wall wall{dem::Vec3::Zero(), dem::Vec3::UnitZ()};
  const auto g = dem::wall_geometry(p, wall, 0.0, dem::WallLeverArm::contact_point);
  ASSERT_TRUE(g.against_wall);
  ASSERT_NEAR(g.overlap, 1e-4, 1e-16);
  dem::NormalResponse n;
  n.stiffness = 1e5;
  const double eta = dem::laws::restitution_damping_coefficient(0.8, m, 1e5);
  EXPECT_NEAR(d.coefficient(g, n), 0.02 / (0.02 - 1e-4) * eta, 1e-15 * eta);
  EXPECT_NEAR(dem::yade_incident_velocity_scale(g), 0.02 / 0.0199, 1e-15);
}

TEST(YadeFrictViscoDamping, NormalForceIsSpringPlusScaledDashpotUnclamped) {
  dem::PairLaw law;
  law.normal = dem::LinearNormal{1e5};
  law.damping = dem::YadeFrictViscoDamping{0.5, dem::laws::restitution_damping_factor(0.5)};
  law.tangential = dem::NoTangential{};
  law.cohesion = dem::NoCohesion{};
  law.rolling = dem::NoRolling{};
  const double m = 4.18879e-3;
  // Separating fast at a small overlap: the dashpot pulls (no clamp, as YADE's law).
  const auto g = dem::pair_geometry(sphere(-0.10999, -4.0, 0.01, 1.0 / m), sphere(0.0, 0.0, 0.1, 0.0));
  const auto out = dem::evaluate_contact(law, g, {}, 1e-6);
  const double alpha = 0.11 / (0.11 - g.overlap);
  const double eta = dem::laws::restitution_damping_coefficient(0.5, m, 1e5);
  // n points from q to p (−x); u_c·n = +4 (separating).
  EXPECT_NEAR(out.normal_force, 1e5 * g.overlap - alpha * eta * 4.0, 1e-13);
  EXPECT_LT(out.normal_force, 0.0);
}

}  // namespace
