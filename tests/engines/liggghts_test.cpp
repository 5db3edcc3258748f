// SPDX-License-Identifier: MIT
// The real LIGGGHTS (ctest -L reference): every canonical two-body case it expresses runs, and the
// core in LIGGGHTS' numerics (inhouse@liggghts) reproduces its traces at round-off; so do scenes
// with cdt rolling resistance, hertz/stiffness, primitive cylinders and STL meshes, and a
// polydisperse pour; the Hertz dashpot written from ε rebounds with ε; cohesion cases are n/a with
// the reason.
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "compare/metrics.hpp"
#include "lammps_test_support.hpp"
#include "mesh_test_support.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/liggghts/atom_types.hpp"
#include "reference/liggghts/liggghts_engine.hpp"
#include "reference/matching.hpp"
#include "support/text_file.hpp"

namespace liggghts_engine_test {

using demwb_lammps_test::canonical;
using demwb_mesh_test::column_gap;

bool liggghts_installed() { return support::find_program("liggghts").has_value(); }

/// Run options with a scratch directory of the running test.
reference::RunOptions scratch(const std::string& run) {
  reference::RunOptions o;
  o.work_dir = std::filesystem::temp_directory_path() / "demwb-liggghts-tests" /
               demwb_engine_test::current_test_folder() / run;
  std::error_code ignored;
  std::filesystem::remove_all(o.work_dir, ignored);
  o.timeout_s = 120.0;
  return o;
}

/// The matched trace deviation (docs/metrics.md) of the core in LIGGGHTS' numerics against LIGGGHTS.
double matched_deviation(const cases::Scene& scene, const std::string& name) {
  const cases::RunResult liggghts = reference::run_engine(reference::LiggghtsEngine{}, scene, scratch(name));
  const cases::RunResult core =
      reference::run_engine(reference::InhouseEngine{}, reference::matched_scene(scene, "liggghts"), {});
  EXPECT_EQ(liggghts.status, cases::RunStatus::ok) << liggghts.reason << "\n" << liggghts.log_tail;
  EXPECT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  std::string problem;
  const auto d = comparison::trace_deviation(scene, core, liggghts, problem);
  EXPECT_TRUE(d.has_value()) << problem;
  return d ? d->whole : 1.0;
}

TEST(LiggghtsCanonical, EveryExpressedTwoBodyCaseMatchesTheCoreInLiggghtsNumerics) {
  if (!liggghts_installed()) GTEST_SKIP() << "liggghts not installed (scripts/setup.sh installs it)";
  for (const char* name : {"single_collision", "sandwich", "hertz_collision", "hertz_damped_collision",
                           "rigid_wall_hertz", "sliding_block", "oblique_wall_impact"}) {
    SCOPED_TRACE(name);
    const cases::Scene scene = canonical(name);
    ASSERT_TRUE(reference::LiggghtsEngine{}.supports(scene).supported())
        << reference::LiggghtsEngine{}.supports(scene).explain();
    const double d = matched_deviation(scene, name);
    std::cout << fmt::format("  {:<24} whole-trace deviation {:.3e}\n", name, d);
    // The matched gate (1e-8); sliding_block's whole trace drifts to 1.4e-10 past its round-off
    // horizon (a one-ulp nudge of the start does the same), the others stay below 1e-14.
    EXPECT_LE(d, 1e-8);
  }
}

TEST(LiggghtsNative, TheHertzDashpotFromTheRestitutionReboundsWithIt) {
  if (!liggghts_installed()) GTEST_SKIP() << "liggghts not installed";
  // hertz_damped_collision at a fine step: LIGGGHTS' own integration error is then far below
  // the 1e-3 asked of the rebound, which is the Tsuji dashpot's exact ε = 0.5.
  cases::Scene scene = canonical("hertz_damped_collision");
  scene.integration.timestep = 2e-7;
  scene.output.trace_every = 50;
  const cases::RunResult r = reference::run_engine(reference::LiggghtsEngine{}, scene, scratch("fine"));
  ASSERT_EQ(r.status, cases::RunStatus::ok) << r.reason << "\n" << r.log_tail;
  const std::vector<double>& va = *r.trace.column("p0.vx");
  const std::vector<double>& vb = *r.trace.column("p1.vx");
  const double before = scene.particles[0].velocity[0] - scene.particles[1].velocity[0];
  const double after = va.back() - vb.back();
  EXPECT_NEAR(-after / before, 0.5, 1e-3);
  EXPECT_EQ(r.conventions.at("version"), "LIGGGHTS-PUBLIC 3.8.0");
}

TEST(LiggghtsCanonical, CohesiveCasesAreNotApplicableWithTheReason) {
  for (const char* name : {"jkr_pulloff", "linear_cohesion_pair"}) {
    const reference::Support s = reference::LiggghtsEngine{}.supports(canonical(name));
    EXPECT_FALSE(s.supported()) << name;
    EXPECT_NE(s.explain().find("sjkr"), std::string::npos) << s.explain();
  }
}

TEST(LiggghtsManyBody, APolydispersePourFromADataFileFollowsTheCoreUntilItsContactsAmplifyRoundOff) {
  if (!liggghts_installed()) GTEST_SKIP() << "liggghts not installed";
  // 150 spheres of Gaussian radii: atoms from a data file, one type per material, diameters per
  // atom. Every position of LIGGGHTS and of the core in its numerics agrees to round-off while the
  // spheres fall and meet the floor (3e-18 m at 27 ms); from about 25 ms on the contacts between the
  // spheres amplify the codes' different summation orders tenfold per 3 ms (1e-13 m by 45 ms), as a
  // one-ulp nudge of the core's own start does (docs/metrics.md, "Round-off horizon").
  const cases::Scene scene = cases::load_case(std::filesystem::path(DEMWB_TEST_DATA_DIR) / "many_body" /
                                              "liggghts_pour.toml");
  ASSERT_GT(scene.particles.size(), reference::liggghts::kMaxInlineAtoms);
  ASSERT_TRUE(reference::liggghts::classify(scene).per_atom_diameter);
  const cases::RunResult liggghts = reference::run_engine(reference::LiggghtsEngine{}, scene, scratch("pour"));
  ASSERT_EQ(liggghts.status, cases::RunStatus::ok) << liggghts.reason << "\n" << liggghts.log_tail;
  const cases::RunResult core =
      reference::run_engine(reference::InhouseEngine{}, reference::matched_scene(scene, "liggghts"), {});
  ASSERT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  ASSERT_EQ(liggghts.trace.rows(), core.trace.rows());
  ASSERT_EQ(liggghts.trace.columns(), core.trace.columns());
  // Positions to 1e-15 m; every other column (velocities, spins, forces, the pair's overlap and
  // fn, the energies) to 1e-9 of its largest value: a mapping error (a diameter, a density, a
  // dashpot) shows at order one; the coordination number exactly.
  for (std::size_t c = 1; c < core.trace.columns().size(); ++c) {
    const std::string& name = core.trace.columns()[c];
    const std::string q = name.substr(name.find('.') + 1);
    const std::vector<double>& a = core.trace.values(c);
    const std::vector<double>& b = liggghts.trace.values(c);
    double scale = 0.0;
    double worst = 0.0;
    for (std::size_t r = 0; r < a.size(); ++r) {
      scale = std::max(scale, std::abs(b[r]));
      worst = std::max(worst, std::abs(a[r] - b[r]));
    }
    if (q == "x" || q == "y" || q == "z") {
      EXPECT_LE(worst, 1e-15) << name << " [m], over 30 ms";
    } else if (name == "all.coordination_number") {
      EXPECT_EQ(worst, 0.0) << name;
    } else {
      EXPECT_LE(worst, 1e-9 * scale) << name << " (largest " << scale << ")";
    }
  }
  const std::vector<double>& z = *core.trace.column("all.coordination_number");
  EXPECT_GT(*std::max_element(z.begin(), z.end()), 0.0);  // the spheres did meet each other
}

/// Two glass spheres side by side on a floor, spinning about tilted axes (rolling, and twisting
/// about both contact normals) under Hertz–Mindlin with the constant rolling torque.
cases::Scene spinning_pair() {
  return cases::load_case_text(R"([case]
name = "spinning_pair"
[model]
normal = "hertz"
damping = "tsuji"
tangential = "mindlin_8g"
rolling = "constant_torque"
[materials.glass]
density = 2500.0
youngs_modulus = 6.0e7
poisson_ratio = 0.23
restitution = 0.7
friction = 0.4
tangential_damping_ratio = 0.0
rolling_friction = 0.08
[[walls]]
type = "plane"
name = "floor"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
material = "glass"
[[particles]]
radius = 0.001
material = "glass"
position = [0.0, 0.0, 0.000999]
velocity = [0.01, 0.0, 0.0]
angular_velocity = [20.0, 5.0, 30.0]
[[particles]]
radius = 0.0008
material = "glass"
position = [0.0017995, 0.0, 0.0007992]
angular_velocity = [-10.0, 15.0, -25.0]
[fields]
gravity = [0.0, 0.0, -9.81]
[integration]
scheme = "velocity_verlet"
timestep = 2.0e-7
duration = 4.0e-3
rotation = true
[output]
trace_every = 100
trace_particles = [0, 1]
trace_pairs = [[0, 1]]
trace_walls = [[0, 0]]
[compare]
pair = [0, 1]
)",
                               "spinning_pair.toml");
}

