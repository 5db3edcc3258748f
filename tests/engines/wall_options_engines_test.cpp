// SPDX-License-Identifier: MIT
// Walls as users write them, through the real codes: a rigid wall (no compliance), a material per
// wall, a velocity aimed at a wall and Hertz walls on YADE, each checked against closed forms written out here, not
// taken from the analytic engine or the core's mixing.
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compare/metrics.hpp"
#include "lammps_test_support.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/lammps/lammps_engine.hpp"
#include "reference/yade/yade_engine.hpp"
#include "yade_test_support.hpp"

namespace wall_options_engines_test {

using std::numbers::pi;

/// The metric `name` of one run for the contact of `particle` with wall `wall`.
double metric(cases::Scene scene, const cases::RunResult& run, std::size_t particle, std::size_t wall,
              const std::string& name) {
  scene.compare.subject = particle;
  scene.compare.wall_contact = std::make_pair(particle, wall);
  scene.compare.metrics = {name};
  const comparison::MetricSet set = comparison::compute_metrics(scene, run, nullptr);
  const comparison::MetricValue& v = set.at(name);
  EXPECT_TRUE(v.value.has_value()) << run.engine << " " << name << ": " << v.problem;
  return v.value.value_or(NAN);
}

/// Expects each metric of sphere 0's contact with wall 0 to agree between two runs within 1e-12
/// relative: the same law in both codes, so round-off, not a tolerance.
void expect_round_off_agreement(const cases::Scene& scene, const cases::RunResult& a, const cases::RunResult& b,
                                std::initializer_list<const char*> names) {
  for (const char* name : names) {
    const double x = metric(scene, a, 0, 0, name), y = metric(scene, b, 0, 0, name);
    EXPECT_NEAR(y, x, 1e-12 * std::abs(x)) << name;
  }
}

/// Hertz impact on a rigid plane (cases/canonical/rigid_wall_hertz.toml), from the inputs alone:
/// E* = E/(1 − ν²) of the sphere, R* = r, m* = m, v_n = v cos θ.
struct RigidHertzClosedForm {
  double duration;
  double max_overlap;
};

RigidHertzClosedForm rigid_hertz_closed_form() {
  const double r = 0.005, rho = 2500.0, e = 1.0e8, nu = 0.3, speed = 1.2, incidence = 30.0;
  const double m = 4.0 / 3.0 * pi * rho * r * r * r;
  const double e_star = e / (1.0 - nu * nu);
  const double v_n = speed * std::cos(incidence * pi / 180.0);
  const double overlap = std::pow(15.0 * m * v_n * v_n / (16.0 * e_star * std::sqrt(r)), 0.4);
  // t_c = 2 ∫₀^δmax dδ / √(v² − (8/5)(E*√R/m) δ^{5/2}) = (4/5) B(2/5, 1/2) δmax / v_n.
  const double beta = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  return {0.8 * beta * overlap / v_n, overlap};
}

TEST(RigidWallEngines, HertzImpactOnARigidPlaneMatchesTheClosedFormOnTheCoreAndOnLammps) {
  const cases::Scene scene = demwb_lammps_test::canonical("rigid_wall_hertz");
  ASSERT_TRUE(scene.walls[0].rigid);
  const RigidHertzClosedForm exact = rigid_hertz_closed_form();
  ASSERT_NEAR(exact.duration, 3.506510e-4, 1e-9);  // the figure the case file's header states
  std::vector<cases::RunResult> runs{reference::run_engine(reference::InhouseEngine{}, scene, {})};
  if (demwb_lammps_test::lammps_installed()) {
    runs.push_back(reference::run_engine(reference::LammpsEngine{}, scene, demwb_lammps_test::scratch("rigid_hertz")));
  } else {
    ADD_FAILURE() << "lmp not installed: the rigid wall is checked on the core only";
  }
  for (const cases::RunResult& run : runs) {
    ASSERT_EQ(run.status, cases::RunStatus::ok) << run.engine << ": " << run.reason << "\n" << run.log_tail;
    const double duration = metric(scene, run, 0, 0, "contact_duration");
    const double overlap = metric(scene, run, 0, 0, "max_overlap");
    EXPECT_NEAR(duration, exact.duration, 1e-4 * exact.duration) << run.engine;
    EXPECT_NEAR(overlap, exact.max_overlap, 1e-4 * exact.max_overlap) << run.engine;
    // The aimed velocity: 1.2 m/s at 30° along +x; no friction, so v_x stays 0.6 m/s.
    EXPECT_NEAR(metric(scene, run, 0, 0, "velocity_after_x"), 0.6, 1e-12) << run.engine;
  }
}

/// The two-wall scene of tests/data/walls/two_wall_materials.toml and its closed forms.
struct TwoWalls {
  cases::Scene scene = cases::load_case(std::string(DEMWB_TEST_DATA_DIR) + "/walls/two_wall_materials.toml");
  double mass = 4.0 / 3.0 * pi * 1000.0 * 1e-6;
  double v_n = 4.0 * std::cos(pi / 3.0);
  double v_t = 4.0 * std::sin(pi / 3.0);
  /// Undamped linear contact: half a period of √(k/m).
  [[nodiscard]] double duration(double k) const { return pi * std::sqrt(mass / k); }
  /// Gross sliding throughout: Δv_t = −μ · 2 v_n.
  [[nodiscard]] double sliding_exit(double mu) const { return v_t - 2.0 * mu * v_n; }
};

/// Checks one run of the two-wall scene: the rigid floor doubles the sphere's stiffness and
/// brings ice's friction; the side wall mixes harmonically and brings the plate's friction.
void expect_two_wall_closed_forms(const TwoWalls& t, const cases::RunResult& run) {
  ASSERT_EQ(run.status, cases::RunStatus::ok) << run.engine << ": " << run.reason << "\n" << run.log_tail;
  // Contact time to within one step (1e-6 s) and its interpolation.
  EXPECT_NEAR(metric(t.scene, run, 0, 0, "contact_duration"), t.duration(2.0e5), 2e-3 * t.duration(2.0e5))
      << run.engine << ": floor";
  EXPECT_NEAR(metric(t.scene, run, 1, 1, "contact_duration"), t.duration(1.0e5), 2e-3 * t.duration(1.0e5))
      << run.engine << ": side wall";
  // The sliding exits differ by 2 (0.2 − 0.1) v_n = 0.4 m/s, so the friction of each wall's own
  // material is what acted; the spring's first steps below the cap leave ~1e-4 m/s.
  EXPECT_NEAR(metric(t.scene, run, 0, 0, "velocity_after_x"), t.sliding_exit(0.1), 1e-3) << run.engine;
  EXPECT_NEAR(metric(t.scene, run, 1, 1, "velocity_after_z"), t.sliding_exit(0.2), 1e-3) << run.engine;
  // Restitution 1 on both walls.
  EXPECT_NEAR(metric(t.scene, run, 0, 0, "velocity_after_z"), t.v_n, 1e-4) << run.engine;
  EXPECT_NEAR(metric(t.scene, run, 1, 1, "velocity_after_x"), t.v_n, 1e-4) << run.engine;
}

TEST(WallMaterialEngines, TheCoreGivesEachWallItsOwnMaterialAndRigidity) {
  const TwoWalls t;
  expect_two_wall_closed_forms(t, reference::run_engine(reference::InhouseEngine{}, t.scene, {}));
}

TEST(WallMaterialEngines, LammpsGivesEachWallItsOwnMaterialAndRigidity) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "lmp not installed";
  const TwoWalls t;
  expect_two_wall_closed_forms(
      t, reference::run_engine(reference::LammpsEngine{}, t.scene, demwb_lammps_test::scratch("two_walls")));
}

