// SPDX-License-Identifier: MIT
// Mesh walls as users write them: `type = "mesh"` reads an STL file beside the case, scales and
// moves it, and becomes one triangle wall per facet whose mesh the core welds and whose file's
// bytes enter the scene's fingerprint; a sphere dropped on it rests on it; a missing or broken
// file and bad keys are errors naming the key.
#include <filesystem>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "case_texts.hpp"
#include "cases/case_loader.hpp"
#include "cases/core_wall.hpp"
#include "dem/simulation/simulation.hpp"
#include "support/sha256.hpp"
#include "support/text_file.hpp"

namespace mesh_wall_loader_test {

using case_texts::replaced;

/// A 4 × 4 mm square floor of two triangles, in millimetres, and a pyramid's four sides above it.
constexpr std::string_view kFloorStl = R"(solid floor
  facet normal 0 0 1
    outer loop
      vertex 0 0 0
      vertex 4 0 0
      vertex 4 4 0
    endloop
  endfacet
  facet normal 0 0 1
    outer loop
      vertex 0 0 0
      vertex 4 4 0
      vertex 0 4 0
    endloop
  endfacet
endsolid floor
)";

constexpr std::string_view kCase = R"([case]
name = "mesh_floor"

[model]
normal = "linear"

[materials.glass]
density = 2500.0
normal_stiffness = 1.0e3

[[walls]]
type = "mesh"
name = "floor"
file = "floor.stl"
scale = 1.0e-3
translate = [-2.0e-3, -2.0e-3, 1.0e-3]
material = "glass"

[[particles]]
radius = 5.0e-4
material = "glass"
position = [1.0e-4, 2.0e-4, 2.0e-3]

[fields]
gravity = [0.0, 0.0, -9.81]

[integration]
scheme = "velocity_verlet"
timestep = 1.0e-6
duration = 0.05
)";

/// A scratch folder holding the floor's STL, removed at the end of the test.
class MeshCase : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("demwb-mesh-loader-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(dir_);
    support::write_file(dir_ / "floor.stl", std::string(kFloorStl));
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  [[nodiscard]] cases::Scene load(const std::string& text) const {
    return cases::load_case_text(text, (dir_ / "case.toml").string());
  }
  /// The CaseError of loading `text` from the scratch folder.
  [[nodiscard]] cases::CaseError error_of(const std::string& text) const {
    try {
      static_cast<void>(load(text));
    } catch (const cases::CaseError& e) {
      return e;
    }
    ADD_FAILURE() << "no CaseError";
    return cases::CaseError("case.toml", "(none)", "no error");
  }
  void expect_error(const std::string& from, const std::string& to, const std::string& key,
                    const std::string& says) const {
    const cases::CaseError e = error_of(replaced(std::string(kCase), from, to));
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
  }

  std::filesystem::path dir_;
};

TEST_F(MeshCase, EachFacetBecomesATriangleWallScaledAndMovedAndTheMeshIsRecorded) {
  const cases::Scene s = load(std::string(kCase));
  ASSERT_EQ(s.walls.size(), 2U);
  ASSERT_EQ(s.meshes.size(), 1U);
  EXPECT_EQ(s.meshes[0].name, "floor");
  EXPECT_EQ(s.meshes[0].file, "floor.stl");
  EXPECT_EQ(s.meshes[0].facets, 2U);
  EXPECT_EQ(s.meshes[0].sha256, support::sha256_hex(kFloorStl));
  EXPECT_EQ(s.walls[1].name, "floor.1");
  EXPECT_EQ(cases::wall_shape_name(s.walls[1]), "mesh");
  EXPECT_EQ(s.walls[1].mesh, 0U);
  EXPECT_EQ(s.walls[1].corners[1], (cases::Vector3{2.0e-3, 2.0e-3, 1.0e-3}));  // 4 mm × 1e-3 − 2 mm
  EXPECT_EQ(s.walls[1].corners[2], (cases::Vector3{-2.0e-3, 2.0e-3, 1.0e-3}));
  std::vector<dem::Wall> walls;
  for (const auto& w : s.walls) walls.push_back(cases::core_wall(w));
  EXPECT_EQ(walls[0].shape, dem::WallShape::triangle);
  EXPECT_NEAR(walls[0].normal.z(), 1.0, 1e-15);
  const std::vector<dem::MeshTopology> meshes = cases::core_meshes(s, walls);
  ASSERT_EQ(meshes.size(), 1U);
  EXPECT_EQ(meshes[0].corners.size(), 4U);  // the diagonal's two corners are shared
  EXPECT_EQ(walls[1].mesh, 0U);
}