TEST(LiggghtsRolling, CdtOnSpinningSpheresIsTheCoresProjectedConstantTorqueAtRoundOff) {
  if (!liggghts_installed()) GTEST_SKIP() << "liggghts not installed";
  const cases::Scene scene = spinning_pair();  // the default (tangent) form
  ASSERT_TRUE(reference::LiggghtsEngine{}.supports(scene).supported()) << reference::LiggghtsEngine{}.supports(scene).explain();
  const cases::RunResult liggghts = reference::run_engine(reference::LiggghtsEngine{}, scene, scratch("cdt"));
  ASSERT_EQ(liggghts.status, cases::RunStatus::ok) << liggghts.reason << "\n" << liggghts.log_tail;
  EXPECT_NE(liggghts.conventions.at("rolling resistance").find("rolling_friction cdt"), std::string::npos);
  std::string problem;
  // The core in LIGGGHTS' numerics (which take the projected form) follows it at round-off.
  const cases::Scene matched = reference::matched_scene(scene, "liggghts");
  ASSERT_EQ(matched.model.constant_torque_form, dem::ConstantTorqueForm::projected);
  const cases::RunResult core = reference::run_engine(reference::InhouseEngine{}, matched, {});
  ASSERT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  const auto d = comparison::trace_deviation(scene, core, liggghts, problem);
  ASSERT_TRUE(d.has_value()) << problem;
  EXPECT_LE(d->whole, 1e-8);
  // Everything else matched but the torque in the core's default form: the spins part at once (the
  // torque's size and direction differ while the spins twist about the normals).
  cases::Scene tangent = matched;
  tangent.model.constant_torque_form = dem::ConstantTorqueForm::tangent;
  const cases::RunResult other = reference::run_engine(reference::InhouseEngine{}, tangent, {});
  ASSERT_EQ(other.status, cases::RunStatus::ok) << other.reason;
  const auto apart = comparison::trace_deviation(scene, other, liggghts, problem);
  ASSERT_TRUE(apart.has_value()) << problem;
  EXPECT_GT(apart->whole, 1e-4);
  std::cout << fmt::format("  matched {:.3e}, with the tangent form {:.3e}\n", d->whole, apart->whole);
  // The rolling torque acted: the spins about the horizontal axes fell.
  const std::vector<double>& wx = *liggghts.trace.column("p0.wx");
  EXPECT_LT(std::abs(wx.back()), 0.9 * 20.0);
}

