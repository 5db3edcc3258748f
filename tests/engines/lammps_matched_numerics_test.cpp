// SPDX-License-Identifier: MIT
// The in-house core on reference::matched_scene(scene, "lammps") reproduces LAMMPS' numbers.
#include <iostream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lammps_test_support.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/lammps/lammps_engine.hpp"
#include "reference/matching.hpp"

namespace lammps_matched_numerics_test {

using demwb_lammps_test::canonical;
using demwb_lammps_test::scaled_differences;
using demwb_lammps_test::scratch;

/// Runs both engines and returns the scaled differences per column (printed for the record).
std::map<std::string, double> matched_differences(const cases::Scene& scene,
                                                  const std::string& test) {
  const cases::RunResult lammps =
      reference::run_engine(reference::LammpsEngine{}, scene, scratch(test));
  const cases::RunResult inhouse = reference::run_engine(
      reference::InhouseEngine{}, reference::matched_scene(scene, "lammps"), {});
  EXPECT_EQ(lammps.status, cases::RunStatus::ok) << lammps.reason << "\n" << lammps.log_tail;
  EXPECT_EQ(inhouse.status, cases::RunStatus::ok) << inhouse.reason;
  EXPECT_EQ(lammps.trace.columns(), inhouse.trace.columns());
  EXPECT_EQ(lammps.trace.rows(), inhouse.trace.rows());
  const auto diff = scaled_differences(scene, inhouse.trace, lammps.trace);
  for (const auto& [column, d] : diff) std::cout << fmt::format("  {:<14} {:.3e}\n", column, d);
  return diff;
}

/// Damped copy of a canonical case.
cases::Scene damped(cases::Scene scene, double restitution) {
  scene.model.damping = "restitution";
  for (auto& m : scene.materials) m.restitution = restitution;
  return scene;
}

void expect_round_off(const std::map<std::string, double>& diff, double tolerance) {
  for (const auto& [column, d] : diff) EXPECT_LE(d, tolerance) << column;
}

/// Agreement required of the matched runs. Both codes perform the same operations in the same
/// order up to the last bits (mass 4/3·π·ρ·r³ vs 4π/3·r³·ρ, (Δt/2m)·F vs (Δt/2)·(F/m),
/// x/d vs x·(1/d)), so positions and velocities agree to a few 1e-16 of their scales. The overlap and
/// the forces that follow from it are differences of centre distances of size r_p + r_q ≈ 0.11 m,
/// whose last bit (1.4e-17 m) is already 1.7e-14 of δ_max; measured worst 2.3e-14. 1e-12 allows
/// ~60 such bits and is still nine orders below the native (integrator) discrepancy.
constexpr double kMatchedTolerance = 1e-12;

/// A glancing 3-D collision under gravity with spin: every column non-trivial.
cases::Scene oblique_with_gravity_and_spin() {
  cases::Scene scene = damped(canonical("single_collision"), 0.7);
  scene.name = "oblique";
  scene.gravity = {0.0, 0.0, -9.81};
  scene.integration.rotation = true;
  scene.particles[0].velocity = {4.0, 0.5, 0.3};
  scene.particles[0].angular_velocity = {10.0, -20.0, 30.0};
  scene.particles[1].position = {0.1102, 0.012, -0.004};
  return scene;
}

/// Two mobile spheres of different sizes meeting head-on: m* = m_p m_q/(m_p + m_q) in η.
cases::Scene two_mobile_spheres() {
  cases::Scene scene = damped(canonical("single_collision"), 0.5);
  scene.name = "head_on";
  scene.particles[1].fixed = false;
  scene.particles[1].radius = 0.02;
  scene.particles[1].effect_radius = 0.02;
  scene.particles[1].position = {0.0302, 0.0, 0.0};
  scene.particles[1].velocity = {-2.0, 0.0, 0.0};
  scene.output.trace_particles = {0, 1};
  return scene;
}

TEST(LammpsMatchedNumerics, SingleCollisionAgreesToRoundOff) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_round_off(matched_differences(canonical("single_collision"), "matched_single"),
                   kMatchedTolerance);
}

TEST(LammpsMatchedNumerics, SandwichAgreesToRoundOff) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_round_off(matched_differences(canonical("sandwich"), "matched_sandwich"),
                   kMatchedTolerance);
}

TEST(LammpsMatchedNumerics, DampedSingleCollisionAgreesToRoundOff) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_round_off(
      matched_differences(damped(canonical("single_collision"), 0.5), "matched_single_damped"),
      kMatchedTolerance);
}

TEST(LammpsMatchedNumerics, DampedSandwichAgreesToRoundOff) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_round_off(
      matched_differences(damped(canonical("sandwich"), 0.5), "matched_sandwich_damped"),
      kMatchedTolerance);
}

TEST(LammpsMatchedNumerics, ObliqueCollisionWithGravityAndSpinAgreesToRoundOff) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_round_off(matched_differences(oblique_with_gravity_and_spin(), "matched_oblique"),
                   kMatchedTolerance);
}

TEST(LammpsMatchedNumerics, TwoMobileSpheresAgreeToRoundOff) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  expect_round_off(matched_differences(two_mobile_spheres(), "matched_head_on"),
                   kMatchedTolerance);
}

TEST(LammpsMatchedNumerics, ClampedDashpotAgreesToRoundOff) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  cases::Scene scene = damped(canonical("single_collision"), 0.3);
  scene.model.clamp_tensile = true;  // LAMMPS: limit_damping
  expect_round_off(matched_differences(scene, "matched_clamped"), kMatchedTolerance);
}

}  // namespace
