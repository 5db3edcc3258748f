// SPDX-License-Identifier: MIT
// Scenes `demwb fuzz-matched` found disagreeing, kept as regressions (tests/data/matched): each
// now agrees at round-off between the code and the core with its numerics, or is n/a with the
// reason its mapping gives.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "compare/metrics.hpp"
#include "lammps_test_support.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/lammps/lammps_engine.hpp"
#include "reference/matching.hpp"
#include "reference/yade/yade_engine.hpp"

namespace matched_regression_test {

namespace fs = std::filesystem;

cases::Scene regression(const std::string& name) {
  return cases::load_case(fs::path(DEMWB_SOURCE_DIR) / "tests" / "data" / "matched" / (name + ".toml"));
}

/// Trace deviation of the core on `code`'s numerics against `code` itself on `scene`.
double matched_deviation(const cases::Scene& scene, const reference::Engine& engine, const std::string& code) {
  const cases::RunResult theirs = reference::run_engine(engine, scene, demwb_lammps_test::scratch("regression-" + scene.name));
  EXPECT_EQ(theirs.status, cases::RunStatus::ok) << theirs.reason << "\n" << theirs.log_tail;
  const cases::RunResult ours =
      reference::run_engine(reference::InhouseEngine{}, reference::matched_scene(scene, code), {});
  EXPECT_EQ(ours.status, cases::RunStatus::ok) << ours.reason;
  std::string problem;
  const std::optional<double> deviation = comparison::trace_deviation(scene, ours, theirs, problem);
  EXPECT_TRUE(deviation.has_value()) << problem;
  return deviation.value_or(1.0);
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

TEST(MatchedRegression, GravityFromTheYadeStartAgreesWithYade) {
  if (!reference::YadeEngine{}.version()) GTEST_SKIP() << "YADE not installed";
  EXPECT_LE(matched_deviation(regression("yade_gravity_wall"), reference::YadeEngine{}, "yade"), 1e-8);
}

}  // namespace matched_regression_test