/// Three glass spheres in a drum (a z cylinder on a floor) under a horizontal rod (an x cylinder):
/// two slide and spin into the drum's wall from inside, one falls onto the rod from outside.
cases::Scene drum_and_rod() {
  return cases::load_case_text(R"([case]
name = "drum_and_rod"
)" + demwb_mesh_test::glass_hertz_mindlin() + R"([[walls]]
type = "plane"
name = "floor"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
material = "glass"
[[walls]]
type = "cylinder"
name = "drum"
base = [0.0, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]
radius = 0.005
height = 0.01
material = "glass"
[[walls]]
type = "cylinder"
name = "rod"
base = [0.004, 0.0, 0.006]
axis = [-1.0, 0.0, 0.0]
radius = 0.0005
height = 0.008
material = "glass"
[[particles]]
radius = 0.0008
material = "glass"
position = [0.003, 0.0, 0.0008]
velocity = [0.3, 0.1, 0.0]
[[particles]]
radius = 0.0008
material = "glass"
position = [-0.002, 0.002, 0.002]
velocity = [-0.2, 0.25, -0.1]
angular_velocity = [30.0, -10.0, 20.0]
[[particles]]
radius = 0.0008
material = "glass"
position = [0.0003, 0.0002, 0.0075]
[fields]
gravity = [0.0, 0.0, -9.81]
[integration]
scheme = "velocity_verlet"
timestep = 2.0e-7
duration = 0.02
rotation = true
[output]
trace_every = 500
trace_particles = [0, 1, 2]
[compare]
wall_contact = [0, 0]
)",
                               "drum_and_rod.toml");
}

