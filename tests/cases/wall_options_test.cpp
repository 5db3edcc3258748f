// SPDX-License-Identifier: MIT
// Walls as users write them: `rigid = true` (the wall adds no compliance), a material per wall,
// and a particle velocity aimed at a named wall as a speed and an incidence angle.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "case_texts.hpp"
#include "cases/case_loader.hpp"
#include "dem/contact/pair_table.hpp"

namespace wall_options_test {

using case_texts::error_of;
using case_texts::replaced;

/// One glass sphere above a floor and beside a side wall; each wall has its own material.
constexpr std::string_view kWalls = R"([case]
name = "walls"

[model]
normal = "hertz"

[materials.glass]
density = 2500.0
youngs_modulus = 1.0e8
poisson_ratio = 0.3
friction = 0.5

[materials.steel]
density = 7800.0
youngs_modulus = 2.0e11
poisson_ratio = 0.29
friction = 0.1

[[walls]]
type = "plane"
name = "floor"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
material = "steel"
rigid = true

[[walls]]
type = "plane"
name = "side"
point = [-0.1, 0.0, 0.0]
normal = [1.0, 0.0, 0.0]
material = "glass"

[[particles]]
radius = 0.005
material = "glass"
position = [0.0, 0.0, 0.01]
velocity = { speed = 2.0, wall = "floor", incidence = 30.0, direction = [0.0, 1.0, 0.0] }

[integration]
scheme = "velocity_verlet"
timestep = 1.0e-6
duration = 1.0e-4
)";

TEST(RigidWall, AMaterialOnlyRigidWallsUseBecomesRigidInPlace) {
  const cases::Scene s = cases::load_case_text(kWalls, "case.toml");
  ASSERT_EQ(s.materials.size(), 2U);  // no copy: steel is used by the rigid floor alone
  EXPECT_TRUE(s.walls[0].rigid);
  EXPECT_FALSE(s.walls[1].rigid);
  EXPECT_TRUE(s.materials[1].rigid);
  EXPECT_FALSE(s.materials[0].rigid);
  const dem::PairTable t(s.materials, s.mixing, s.pair_overrides, s.model);
  // Glass on the rigid floor: E* = E/(1 − ν²) of glass alone; μ = min(0.5, 0.1).
  EXPECT_DOUBLE_EQ(*t.properties(0, s.walls[0].material).effective_modulus, 1.0e8 / (1.0 - 0.09));
  EXPECT_DOUBLE_EQ(*t.properties(0, s.walls[0].material).friction, 0.1);
  // Glass on the compliant glass side wall: eq 3.13 with both halves, μ = 0.5.
  EXPECT_DOUBLE_EQ(*t.properties(0, s.walls[1].material).effective_modulus, 1.0e8 / (2.0 * 0.91));
  EXPECT_DOUBLE_EQ(*t.properties(0, s.walls[1].material).friction, 0.5);
}

TEST(RigidWall, AMaterialParticlesAlsoUseGetsARigidCopyWithItsPairEntries) {
  // The side wall is rigid too, but glass is the particles' material: a rigid copy is made.
  std::string text = replaced(std::string(kWalls), "material = \"glass\"\n\n[[particles]]",
                              "material = \"glass\"\nrigid = true\n\n[[particles]]");
  text += "\n[[pairs]]\nmaterials = [\"glass\", \"glass\"]\nfriction = 0.3\n";
  const cases::Scene s = cases::load_case_text(text, "case.toml");
  ASSERT_EQ(s.materials.size(), 3U);
  EXPECT_EQ(s.materials[2].name, "glass (rigid)");
  EXPECT_TRUE(s.materials[2].rigid);
  EXPECT_FALSE(s.materials[0].rigid);  // the particle keeps the compliant glass
  EXPECT_EQ(s.particles[0].material, 0U);
  EXPECT_EQ(s.walls[1].material, 2U);
  const dem::PairTable t(s.materials, s.mixing, s.pair_overrides, s.model);
  EXPECT_DOUBLE_EQ(*t.properties(0, 2).effective_modulus, 1.0e8 / 0.91);
  // The measured glass–glass friction carries over to glass against the rigid glass wall.
  EXPECT_DOUBLE_EQ(*t.properties(0, 2).friction, 0.3);
  EXPECT_DOUBLE_EQ(*t.properties(0, 0).friction, 0.3);
}

TEST(RigidWall, ARigidWallsMaterialNeedsNoElasticConstants) {
  std::string text = replaced(std::string(kWalls), "youngs_modulus = 2.0e11\npoisson_ratio = 0.29\n", "");
  const cases::Scene s = cases::load_case_text(text, "case.toml");
  const dem::PairTable t(s.materials, s.mixing, s.pair_overrides, s.model);
  EXPECT_DOUBLE_EQ(std::get<dem::HertzNormal>(t.law(0, 1).normal).effective_modulus, 1.0e8 / 0.91);
  // Without `rigid` the same wall is an error naming the missing property.
  const auto e = error_of(replaced(text, "rigid = true\n", ""));
  EXPECT_NE(std::string(e.what()).find("'effective_modulus'"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("glass–steel"), std::string::npos) << e.what();
}

TEST(RigidWall, RigidOnABoxMakesEveryFaceRigidAndMustBeABoolean) {
  std::string text = replaced(std::string(kWalls), R"(type = "plane"
name = "floor"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0])", R"(type = "box"
name = "bin"
min = [-0.05, -0.05, 0.0]
max = [0.05, 0.05, 0.1])");
  text = replaced(text, "wall = \"floor\"", "wall = \"bin.z-\"");
  const cases::Scene s = cases::load_case_text(text, "case.toml");
  ASSERT_EQ(s.walls.size(), 7U);
  for (std::size_t w = 0; w < 6; ++w) EXPECT_TRUE(s.walls[w].rigid) << s.walls[w].name;
  EXPECT_FALSE(s.walls[6].rigid);
  const auto e = error_of(replaced(std::string(kWalls), "rigid = true", "rigid = 1"));
  EXPECT_EQ(e.key(), "walls[0].rigid") << e.what();
}