TEST(WallMaterialEngines, YadeGivesEachWallItsOwnMaterialAndRigidity) {
  DEMWB_REQUIRE_YADE();
  const TwoWalls t;
  expect_two_wall_closed_forms(
      t, reference::run_engine(reference::YadeEngine{}, t.scene, {demwb_yade_test::scratch("two-walls"), 120.0}));
}

TEST(RigidWallEngines, YadeReproducesTheRigidWallClosedFormThroughItsCompensatingMaterial) {
  DEMWB_REQUIRE_YADE();
  const cases::Scene scene = demwb_lammps_test::canonical("rigid_wall_hertz");
  const RigidHertzClosedForm exact = rigid_hertz_closed_form();
  const cases::RunResult run =
      reference::run_engine(reference::YadeEngine{}, scene, {demwb_yade_test::scratch("rigid-hertz"), 120.0});
  ASSERT_EQ(run.status, cases::RunStatus::ok) << run.reason << "\n" << run.log_tail;
  EXPECT_NEAR(metric(scene, run, 0, 0, "contact_duration"), exact.duration, 1e-4 * exact.duration);
  EXPECT_NEAR(metric(scene, run, 0, 0, "max_overlap"), exact.max_overlap, 1e-4 * exact.max_overlap);
  EXPECT_EQ(run.conventions.count("wall contact radius"), 1U);
}