TEST(LiggghtsWalls, PrimitiveCylindersInsideAndOutsideAreTheCoresCylindersAtRoundOff) {
  if (!liggghts_installed()) GTEST_SKIP() << "liggghts not installed";
  const cases::Scene scene = drum_and_rod();
  ASSERT_TRUE(reference::LiggghtsEngine{}.supports(scene).supported()) << reference::LiggghtsEngine{}.supports(scene).explain();
  const cases::RunResult liggghts = reference::run_engine(reference::LiggghtsEngine{}, scene, scratch("drum"));
  ASSERT_EQ(liggghts.status, cases::RunStatus::ok) << liggghts.reason << "\n" << liggghts.log_tail;
  EXPECT_NE(liggghts.conventions.at("walls").find("unbounded"), std::string::npos);
  const cases::RunResult core =
      reference::run_engine(reference::InhouseEngine{}, reference::matched_scene(scene, "liggghts"), {});
  ASSERT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  std::string problem;
  const auto d = comparison::trace_deviation(scene, core, liggghts, problem);
  ASSERT_TRUE(d.has_value()) << problem;
  std::cout << fmt::format("  whole-trace deviation {:.3e}\n", d->whole);
  EXPECT_LE(d->whole, 1e-8);
  // Every position agrees to round-off over the whole 20 ms (1.2e-16 m at the end; the spins, from
  // about 10 ms on, drift as far as a one-ulp nudge of the start takes them).
  for (const char* column : {"p0.x", "p0.y", "p0.z", "p1.x", "p1.y", "p1.z", "p2.x", "p2.y", "p2.z"}) {
    EXPECT_LE(column_gap(core, liggghts, column).first, 1e-15) << column << " [m]";
  }
  // The walls acted: the sliding sphere came back off the drum, the falling one stopped on the rod.
  const std::vector<double>& x0 = *liggghts.trace.column("p0.x");
  EXPECT_LT(*std::max_element(x0.begin(), x0.end()), 0.005 - 0.0008 + 1e-4);
  EXPECT_LT(liggghts.trace.column("p0.vx")->back(), 0.3);
  const std::vector<double>& z2 = *liggghts.trace.column("p2.z");
  EXPECT_GT(*std::min_element(z2.begin(), z2.end()), 0.006 + 0.0005 + 0.0008 - 1e-4);
}

