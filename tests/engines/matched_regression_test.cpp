// SPDX-License-Identifier: MIT
// Scenes `demwb fuzz-matched` found disagreeing, kept as regressions (tests/data/matched): each
// now agrees at round-off between the code and the core with its numerics, or is n/a with the
// reason its mapping gives.
#include <filesystem>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "compare/metrics.hpp"
#include "lammps_test_support.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/registry.hpp"
#include "reference/lammps/lammps_engine.hpp"
#include "reference/matching.hpp"
#include "reference/yade/yade_engine.hpp"

namespace matched_regression_test {

namespace fs = std::filesystem;

cases::Scene regression(const std::string& name) {
  return cases::load_case(fs::path(DEMWB_SOURCE_DIR) / "tests" / "data" / "matched" / (name + ".toml"));
}

/// Whole-trace deviation of the core on `code`'s numerics against `code` itself on `scene`, the
/// matched scene first passed through `edit`; `if_failed` when a run or the comparison fails
/// (the caller picks it so that its own check then fails).
template <class Edit>
double whole_deviation(const cases::Scene& scene, const reference::Engine& engine, const std::string& code, Edit edit,
                       double if_failed) {
  const cases::RunResult theirs = reference::run_engine(engine, scene, demwb_lammps_test::scratch("regression-" + scene.name));
  EXPECT_EQ(theirs.status, cases::RunStatus::ok) << theirs.reason << "\n" << theirs.log_tail;
  cases::Scene matched = reference::matched_scene(scene, code);
  edit(matched);
  const cases::RunResult ours = reference::run_engine(reference::InhouseEngine{}, matched, {});
  EXPECT_EQ(ours.status, cases::RunStatus::ok) << ours.reason;
  std::string problem;
  const auto deviation = comparison::trace_deviation(scene, ours, theirs, problem);
  EXPECT_TRUE(deviation.has_value()) << problem;
  return deviation ? deviation->whole : if_failed;
}

/// Trace deviation of the core on `code`'s numerics against `code` itself on `scene`.
double matched_deviation(const cases::Scene& scene, const reference::Engine& engine, const std::string& code) {
  return whole_deviation(scene, engine, code, [](cases::Scene&) {}, 1.0);
}

TEST(MatchedRegression, JkrWithMindlinOnTheContactRadiusAgreesWithLammps) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "LAMMPS not installed";
  EXPECT_LE(matched_deviation(regression("lammps_jkr_mindlin_contact_radius"), reference::LammpsEngine{}, "lammps"),
            1e-8);
}

TEST(MatchedRegression, FrictionalSpinningPairsAgreeWithLammps) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "LAMMPS not installed";
  EXPECT_LE(matched_deviation(regression("lammps_spinning_spring_coulomb_pair"), reference::LammpsEngine{}, "lammps"),
            1e-8);
  EXPECT_LE(matched_deviation(regression("lammps_hertz_mindlin_falling_onto_floor"), reference::LammpsEngine{}, "lammps"),
            1e-8);
}

TEST(MatchedRegression, IncrementalMindlinAgreesWithLammpsMindlinForce) {
  // mindlin_form 'incremental' is written as `tangential mindlin/force` (pairs and the floor).
  // The core on the other form must miss LAMMPS by far more than round-off, or this scene would
  // not tell the two histories apart.
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "LAMMPS not installed";
  cases::Scene scene = regression("lammps_hertz_mindlin_falling_onto_floor");
  scene.model.mindlin_form = dem::MindlinForm::incremental;
  const double same_form = matched_deviation(scene, reference::LammpsEngine{}, "lammps");
  EXPECT_LE(same_form, 1e-8);
  const double other_form = whole_deviation(
      scene, reference::LammpsEngine{}, "lammps",
      [](cases::Scene& matched) { matched.model.mindlin_form = dem::MindlinForm::total; }, 0.0);
  EXPECT_GT(other_form, 1e-6);
  std::cout << "incremental Mindlin against mindlin/force: " << same_form << "; the total form: " << other_form << "\n";
}

TEST(MatchedRegression, JkrWithMindlinOnTheOverlapIsNotApplicableForLammps) {
  // The same scene with the core's default radius: LAMMPS cannot express it.
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "LAMMPS not installed";
  cases::Scene scene = regression("lammps_jkr_mindlin_contact_radius");
  scene.model.mindlin_radius = dem::MindlinRadius::overlap;
  const cases::RunResult r = reference::run_engine(reference::LammpsEngine{}, scene, demwb_lammps_test::scratch("regression-jkr-overlap"));
  EXPECT_EQ(r.status, cases::RunStatus::not_applicable);
  EXPECT_NE(r.reason.find("mindlin_radius"), std::string::npos) << r.reason;
}

