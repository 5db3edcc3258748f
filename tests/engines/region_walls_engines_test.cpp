// SPDX-License-Identifier: MIT
// Cylinder and cone walls through the real LAMMPS (fix wall/gran/region on regions open at both
// ends): frictionless linear spheres bouncing in a funnel — on its cone, on its cylinder, over the
// orifice's rim and out through it — follow the same paths in the core and in LAMMPS, and a
// shutter removed at t = 0 is left out of the deck.
#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>
#include <string>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "cases/trace.hpp"
#include "lammps_test_support.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/lammps/lammps_engine.hpp"

namespace region_walls_engines_test {

/// A funnel: a cone from radius 3 mm at z = 0 to 10 mm at z = 7 mm under a cylinder of radius
/// 10 mm, a shutter disc under it removed at t = 0, and four frictionless linear spheres (r = 1
/// mm) thrown in off the axis. The linear spring does not depend on the wall's curvature, which
/// LAMMPS' region walls put into R* and the core does not.
constexpr std::string_view kFunnel = R"([case]
name = "funnel"

[model]
normal = "linear"
damping = "restitution"

[materials.bead]
density = 2500.0
normal_stiffness = 2.0e3
restitution = 0.9

[[walls]]
type = "cone"
name = "cone"
base = [0.0, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]
height = 7.0e-3
base_radius = 3.0e-3
top_radius = 1.0e-2
material = "bead"

[[walls]]
type = "cylinder"
name = "tube"
base = [0.0, 0.0, 7.0e-3]
axis = [0.0, 0.0, 1.0]
height = 3.0e-2
radius = 1.0e-2
material = "bead"

[[walls]]
type = "disc"
name = "shutter"
centre = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
radius = 1.0e-2
material = "bead"
remove_at = 0.0

[[particles]]
radius = 1.0e-3
material = "bead"
position = [6.0e-3, 0.0, 1.5e-2]
velocity = [0.3, 0.1, -0.2]

[[particles]]
radius = 1.0e-3
material = "bead"
position = [-2.0e-3, 4.0e-3, 2.0e-2]
velocity = [-0.2, 0.3, 0.0]

[[particles]]
radius = 1.0e-3
material = "bead"
position = [2.6e-3, 0.0, 4.0e-3]
velocity = [0.0, 0.0, -0.1]

[[particles]]
radius = 1.0e-3
material = "bead"
position = [0.0, -7.0e-3, 2.5e-2]
velocity = [0.1, -0.3, -0.5]

[fields]
gravity = [0.0, 0.0, -9.81]

[integration]
scheme = "velocity_verlet"
timestep = 1.0e-5
duration = 0.08
rotation = false

[output]
trace_every = 10
)";

/// `text` with its one `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// Whether one of `reasons` contains `text`.
bool names(const std::vector<std::string>& reasons, std::string_view text) {
  return std::any_of(reasons.begin(), reasons.end(), [&](const std::string& r) { return r.find(text) != std::string::npos; });
}

/// Largest |x_core − x_lammps| over the traced positions of every sphere and row.
double largest_position_difference(const cases::Trace& a, const cases::Trace& b, std::size_t spheres) {
  double worst = 0.0;
  for (std::size_t i = 0; i < spheres; ++i) {
    for (const char* q : {"x", "y", "z"}) {
      const auto* ca = a.column(cases::particle_column(i, q));
      const auto* cb = b.column(cases::particle_column(i, q));
      EXPECT_TRUE(ca != nullptr && cb != nullptr) << cases::particle_column(i, q);
      if (ca == nullptr || cb == nullptr) return INFINITY;
      EXPECT_EQ(ca->size(), cb->size());
      for (std::size_t k = 0; k < std::min(ca->size(), cb->size()); ++k) {
        worst = std::max(worst, std::abs((*ca)[k] - (*cb)[k]));
      }
    }
  }
  return worst;
}

TEST(RegionWallEngines, SpheresInAFunnelFollowTheSamePathsInTheCoreAndLammps) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_FAIL() << "lmp not installed: the region walls need the real LAMMPS";
  const cases::Scene scene = cases::load_case_text(kFunnel, "funnel.toml");
  const cases::RunResult core = reference::run_engine(reference::InhouseEngine{}, scene, {});
  const cases::RunResult lammps =
      reference::run_engine(reference::LammpsEngine{}, scene, demwb_lammps_test::scratch("region_funnel"));
  ASSERT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  ASSERT_EQ(lammps.status, cases::RunStatus::ok) << lammps.reason << "\n" << lammps.log_tail;
  // The paths touch every wall: sphere 2 starts over the orifice's rim and falls through it; the
  // others bounce on the cone and the cylinder.
  const auto& z2 = *core.trace.column(cases::particle_column(2, "z"));
  EXPECT_LT(z2.back(), -1e-2) << "sphere 2 left through the orifice";
  const auto& x0 = *core.trace.column(cases::particle_column(0, "x"));
  const auto& y0 = *core.trace.column(cases::particle_column(0, "y"));
  double widest = 0.0;
  for (std::size_t k = 0; k < x0.size(); ++k) widest = std::max(widest, std::hypot(x0[k], y0[k]));
  EXPECT_GT(widest, 8.9e-3) << "sphere 0 reached the cylinder";
  // Same law, same integrator, same geometry: the paths agree to round-off growth over 8,000
  // steps of bouncing (a nanometre against millimetre paths).
  const double worst = largest_position_difference(core.trace, lammps.trace, scene.particles.size());
  EXPECT_LT(worst, 1e-9) << "largest position difference " << worst << " m";
}

TEST(RegionWallEngines, ADiscOrAWallRemovedDuringTheRunIsNotApplicableOnLammps) {
  std::string text(kFunnel);
  const reference::LammpsEngine lammps;
  // The shutter removed at t = 0 is never met by the run: supported.
  const cases::Scene funnel = cases::load_case_text(text, "f.toml");
  EXPECT_TRUE(lammps.supports(reference::PreparedScene(funnel)).reasons.empty());
  // Removed later, it would need a second run.
  const cases::Scene later_scene = cases::load_case_text(replaced(text, "remove_at = 0.0", "remove_at = 0.01"), "f.toml");
  const auto reasons = lammps.supports(reference::PreparedScene(later_scene)).reasons;
  EXPECT_TRUE(names(reasons, "is a disc"));
  EXPECT_TRUE(names(reasons, "removed at 0.01 s"));
  // A cone about a tilted axis has no LAMMPS region.
  const cases::Scene tilted_scene = cases::load_case_text(
      replaced(text, "axis = [0.0, 0.0, 1.0]\nheight = 7.0e-3", "axis = [0.0, 0.1, 1.0]\nheight = 7.0e-3"), "f.toml");
  EXPECT_TRUE(names(lammps.supports(reference::PreparedScene(tilted_scene)).reasons, "lie along x, y or z"));
}

}  // namespace region_walls_engines_test
