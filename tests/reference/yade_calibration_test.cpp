// SPDX-License-Identifier: MIT
// The YADE restitution calibration (issue 4 §4): when it is planned, the Python block the
// script gets, and the parser on a calibration captured from the real YADE.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "reference/yade/output_parser.hpp"
#include "reference/yade/restitution_calibration.hpp"
#include "reference/yade/run_plan.hpp"
#include "reference/yade/script_writer.hpp"
#include "support/text_file.hpp"

namespace yade_calibration_test {

const std::filesystem::path kCanonical = std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/canonical";
const std::filesystem::path kData = std::filesystem::path(DEMWB_TEST_DATA_DIR) / "yade";

TEST(YadeCalibration, NativeWallImpactCalibratesTheSphereMaterialAgainstTheWall) {
  const auto scene = cases::load_case(kCanonical / "oblique_wall_impact.toml");
  const auto plan = reference::yade::make_run_plan(reference::PreparedScene(scene));
  ASSERT_TRUE(plan.calibration);
  EXPECT_EQ(plan.calibration->material, 0u);
  EXPECT_EQ(plan.calibration->target, 0.8);
  EXPECT_TRUE(plan.calibration->partner_wall);
  EXPECT_EQ(plan.calibration->normal[2], 1.0);
  const double ln = std::log(0.8);
  EXPECT_NEAR(plan.calibration->start, -ln / std::sqrt(M_PI * M_PI + ln * ln), 1e-16);
  const std::string s = reference::yade::write_yade_script(scene, plan);
  EXPECT_NE(s.find("def _calibration_rebound(betan):"), std::string::npos);
  EXPECT_NE(s.find("with open('calibration.csv', 'w') as _f:"), std::string::npos);
}

TEST(YadeCalibration, YadesOwnDampingAndUndampedCasesAreNotCalibrated) {
  auto scene = cases::load_case(kCanonical / "oblique_wall_impact.toml");
  scene.model.damping = "yade_frictvisco";
  EXPECT_FALSE(reference::yade::make_run_plan(reference::PreparedScene(scene)).calibration);
  const cases::Scene single = cases::load_case(kCanonical / "single_collision.toml");
  EXPECT_FALSE(reference::yade::make_run_plan(reference::PreparedScene(single)).calibration);
}

TEST(YadeCalibration, ParsesTheCapturedTableAndTakesTheLastRowAsChosen) {
  const auto scene = cases::load_case(kCanonical / "oblique_wall_impact.toml");
  const auto plan = reference::yade::make_run_plan(reference::PreparedScene(scene));
  const auto c = reference::yade::parse_calibration_csv(
      support::read_file(kData / "oblique_wall_calibration.csv"), *plan.calibration);
  EXPECT_EQ(c.samples.size(), 5u);
  EXPECT_NEAR(c.samples.front().second, 0.798292981945887, 1e-15);  // textbook betan: α lowers e
  EXPECT_NEAR(c.chosen, 0.070174920010671077, 1e-17);
  EXPECT_GT(c.chosen, 0.0);
  EXPECT_LT(c.chosen, plan.calibration->start);  // less damping than the textbook value
  EXPECT_NEAR(c.samples.back().second, 0.8, 1e-12);
  EXPECT_NE(c.parameter.find("FrictViscoMat.betan"), std::string::npos);
}

TEST(YadeCalibration, BrokenTableNamesFileAndLine) {
  const reference::yade::YadeCalibrationPlan plan;
  try {
    static_cast<void>(reference::yade::parse_calibration_csv("betan,restitution\n0.1,0.8\nx,0.7\n", plan));
    FAIL() << "no error";
  } catch (const reference::yade::YadeOutputError& e) {
    EXPECT_NE(std::string(e.what()).find("calibration.csv:3"), std::string::npos) << e.what();
  }
  EXPECT_THROW(static_cast<void>(reference::yade::parse_calibration_csv("betan,restitution\n", plan)),
               reference::yade::YadeOutputError);
}

}  // namespace