TEST(MatchedRegression, DmtWithFrictionIsNotApplicableForLammps) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "LAMMPS not installed";
  const cases::RunResult r =
      reference::run_engine(reference::LammpsEngine{}, regression("lammps_dmt_friction"), demwb_lammps_test::scratch("regression-dmt"));
  EXPECT_EQ(r.status, cases::RunStatus::not_applicable);
  EXPECT_NE(r.reason.find("dmt"), std::string::npos) << r.reason;
}

/// Trace deviation when the matched core drops a policy `code` uses: `unset` edits the matched
/// scene back to the core's default.
template <class Unset>
double deviation_without_policy(const cases::Scene& scene, const reference::Engine& engine, const std::string& code,
                                Unset unset) {
  return whole_deviation(scene, engine, code, unset, 0.0);
}

TEST(MatchedRegression, SpheresTouchingAtTheStartDropAnOverloadedTangentialDashpotAsLammpsDoes) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "LAMMPS not installed";
  const auto cap = [](cases::Scene& s) { s.model.unloaded_slider = dem::UnloadedSlider::cap; };
  for (const char* name : {"lammps_unloaded_slider_jkr", "lammps_unloaded_slider_wall", "lammps_unloaded_slider_rolling"}) {
    const cases::Scene scene = regression(name);
    EXPECT_LE(matched_deviation(scene, reference::LammpsEngine{}, "lammps"), 1e-8) << name;
    // The policy carries the agreement: capping instead parts from LAMMPS.
    EXPECT_GT(deviation_without_policy(scene, reference::LammpsEngine{}, "lammps", cap), 1e-6) << name;
  }
}

TEST(MatchedRegression, AChaoticClusterAgreesWithLammpsUpToItsRoundoffHorizon) {
  if (!demwb_lammps_test::lammps_installed()) GTEST_SKIP() << "LAMMPS not installed";
  const cases::Scene scene = regression("lammps_chaotic_jkr_cluster");
  const cases::RunResult theirs =
      reference::run_engine(reference::LammpsEngine{}, scene, demwb_lammps_test::scratch("regression-chaotic"));
  ASSERT_EQ(theirs.status, cases::RunStatus::ok) << theirs.reason;
  const cases::RunResult ours = reference::run_engine(*reference::make_engine("inhouse@lammps"), scene, {});
  ASSERT_EQ(ours.status, cases::RunStatus::ok) << ours.reason;
  ASSERT_TRUE(ours.roundoff_twin.has_value());
  std::string problem;
  const auto d = comparison::trace_deviation(scene, ours, theirs, problem);
  ASSERT_TRUE(d) << problem;
  // The horizon falls inside the run but past its first tenth, and before it the codes agree.
  EXPECT_LT(d->horizon, d->rows);
  EXPECT_GE(10 * d->horizon, d->rows);
  EXPECT_LE(d->value, 1e-8);
}

TEST(MatchedRegression, DmtWithADashpotCapsTheDashpotAtThePulloffForceAsYadeDoes) {
  if (!reference::YadeEngine{}.version()) GTEST_SKIP() << "YADE not installed";
  const cases::Scene scene = regression("yade_dmt_dashpot_pulloff_cap");
  EXPECT_LE(matched_deviation(scene, reference::YadeEngine{}, "yade"), 1e-8);
  const auto clamp = [](cases::Scene& s) { s.model.adhesive_dashpot = dem::AdhesiveDashpot::clamp; };
  EXPECT_GT(deviation_without_policy(scene, reference::YadeEngine{}, "yade", clamp), 1e-6);
  // With the core's default the native mapping cannot compare, and says why.
  cases::Scene native = scene;
  native.model.adhesive_dashpot = dem::AdhesiveDashpot::clamp;
  const cases::RunResult r = reference::run_engine(reference::YadeEngine{}, native, demwb_lammps_test::scratch("regression-dmt-clamp"));
  EXPECT_EQ(r.status, cases::RunStatus::not_applicable);
  EXPECT_NE(r.reason.find("adhesive_dashpot"), std::string::npos) << r.reason;
}

TEST(MatchedRegression, GravityFromTheYadeStartAgreesWithYade) {
  if (!reference::YadeEngine{}.version()) GTEST_SKIP() << "YADE not installed";
  EXPECT_LE(matched_deviation(regression("yade_gravity_wall"), reference::YadeEngine{}, "yade"), 1e-8);
}

}  // namespace matched_regression_test
