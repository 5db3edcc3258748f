// SPDX-License-Identifier: MIT
// Mesh walls on the real YADE (label `reference`): each facet a utils.facet, against the core in
// YADE's numerics (docs/engines.md, "YADE": meshes). Spheres on a lone triangle's face, over its
// free edge and onto its corner agree at round-off with friction and spin; over a floor's seams
// YADE pushes with every facet in reach, which the run's conventions say.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "mesh_test_support.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/matching.hpp"
#include "support/text_file.hpp"
#include "yade_test_support.hpp"

namespace yade_mesh_test {

using namespace demwb_yade_test;
using demwb_mesh_test::column_gap;

/// Hertz–Mindlin glass with friction in YADE's form (clipped normal force, incremental shear).
std::string glass() { return demwb_mesh_test::glass_hertz_mindlin("clamp_tensile = true\nmindlin_form = \"incremental\"\n"); }

/// One triangle at z = 0 with corners (−20, −20), (30, −20), (−20, 30) mm.
constexpr std::string_view kPlateStl = R"(solid plate
  facet normal 0 0 1
    outer loop
      vertex -0.02 -0.02 0
      vertex 0.03 -0.02 0
      vertex -0.02 0.03 0
    endloop
  endfacet
endsolid plate
)";

/// A case of `particles` over the mesh in `stl`, written with the STL into a scratch folder.
cases::Scene mesh_case(const std::string& name, std::string_view stl, const std::string& particles, double duration) {
  const std::filesystem::path dir = scratch(name + "-case");
  support::write_file(dir / "mesh.stl", std::string(stl));
  const std::string text = fmt::format(R"([case]
name = "{}"
{}[[walls]]
type = "mesh"
name = "mesh"
file = "mesh.stl"
material = "glass"
{}[fields]
gravity = [0.0, 0.0, -9.81]
[integration]
scheme = "velocity_verlet"
timestep = 2.0e-7
duration = {}
rotation = true
[output]
trace_every = 250
trace_particles = [0, 1, 2, 3]
)",
                                       name, glass(), particles, duration);
  support::write_file(dir / "case.toml", text);
  return cases::load_case(dir / "case.toml");
}

/// A sphere of radius r at `position` with velocity v and spin w.
std::string sphere(double r, std::array<double, 3> x, std::array<double, 3> v, std::array<double, 3> w) {
  return fmt::format(R"([[particles]]
radius = {}
material = "glass"
position = [{}, {}, {}]
velocity = [{}, {}, {}]
angular_velocity = [{}, {}, {}]
)",
                     r, x[0], x[1], x[2], v[0], v[1], v[2], w[0], w[1], w[2]);
}

/// YADE and the core in YADE's numerics on `scene`.
std::pair<cases::RunResult, cases::RunResult> run_both(const cases::Scene& scene, const std::string& name) {
  EXPECT_TRUE(reference::YadeEngine{}.supports(scene).supported()) << reference::YadeEngine{}.supports(scene).explain();
  cases::RunResult yade = reference::run_engine(reference::YadeEngine{}, scene, {scratch(name), 120.0});
  EXPECT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  cases::RunResult core = reference::run_engine(reference::InhouseEngine{}, reference::matched_scene(scene, "yade"), {});
  EXPECT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  return {std::move(core), std::move(yade)};
}