TEST(RigidWallEngines, YadeRunsClippedTsujiAgainstACompliantWallAsTheCoreDoes) {
  DEMWB_REQUIRE_YADE();
  // Compliant wall (E = 2e8, ν = 0.25), tsuji ε = 0.7 with clamp_tensile: the same law in both
  // codes, so the native runs agree at round-off, not merely within a tolerance.
  const cases::Scene scene = cases::load_case(std::string(DEMWB_TEST_DATA_DIR) + "/walls/hertz_wall_tsuji.toml");
  const auto core = reference::run_engine(reference::InhouseEngine{}, scene, {});
  const auto yade = reference::run_engine(reference::YadeEngine{}, scene, {demwb_yade_test::scratch("wall-tsuji"), 120.0});
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  expect_round_off_agreement(scene, core, yade, {"contact_duration", "max_overlap", "max_force", "restitution"});
  EXPECT_LT(metric(scene, core, 0, 0, "restitution"), 0.75);  // damped: the dashpot acted
}

TEST(RigidWallEngines, YadeRunsAFrictionlessWallInAFrictionalScene) {
  DEMWB_REQUIRE_YADE();
  // The compliant-wall scene with Hertz–Mindlin friction on the sphere (μ = 0.4, incremental form)
  // and none on the wall (μ = 0): μ mixes to 0 at the wall, so YADE's law applies no tangential
  // force or torque there, exactly as the core, and the wall is mapped. With μ = 0.3 on the wall
  // YADE's lever arm r − δ would matter, and the driver refuses it.
  cases::Scene scene = cases::load_case(std::string(DEMWB_TEST_DATA_DIR) + "/walls/hertz_wall_tsuji.toml");
  scene.model.tangential = "mindlin_8g";
  scene.model.mindlin_form = dem::MindlinForm::incremental;
  scene.integration.rotation = true;
  for (auto& m : scene.materials) {
    m.friction = m.name == "steel" ? 0.0 : 0.4;
    m.tangential_damping_ratio = 0.0;
  }
  const auto core = reference::run_engine(reference::InhouseEngine{}, scene, {});
  const auto yade = reference::run_engine(reference::YadeEngine{}, scene, {demwb_yade_test::scratch("wall-frictionless"), 120.0});
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  expect_round_off_agreement(scene, core, yade,
                             {"contact_duration", "max_overlap", "restitution", "tangential_restitution"});
  EXPECT_DOUBLE_EQ(metric(scene, core, 0, 0, "tangential_restitution"), -1.0);  // no tangential force
  EXPECT_EQ(metric(scene, yade, 0, 0, "spin_after"), 0.0);
  for (auto& m : scene.materials) m.friction = 0.3;
  const auto refused = reference::run_engine(reference::YadeEngine{}, scene, {demwb_yade_test::scratch("wall-friction"), 120.0});
  EXPECT_EQ(refused.status, cases::RunStatus::not_applicable);
  EXPECT_NE(refused.reason.find("lever arm r − δ"), std::string::npos) << refused.reason;
}

}  // namespace wall_options_engines_test