/// A roof beside the floor: two slopes of two triangles each meeting at a ridge along y at
/// x = 20 mm, z = 3 mm, over x in [15, 25] mm and y in [−5, 5] mm.
std::string roof_stl() {
  std::string stl = "solid roof\n";
  const auto facet = [&](std::array<std::array<double, 3>, 3> c) {
    stl += "  facet normal 0 0 0\n    outer loop\n";
    for (const auto& p : c) stl += fmt::format("      vertex {:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
    stl += "    endloop\n  endfacet\n";
  };
  facet({{{0.015, -0.005, 0.0}, {0.02, -0.005, 0.003}, {0.02, 0.005, 0.003}}});
  facet({{{0.015, -0.005, 0.0}, {0.02, 0.005, 0.003}, {0.015, 0.005, 0.0}}});
  facet({{{0.02, -0.005, 0.003}, {0.025, -0.005, 0.0}, {0.025, 0.005, 0.0}}});
  facet({{{0.02, -0.005, 0.003}, {0.025, 0.005, 0.0}, {0.02, 0.005, 0.003}}});
  return stl + "endsolid roof\n";
}

TEST(LiggghtsWalls, SpheresOverAMeshFloorsSeamsAndOntoARidgeAreTheCoresAtRoundOff) {
  if (!liggghts_installed()) GTEST_SKIP() << "liggghts not installed";
  const std::filesystem::path dir = scratch("mesh-floor").work_dir;
  std::filesystem::create_directories(dir);
  support::write_file(dir / "floor.stl", demwb_mesh_test::flat_floor_stl());
  support::write_file(dir / "roof.stl", roof_stl());
  const std::string text = R"([case]
name = "mesh_floor"
)" + demwb_mesh_test::glass_hertz_mindlin() + R"([[walls]]
type = "mesh"
name = "floor"
file = "floor.stl"
material = "glass"
[[walls]]
type = "mesh"
name = "roof"
file = "roof.stl"
material = "glass"
[[particles]]
radius = 0.001
material = "glass"
position = [-0.006, -0.004, 0.000999]
velocity = [0.5, 0.3, 0.0]
angular_velocity = [0.0, 0.0, 40.0]
[[particles]]
radius = 0.0008
material = "glass"
position = [0.004, -0.0075, 0.0009]
velocity = [-0.2, 0.45, -0.05]
angular_velocity = [60.0, 0.0, 0.0]
[[particles]]
radius = 0.0008
material = "glass"
position = [0.0201, 0.001, 0.0042]
velocity = [0.0, 0.05, -0.1]
[fields]
gravity = [0.0, 0.0, -9.81]
[integration]
scheme = "velocity_verlet"
timestep = 2.0e-7
duration = 0.02
rotation = true
[output]
trace_every = 500
trace_particles = [0, 1, 2]
)";
  support::write_file(dir / "mesh_floor.toml", text);
  const cases::Scene scene = cases::load_case(dir / "mesh_floor.toml");
  ASSERT_EQ(scene.meshes.size(), 2U);
  ASSERT_TRUE(reference::LiggghtsEngine{}.supports(scene).supported()) << reference::LiggghtsEngine{}.supports(scene).explain();
  const cases::RunResult liggghts = reference::run_engine(reference::LiggghtsEngine{}, scene, scratch("mesh-run"));
  ASSERT_EQ(liggghts.status, cases::RunStatus::ok) << liggghts.reason << "\n" << liggghts.log_tail;
  const cases::RunResult core =
      reference::run_engine(reference::InhouseEngine{}, reference::matched_scene(scene, "liggghts"), {});
  ASSERT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  // Positions to 1e-15 m and spins to 1e-9 of their largest over the 20 ms (measured: 8e-17 m and
  // 1.4e-10 rad/s of 318): the facets' faces, the seams where the floor's triangles meet flat, and
  // the roof's convex ridge, whose edge the third sphere lands on, are met alike.
  for (const char* column : {"p0.x", "p0.y", "p0.z", "p1.x", "p1.y", "p1.z", "p2.x", "p2.y", "p2.z", "p0.wx", "p0.wy",
                             "p0.wz", "p1.wx", "p1.wy", "p1.wz", "p2.wx", "p2.wy", "p2.wz"}) {
    const auto [worst, scale] = column_gap(core, liggghts, column);
    const bool position = std::string(column).find(".w") == std::string::npos;
    EXPECT_LE(worst, position ? 1e-15 : 1e-9 * scale) << column;
  }
  // The spheres crossed seams (the grid lines x = −5 and 0 mm, diagonals between) and the third one
  // came down the ridge's +x slope.
  EXPECT_GT(liggghts.trace.column("p0.x")->back(), 0.001);
  EXPECT_GT(liggghts.trace.column("p1.y")->back(), -0.002);
  EXPECT_GT(liggghts.trace.column("p2.x")->back(), 0.0203);
}