TEST(YadeMeshes, SpheresOnAFacetsFaceOverItsEdgeAndOntoItsCornerAreTheMatchedCoreAtRoundOff) {
  DEMWB_REQUIRE_YADE();
  // Two spinning spheres slide and roll on the face, one drops onto the corner (−20, −20) mm
  // from outside the triangle, one rolls off the free edge x + y = 10 mm: face, corner and edge
  // contacts with friction, 20 ms.
  const std::string particles = sphere(0.001, {-0.006, -0.004, 0.0012}, {0.5, 0.3, -0.1}, {0.0, 0.0, 40.0}) +
                                sphere(0.0008, {0.004, 0.003, 0.0009}, {-0.2, 0.45, -0.05}, {60.0, 0.0, 0.0}) +
                                sphere(0.0008, {-0.0204, -0.0203, 0.0009}, {0.1, 0.05, -0.1}, {0.0, 0.0, 0.0}) +
                                sphere(0.0008, {0.004, 0.0049, 0.00081}, {0.3, 0.3, 0.0}, {-300.0, 300.0, 10.0});
  const cases::Scene scene = mesh_case("plate", kPlateStl, particles, 0.02);
  const auto [core, yade] = run_both(scene, "plate");
  ASSERT_EQ(yade.status, cases::RunStatus::ok);
  // Measured: positions 6e-17 m, velocities 2e-14 m/s, spins 1e-11 rad/s of 225. The Mindlin
  // stiffness against a facet comes from the compensated material (YADE's R = 2r/3).
  // Forces: 2e-18 N of 2e-2 (the contact forces with gravity, F(x(n)) of each row).
  for (int p = 0; p < 4; ++p) {
    for (const char* q : {"x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz", "fx", "fy", "fz"}) {
      const std::string column = fmt::format("p{}.{}", p, q);
      const auto [worst, scale] = column_gap(core, yade, column);
      const bool position = q[1] == '\0';
      EXPECT_LE(worst, position ? 1e-15 : 1e-12 * scale) << column;
    }
  }
  // The contacts happened: friction spun the first sphere up about x and y, the third rose off
  // the corner it fell on, the fourth went over the edge and below the plate.
  EXPECT_GT(max_abs(*yade.trace.column("p0.wy")), 100.0);
  EXPECT_GT(yade.trace.column("p2.z")->back(), 0.001);
  EXPECT_GT(yade.trace.column("p3.x")->back() + yade.trace.column("p3.y")->back(), 0.011);
  EXPECT_LT(yade.trace.column("p3.z")->back(), 0.0);
  EXPECT_TRUE(yade.conventions.contains("facet contact radius"));
  // The native core (velocity Verlet) is not YADE's numerics: it parts at 1e-8 m, so the
  // agreement above is the matching's.
  const cases::RunResult native = reference::run_engine(reference::InhouseEngine{}, scene, {});
  EXPECT_GT(column_gap(native, yade, "p0.x").first, 1e-10);
}

TEST(YadeMeshes, OverAFloorsSeamsYadePushesWithEveryFacetInReachAsItsConventionsSay) {
  DEMWB_REQUIRE_YADE();
  // The first sphere rests on the floor 1 mm from the seam x = −5 mm and rolls across seams;
  // YADE adds the neighbour facets' edge contacts the core does not count, and the runs part at
  // order one of the motion. Two spheres dropped straight down inside one facet each, a
  // millimetre or more from any seam, still agree at round-off.
  const std::string particles = sphere(0.001, {-0.006, -0.004, 0.000999}, {0.5, 0.3, -0.1}, {0.0, 0.0, 40.0}) +
                                sphere(0.0008, {0.004, 0.003, 0.0009}, {-0.2, 0.45, -0.05}, {60.0, 0.0, 0.0}) +
                                sphere(0.0008, {-0.0085, 0.006, 0.003}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}) +
                                sphere(0.0008, {0.0075, -0.0075, 0.003}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0});
  const cases::Scene scene = mesh_case("floor", demwb_mesh_test::flat_floor_stl(), particles, 0.01);
  const auto [core, yade] = run_both(scene, "floor");
  ASSERT_EQ(yade.status, cases::RunStatus::ok);
  EXPECT_GT(column_gap(core, yade, "p0.z").first, 1e-5);  // measured 1.7e-4 m
  for (int p = 2; p < 4; ++p) {  // dropped inside one facet each, never near a seam
    const auto [worst, scale] = column_gap(core, yade, fmt::format("p{}.z", p));
    EXPECT_LE(worst, 1e-15) << p;
  }
  const auto facets = yade.conventions.find("mesh facets");
  ASSERT_NE(facets, yade.conventions.end());
  EXPECT_NE(facets->second.find("agree while no sphere touches an edge or corner that two facets share"),
            std::string::npos);
}

}  // namespace yade_mesh_test