TEST_F(MeshCase, ASphereDroppedOnTheMeshBouncesOnItAsOnThePlaneThrough) {
  // Dropped 0.5 mm beside the floor's diagonal seam, it bounces (no damping) on the mesh exactly as
  // on the plane z = 1 mm, and never goes through.
  const cases::Scene s = load(std::string(kCase));
  const auto run = [&](bool mesh) {
    dem::SimulationSetup setup;
    setup.materials = s.materials;
    setup.model = s.model;
    if (mesh) {
      for (const auto& w : s.walls) setup.walls.push_back(cases::core_wall(w));
      setup.meshes = cases::core_meshes(s, setup.walls);
    } else {
      setup.walls = {dem::Wall{dem::Vec3(0, 0, 1e-3), dem::Vec3::UnitZ()}};
    }
    const auto& p = s.particles[0];
    setup.particles.push_back({p.radius, p.radius, 2500.0, 0, dem::Vec3(p.position[0], p.position[1], p.position[2]),
                               dem::Vec3::Zero(), dem::Vec3::Zero(), false});
    setup.fields.gravity = dem::Vec3(0, 0, -9.81);
    setup.timestep = 1e-6;
    setup.scheme_settings.rotation = false;
    dem::Simulation sim(setup);
    double lowest = 1.0;
    for (int k = 0; k < 30000; ++k) {
      sim.step();
      lowest = std::min(lowest, sim.state().position(2, 0));
    }
    return std::pair{lowest, sim.state().position(2, 0)};
  };
  const auto [lowest_mesh, end_mesh] = run(true);
  const auto [lowest_plane, end_plane] = run(false);
  EXPECT_LT(lowest_plane, 1.5e-3);  // it pressed into the floor
  EXPECT_GT(lowest_plane, 1.0e-3);
  EXPECT_NEAR(lowest_mesh, lowest_plane, 1e-12);
  EXPECT_NEAR(end_mesh, end_plane, 1e-12);
}

TEST_F(MeshCase, TheFilesBytesEnterTheScenesFingerprint) {
  const cases::Scene before = load(std::string(kCase));
  support::write_file(dir_ / "floor.stl", replaced(std::string(kFloorStl), "vertex 0 4 0", "vertex 0 4 0.5"));
  const cases::Scene after = load(std::string(kCase));
  EXPECT_NE(before.meshes[0].sha256, after.meshes[0].sha256);
  EXPECT_NE(before.walls[1].corners[2], after.walls[1].corners[2]);
}

TEST_F(MeshCase, BadFilesAndKeysAreErrorsNamingTheKey) {
  expect_error("file = \"floor.stl\"", "file = \"absent.stl\"", "walls[0].file", "absent.stl");
  expect_error("file = \"floor.stl\"", "file = \"\"", "walls[0].file", "must name an STL file");
  expect_error("scale = 1.0e-3", "scale = -1.0", "walls[0].scale", "must be > 0, got -1");
  expect_error("scale = 1.0e-3", "scale = 1.0e-3\nrotate = 1.0", "walls[0].rotate", "unknown key 'rotate'");
  expect_error("file = \"floor.stl\"\n", "", "walls[0].file", "missing required");
  support::write_file(dir_ / "broken.stl", std::string(kFloorStl.substr(0, 120)));
  expect_error("file = \"floor.stl\"", "file = \"broken.stl\"", "walls[0].file", "broken.stl");
  // A facet that collapses once moved far away: 4 µm triangles at 1e12 m.
  const cases::CaseError far = error_of(replaced(replaced(std::string(kCase), "scale = 1.0e-3", "scale = 1.0e-6"),
                                                 "translate = [-2.0e-3, -2.0e-3, 1.0e-3]", "translate = [1.0e12, 0.0, 0.0]"));
  EXPECT_EQ(far.key(), "walls[0].file") << far.what();
  EXPECT_NE(std::string(far.what()).find("has no area once scaled"), std::string::npos) << far.what();
}

}  // namespace mesh_wall_loader_test
