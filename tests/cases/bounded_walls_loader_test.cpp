// SPDX-License-Identifier: MIT
// Bounded walls as users write them (rectangle, disc, cylinder, cone, remove_at) and the
// discharge outlet ([compare.discharge]): what each key becomes, and bad input rejected with an
// error naming the key.
#include <string>

#include <gtest/gtest.h>

#include "case_texts.hpp"
#include "cases/case_loader.hpp"
#include "cases/core_wall.hpp"

namespace bounded_walls_loader_test {

using case_texts::error_of;
using case_texts::replaced;

/// A funnel of glass: a cylinder on a cone over a ring, a catch plate, one sphere.
constexpr std::string_view kFunnel = R"([case]
name = "funnel"

[model]
normal = "linear"

[materials.glass]
density = 2500.0
normal_stiffness = 1.0e3

[[walls]]
type = "cylinder"
name = "tube"
base = [0.0, 0.0, 0.01]
axis = [0.0, 0.0, 2.0]
height = 0.02
radius = 0.008
material = "glass"

[[walls]]
type = "cone"
name = "funnel"
base = [0.0, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]
height = 0.01
base_radius = 0.003
top_radius = 0.008
material = "glass"

[[walls]]
type = "disc"
name = "floor"
centre = [0.0, 0.0, -0.004]
normal = [0.0, 0.0, 1.0]
radius = 0.008
hole_radius = 0.002
material = "glass"
remove_at = 0.005

[[walls]]
type = "rectangle"
name = "plate"
centre = [0.0, 0.0, -0.01]
normal = [0.0, 0.0, 1.0]
axis = [1.0, 0.0, 0.0]
size = [0.02, 0.01]
material = "glass"
rigid = true

[[particles]]
radius = 0.001
material = "glass"
position = [0.0, 0.0, 0.02]

[fields]
gravity = [0.0, 0.0, -9.81]

[integration]
scheme = "velocity_verlet"
timestep = 1.0e-5
duration = 0.01
)";

TEST(BoundedWallKeys, BecomeTheCoresShapes) {
  const cases::Scene s = cases::load_case_text(kFunnel, "case.toml");
  ASSERT_EQ(s.walls.size(), 4U);
  const dem::Wall tube = cases::core_wall(s.walls[0]);
  EXPECT_EQ(tube.shape, dem::WallShape::frustum);
  EXPECT_EQ(tube.normal, dem::Vec3(0, 0, 1));  // the axis is scaled to unit length
  EXPECT_EQ(tube.size_u, 0.008);
  EXPECT_EQ(tube.size_v, 0.008);
  EXPECT_EQ(tube.length, 0.02);
  EXPECT_EQ(cases::wall_shape_name(s.walls[0]), "cylinder");
  EXPECT_EQ(cases::wall_shape_name(s.walls[1]), "cone");
  EXPECT_EQ(s.walls[1].size_u, 0.003);
  EXPECT_EQ(s.walls[1].size_v, 0.008);
  const dem::Wall floor = cases::core_wall(s.walls[2]);
  EXPECT_EQ(floor.shape, dem::WallShape::annulus);
  EXPECT_EQ(floor.size_u, 0.002);
  EXPECT_EQ(floor.size_v, 0.008);
  EXPECT_EQ(floor.removed_at, 0.005);
  EXPECT_TRUE(floor.present(0.0049));
  EXPECT_FALSE(floor.present(0.005));
  const dem::Wall plate = cases::core_wall(s.walls[3]);
  EXPECT_EQ(plate.shape, dem::WallShape::rectangle);
  EXPECT_EQ(plate.size_u, 0.01);  // half of the sides
  EXPECT_EQ(plate.size_v, 0.005);
  EXPECT_EQ(plate.axis_u, dem::Vec3(1, 0, 0));
  EXPECT_TRUE(plate.present(1e300));  // never removed
  EXPECT_TRUE(s.walls[3].rigid);
}

TEST(BoundedWallKeys, RemoveAtOnABoxRemovesEveryFace) {
  const std::string text = replaced(std::string(kFunnel), R"([[walls]]
type = "rectangle")", R"([[walls]]
type = "box"
name = "bin"
min = [-0.02, -0.02, -0.03]
max = [0.02, 0.02, 0.04]
material = "glass"
remove_at = 0.002

[[walls]]
type = "rectangle")");
  const cases::Scene s = cases::load_case_text(text, "case.toml");
  int removed = 0;
  for (const auto& w : s.walls) {
    if (w.name.rfind("bin.", 0) == 0) {
      ASSERT_TRUE(w.removed_at.has_value()) << w.name;
      EXPECT_EQ(*w.removed_at, 0.002);
      ++removed;
    }
  }
  EXPECT_EQ(removed, 6);
}