TEST(LiggghtsHertzStiffness, HertzWithTheViscoelasticDashpotIsHertzStiffnessAtRoundOff) {
  if (!liggghts_installed()) GTEST_SKIP() << "liggghts not installed";
  // Two materials, the steel pairs with a tangential dashpot: k_n = 4/3 E*, k_t = 8 G*, γ_n = η₀ and
  // γ_t per type pair, each scaled by √(R* δ) (and m*) in LIGGGHTS' law.
  const cases::Scene scene = cases::load_case_text(R"([case]
name = "hs"
[model]
normal = "hertz"
damping = "lammps_viscoelastic"
tangential = "mindlin_8g"
[materials.steel]
density = 7800.0
youngs_modulus = 2.0e8
poisson_ratio = 0.29
viscoelastic_damping = 500.0
friction = 0.3
tangential_damping_ratio = 0.4
[materials.glass]
density = 2500.0
youngs_modulus = 6.0e7
poisson_ratio = 0.23
viscoelastic_damping = 200.0
friction = 0.4
tangential_damping_ratio = 0.0
[[walls]]
type = "plane"
name = "floor"
point = [0.0, 0.0, -0.01]
normal = [0.0, 0.0, 1.0]
material = "glass"
[[particles]]
radius = 0.002
material = "steel"
position = [0.0, 0.0, 0.0]
velocity = [0.5, 0.0, -0.3]
angular_velocity = [0.0, 20.0, 0.0]
[[particles]]
radius = 0.003
material = "glass"
position = [0.0051, 0.0, -0.001]
[fields]
gravity = [0.0, 0.0, -9.81]
[integration]
scheme = "velocity_verlet"
timestep = 1.0e-6
duration = 0.06
rotation = true
[output]
trace_every = 100
trace_particles = [0, 1]
trace_pairs = [[0, 1]]
trace_walls = [[0, 0]]
[compare]
pair = [0, 1]
)",
                                                   "hertz_stiffness.toml");
  ASSERT_TRUE(reference::LiggghtsEngine{}.supports(scene).supported()) << reference::LiggghtsEngine{}.supports(scene).explain();
  const cases::RunResult liggghts = reference::run_engine(reference::LiggghtsEngine{}, scene, scratch("hs"));
  ASSERT_EQ(liggghts.status, cases::RunStatus::ok) << liggghts.reason << "\n" << liggghts.log_tail;
  EXPECT_NE(liggghts.conventions.at("contact model").find("model hertz/stiffness"), std::string::npos);
  const double d = matched_deviation(scene, "hs-matched");
  std::cout << fmt::format("  whole-trace deviation {:.3e}\n", d);
  EXPECT_LE(d, 1e-8);
  // The spheres met each other and the floor, and the dashpots took energy: the steel sphere's
  // largest overlaps with both came and went.
  const std::vector<double>& pair = *liggghts.trace.column(cases::pair_column(0, 1, "overlap"));
  const std::vector<double>& floor = *liggghts.trace.column(cases::wall_column(0, 0, "overlap"));
  EXPECT_GT(*std::max_element(pair.begin(), pair.end()), 0.0);
  EXPECT_GT(*std::max_element(floor.begin(), floor.end()), 0.0);
}

}  // namespace liggghts_engine_test