TEST(AimedVelocity, IsSpeedTimesSinThetaAlongTheHeadingMinusCosThetaAlongTheNormal) {
  const cases::Scene s = cases::load_case_text(kWalls, "case.toml");
  const auto& u = s.particles[0].velocity;
  const double theta = 30.0 * std::numbers::pi / 180.0;
  EXPECT_DOUBLE_EQ(u[0], 0.0);
  EXPECT_DOUBLE_EQ(u[1], 2.0 * std::sin(theta));
  EXPECT_DOUBLE_EQ(u[2], -2.0 * std::cos(theta));
  // At the side wall (normal +x) with a heading that is not in its plane: the in-plane part is used.
  const cases::Scene side = cases::load_case_text(
      replaced(std::string(kWalls), "wall = \"floor\", incidence = 30.0, direction = [0.0, 1.0, 0.0]",
               "wall = 1, incidence = 60.0, direction = [3.0, 0.0, -4.0]"),
      "case.toml");
  const auto& v = side.particles[0].velocity;
  EXPECT_NEAR(v[0], -2.0 * 0.5, 1e-15);
  EXPECT_DOUBLE_EQ(v[1], 0.0);
  EXPECT_NEAR(v[2], -2.0 * std::sin(60.0 * std::numbers::pi / 180.0), 1e-15);
  // Normal incidence needs no heading.
  const cases::Scene head_on = cases::load_case_text(
      replaced(std::string(kWalls), "incidence = 30.0, direction = [0.0, 1.0, 0.0]", "incidence = 0.0"),
      "case.toml");
  EXPECT_EQ(head_on.particles[0].velocity, (cases::Vector3{0.0, 0.0, -2.0}));
}

TEST(AimedVelocity, BadValuesNameTheKeyAndTheProblem) {
  const std::string text(kWalls);
  const std::string aim = "{ speed = 2.0, wall = \"floor\", incidence = 30.0, direction = [0.0, 1.0, 0.0] }";
  struct Bad {
    std::string velocity;
    std::string key;
    std::string says;
  };
  const Bad bad[] = {
      {"{ speed = 2.0, wall = \"floor\", incidence = 30.0 }", "particles[0].velocity.direction", "missing"},
      {"{ speed = 2.0, wall = \"floor\", incidence = 90.0, direction = [0.0, 1.0, 0.0] }",
       "particles[0].velocity.incidence", "90"},
      {"{ speed = 2.0, wall = \"floor\", incidence = -5.0, direction = [0.0, 1.0, 0.0] }",
       "particles[0].velocity.incidence", "0"},
      {"{ speed = 0.0, wall = \"floor\", incidence = 30.0, direction = [0.0, 1.0, 0.0] }",
       "particles[0].velocity.speed", "0"},
      {"{ speed = 2.0, wall = \"ceiling\", incidence = 30.0, direction = [0.0, 1.0, 0.0] }",
       "particles[0].velocity.wall", "'floor', 'side'"},
      {"{ speed = 2.0, wall = 7, incidence = 30.0, direction = [0.0, 1.0, 0.0] }",
       "particles[0].velocity.wall", "7"},
      {"{ speed = 2.0, wall = \"floor\", incidence = 30.0, direction = [0.0, 0.0, 2.0] }",
       "particles[0].velocity.direction", "plane of wall 'floor'"},
      {"{ speed = 2.0, wall = \"floor\", incidence = 30.0, direction = [0.0, 1.0, 0.0], spin = 1.0 }",
       "particles[0].velocity.spin", "unknown"},
      {"{ wall = \"floor\", incidence = 30.0, direction = [0.0, 1.0, 0.0] }", "particles[0].velocity.speed",
       "missing"},
  };
  for (const Bad& b : bad) {
    const auto e = error_of(replaced(text, aim, b.velocity));
    EXPECT_EQ(e.key(), b.key) << b.velocity << "\n" << e.what();
    EXPECT_NE(std::string(e.what()).find(b.says), std::string::npos) << b.velocity << "\n" << e.what();
  }
}

TEST(AimedVelocity, ACaseWithoutWallsSaysThereIsNothingToAimAt) {
  std::string text(kWalls);
  const auto from = text.find("[[walls]]");
  const auto to = text.find("[[particles]]");
  text.erase(from, to - from);
  const auto e = error_of(text);
  EXPECT_EQ(e.key(), "particles[0].velocity.wall") << e.what();
  EXPECT_NE(std::string(e.what()).find("no [[walls]]"), std::string::npos) << e.what();
}

}  // namespace wall_options_test
