// SPDX-License-Identifier: MIT
// The launch stage against closed forms: centre of mass, L_A, velocities and t_max (eq 5.1).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "prepare/launch.hpp"

namespace launch_test {

cases::ParticleSpec sphere(double r, cases::Vector3 x, bool fixed = false) {
  cases::ParticleSpec p;
  p.radius = r;
  p.effect_radius = r;
  p.position = x;
  p.velocity = {0.1, 0.2, 0.3};
  p.angular_velocity = {1.0, 2.0, 3.0};
  p.fixed = fixed;
  return p;
}

cases::WallSpec floor_at(double z) {
  cases::WallSpec w;
  w.name = "floor";
  w.point = {0.5, -0.25, z};
  w.normal = {0.0, 0.0, 1.0};
  return w;
}

TEST(Launch, PlacesTheCentreOfMassOneEnclosingDiameterAboveTheWall) {
  // Two equal spheres 2a apart: centre of mass midway, L_A = 2(a + r).
  const double a = 0.03;
  const double r = 0.01;
  std::vector<cases::ParticleSpec> ps{sphere(r, {1.0 - a, 2.0, 3.0}), sphere(r, {1.0 + a, 2.0, 3.0})};
  cases::LaunchStageSpec spec;
  spec.speed = 3.0;
  spec.angle = 30.0;
  spec.direction = {0.0, 1.0, 0.0};
  const prepare::LaunchFigures f = prepare::launch(ps, {8000.0, 8000.0}, floor_at(-1.0), spec);
  const double la = 2.0 * (a + r);
  EXPECT_DOUBLE_EQ(f.enclosing_diameter, la);
  EXPECT_NEAR(f.centre_of_mass[0], 0.5, 1e-15);
  EXPECT_NEAR(f.centre_of_mass[1], -0.25, 1e-15);
  EXPECT_NEAR(f.centre_of_mass[2], -1.0 + la, 1e-15);
  EXPECT_NEAR(ps[0].position[0], 0.5 - a, 1e-15);
  EXPECT_NEAR(ps[1].position[0], 0.5 + a, 1e-15);
  EXPECT_NEAR(ps[1].position[2], -1.0 + la, 1e-15);
  // u = |u| (cos θ t̂ − sin θ n): 3 (cos 30°, along y) and −3 sin 30° along z.
  for (const auto& p : ps) {
    EXPECT_NEAR(p.velocity[0], 0.0, 1e-15);
    EXPECT_NEAR(p.velocity[1], 3.0 * std::sqrt(3.0) / 2.0, 1e-15);
    EXPECT_NEAR(p.velocity[2], -1.5, 1e-15);
    EXPECT_EQ(p.angular_velocity, (cases::Vector3{0.0, 0.0, 0.0}));
  }
  EXPECT_NEAR(f.duration, 4.0 * la / (3.0 * 0.5), 1e-15);
}

TEST(Launch, WeighsTheCentreOfMassAndLeavesFixedSpheresAlone) {
  // A heavy sphere (ρ 3×) at x = 0 and a light one at x = 0.04: centre of mass at x = 0.01;
  // L_A = 2 × max(0.01 + 0.005, 0.03 + 0.005) = 0.07.
  std::vector<cases::ParticleSpec> ps{sphere(0.005, {0.0, 0.0, 0.5}), sphere(0.005, {0.04, 0.0, 0.5}),
                                      sphere(0.02, {9.0, 9.0, 9.0}, true)};
  cases::LaunchStageSpec spec;
  spec.speed = 2.0;
  spec.angle = 90.0;
  spec.direction = {1.0, 0.0, 0.0};
  spec.height = 2.0;
  const prepare::LaunchFigures f = prepare::launch(ps, {3000.0, 1000.0, 1000.0}, floor_at(0.0), spec);
  EXPECT_NEAR(f.enclosing_diameter, 0.07, 1e-15);
  EXPECT_NEAR(ps[0].position[0], 0.5 - 0.01, 1e-15);
  EXPECT_NEAR(ps[0].position[2], 0.14, 1e-15);
  EXPECT_NEAR(ps[1].velocity[2], -2.0, 1e-15);
  EXPECT_NEAR(ps[1].velocity[0], 0.0, 1e-15);
  EXPECT_EQ(ps[2].position, (cases::Vector3{9.0, 9.0, 9.0}));
  EXPECT_EQ(ps[2].velocity, (cases::Vector3{0.1, 0.2, 0.3}));
  EXPECT_NEAR(f.duration, 4.0 * 0.07 / 2.0, 1e-15);
}

TEST(Launch, NeedsAMobileSphere) {
  std::vector<cases::ParticleSpec> ps{sphere(0.01, {0.0, 0.0, 1.0}, true)};
  cases::LaunchStageSpec spec;
  spec.speed = 1.0;
  spec.angle = 45.0;
  spec.direction = {1.0, 0.0, 0.0};
  EXPECT_THROW(static_cast<void>(prepare::launch(ps, {1000.0}, floor_at(0.0), spec)), std::invalid_argument);
}

}  // namespace
