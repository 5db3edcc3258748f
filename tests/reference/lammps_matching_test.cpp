// SPDX-License-Identifier: MIT
// reference::matched_scene: the in-house set-up that reproduces a reference engine's numerics.
#include <stdexcept>

#include <gtest/gtest.h>

#include "lammps_scenes.hpp"
#include "reference/common/core_setup.hpp"
#include "reference/matching.hpp"

namespace lammps_matching_test {

TEST(MatchedScene, LammpsIsVelocityVerletWithTheSameTimestep) {
  cases::Scene scene = demwb_lammps_unit::mixed_scene();
  scene.integration.scheme = dem::SchemeId::rk4;
  const cases::Scene matched = reference::matched_scene(scene, "lammps");
  EXPECT_EQ(matched.integration.scheme, dem::SchemeId::velocity_verlet);
  EXPECT_EQ(matched.integration.timestep, scene.integration.timestep);
  EXPECT_EQ(matched.integration.rotation, scene.integration.rotation);
  EXPECT_EQ(matched.particles.size(), scene.particles.size());
  EXPECT_EQ(matched.model.damping, scene.model.damping);
}

TEST(MatchedScene, PinsAnAutomaticTimestepToTheValueTheCaseResolvesTo) {
  cases::Scene scene = demwb_lammps_unit::mixed_scene();
  scene.integration.timestep.reset();
  const cases::Scene matched = reference::matched_scene(scene, "lammps");
  ASSERT_TRUE(matched.integration.timestep.has_value());
  EXPECT_EQ(*matched.integration.timestep, reference::core_setup(reference::PreparedScene(scene)).simulation.timestep);
}

TEST(MatchedScene, RejectsAnEngineWithoutAMatchedVariant) {
  EXPECT_THROW((void)reference::matched_scene(demwb_lammps_unit::mixed_scene(), "nonesuch"),
               std::invalid_argument);
}

}  // namespace