/// The error of kFunnel with `from` replaced by `to`; expects it to name `key`.
void expect_error(const std::string& from, const std::string& to, const std::string& key, const std::string& says) {
  const auto e = error_of(replaced(std::string(kFunnel), from, to));
  EXPECT_EQ(e.key(), key) << e.what();
  EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
}

TEST(BoundedWallKeys, BadValuesAreErrorsNamingTheKey) {
  expect_error("axis = [1.0, 0.0, 0.0]", "axis = [1.0, 0.0, 0.5]", "walls[3].axis", "orthogonal");
  expect_error("size = [0.02, 0.01]", "size = [0.02]", "walls[3].size", "two side lengths");
  expect_error("size = [0.02, 0.01]", "size = [0.02, -0.01]", "walls[3].size[1]", "");
  expect_error("hole_radius = 0.002", "hole_radius = 0.008", "walls[2].hole_radius", "smaller than radius");
  expect_error("remove_at = 0.005", "remove_at = -1.0", "walls[2].remove_at", "");
  expect_error("base_radius = 0.003\ntop_radius = 0.008", "base_radius = 0.0\ntop_radius = 0.0", "walls[1].top_radius",
               "both be 0");
  expect_error("height = 0.01\nbase_radius", "height = 0.0\nbase_radius", "walls[1].height", "");
  expect_error("axis = [0.0, 0.0, 2.0]", "axis = [0.0, 0.0, 0.0]", "walls[0].axis", "nonzero");
  expect_error("radius = 0.008\nmaterial = \"glass\"\n\n[[walls]]\ntype = \"cone\"",
               "radius = 0.008\nbase_radius = 0.001\nmaterial = \"glass\"\n\n[[walls]]\ntype = \"cone\"",
               "walls[0].base_radius", "");
  expect_error("type = \"cylinder\"", "type = \"tube\"", "walls[0].type", "");
}

TEST(BoundedWallKeys, PeriodicDomainsAndAimingNeedPlanes) {
  expect_error("[integration]", "[domain]\nmin = [-0.05, -0.05, -0.05]\nmax = [0.05, 0.05, 0.05]\nperiodic = [\"x\"]\n\n[integration]",
               "domain.periodic", "bounded walls have no periodic images");
  expect_error("position = [0.0, 0.0, 0.02]",
               "position = [0.0, 0.0, 0.02]\nvelocity = { speed = 1.0, wall = \"funnel\", incidence = 30.0, direction = "
               "[1.0, 0.0, 0.0] }",
               "particles[0].velocity.wall", "needs a plane wall");
}

/// kFunnel with the discharge metrics measured below the floor.
std::string with_discharge(const std::string& discharge, const std::string& output) {
  return std::string(kFunnel) + R"(
[compare]
engines = ["inhouse"]
metrics = ["mass_flow_rate", "discharged_fraction"]
)" + discharge + output;
}

TEST(DischargeKeys, AreReadAndChecked) {
  const std::string outlet = "[compare.discharge]\npoint = [0.0, 0.0, -0.005]\ndirection = [0.0, 0.0, -3.0]\n";
  const std::string every = "[output]\nsnapshot_every = 0.001\n";
  const cases::Scene s = cases::load_case_text(with_discharge(outlet + "fit = [0.1, 0.9]\n", every), "case.toml");
  ASSERT_TRUE(s.compare.discharge.has_value());
  EXPECT_EQ(s.compare.discharge->direction, (cases::Vector3{0.0, 0.0, -1.0}));
  EXPECT_EQ(s.compare.discharge->fit_from, 0.1);
  EXPECT_EQ(s.compare.discharge->fit_to, 0.9);
  EXPECT_EQ(s.output.snapshot_times.size(), 11U);
  // Defaults: the fit window [0.2, 0.6].
  const cases::Scene d = cases::load_case_text(with_discharge(outlet, every), "case.toml");
  EXPECT_EQ(d.compare.discharge->fit_from, 0.2);
  EXPECT_EQ(d.compare.discharge->fit_to, 0.6);

  EXPECT_EQ(error_of(with_discharge("", every)).key(), "compare.metrics");
  EXPECT_EQ(error_of(with_discharge(outlet, "")).key(), "output.snapshot_every");
  EXPECT_EQ(error_of(with_discharge(outlet + "fit = [0.6, 0.2]\n", every)).key(), "compare.discharge.fit");
  EXPECT_EQ(error_of(with_discharge(outlet + "fit = [0.2, 1.5]\n", every)).key(), "compare.discharge.fit[1]");
  EXPECT_EQ(error_of(with_discharge(replaced(outlet, "[0.0, 0.0, -3.0]", "[0.0, 0.0, 0.0]"), every)).key(),
            "compare.discharge.direction");
  EXPECT_EQ(error_of(with_discharge(outlet + "width = 1.0\n", every)).key(), "compare.discharge.width");
}

}  // namespace bounded_walls_loader_test
