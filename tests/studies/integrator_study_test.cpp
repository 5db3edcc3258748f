// SPDX-License-Identifier: MIT
// The integrator study reproduces the global orders of thesis §4.4 (issue "Foundation").
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/integrator_study.hpp"
#include "support/text_file.hpp"

namespace integrator_study_test {

using dem::SchemeId;
using studies::fitted_order;

/// One run of the default study shared by every test of this file (about two seconds).
class IntegratorStudy : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    study_ = new studies::IntegratorStudy(studies::run_integrator_study(studies::default_options()));
  }
  static void TearDownTestSuite() {
    delete study_;
    study_ = nullptr;
  }
  static double order(const char* key, SchemeId id) {
    const auto o = fitted_order(*study_, key, id);
    EXPECT_TRUE(o.has_value()) << key << " " << dem::scheme_info(id).keyword;
    return o.value_or(-1.0);
  }
  static studies::IntegratorStudy* study_;
};

studies::IntegratorStudy* IntegratorStudy::study_ = nullptr;

TEST_F(IntegratorStudy, EveryRunSucceeds) {
  EXPECT_TRUE(study_->problems.empty()) << study_->problems.front();
  EXPECT_GE(study_->options.timesteps.size(), 5U);
  EXPECT_NEAR(study_->options.timesteps.front(), 5e-7, 1e-20);
  EXPECT_NEAR(study_->options.timesteps.back(), 5e-5, 1e-18);
}

TEST_F(IntegratorStudy, ForwardEulerAndBD1AreFirstOrder) {
  for (const char* key : {"dt_nfm_10", "dt_nfm_10_5"}) {
    for (const auto id : {SchemeId::fe, SchemeId::bd1}) {
      EXPECT_GE(order(key, id), 0.8) << key;
      EXPECT_LE(order(key, id), 1.2) << key;
    }
  }
}

TEST_F(IntegratorStudy, SymplecticEulerIsAtLeastSecondOrderInAmplitude) {
  EXPECT_GE(order("dt_nfm_10", SchemeId::se), 1.8);
  EXPECT_GE(order("dt_nfm_10_5", SchemeId::se), 1.8);
}

TEST_F(IntegratorStudy, ContactStartBetweenTimePointsCapsEveryHigherSchemeAtSecondOrder) {
  for (const auto id : {SchemeId::rk2, SchemeId::ab2, SchemeId::bd2, SchemeId::rk4, SchemeId::ab4, SchemeId::abm}) {
    EXPECT_GE(order("dt_nfm_10_5", id), 1.7) << dem::scheme_info(id).keyword;
    EXPECT_LE(order("dt_nfm_10_5", id), 2.5) << dem::scheme_info(id).keyword;
  }
}

TEST_F(IntegratorStudy, ContactStartOnATimePointLetsRungeKuttaKeepItsOrder) {
  EXPECT_GE(order("dt_nfm_10", SchemeId::rk4), 3.8);
  EXPECT_GE(order("dt_nfm_10", SchemeId::rk2), 1.8);
}

TEST_F(IntegratorStudy, WithoutFreeMotionFourthOrderSchemesAreFourthOrder) {
  for (const auto id : {SchemeId::rk4, SchemeId::ab4, SchemeId::abm}) {
    EXPECT_GE(order("dt_sandwich", id), 3.8) << dem::scheme_info(id).keyword;
  }
}

TEST_F(IntegratorStudy, AmplitudeErrorDoesNotDependOnCollisionVelocity) {
  for (const char* key : {"u_nfm_10", "u_nfm_10_5"}) {
    const auto* sweep = studies::find_sweep(*study_, key);
    ASSERT_NE(sweep, nullptr);
    for (const auto& s : sweep->schemes) {
      double lo = INFINITY, hi = 0.0;
      for (const auto& p : s.points) {
        ASSERT_TRUE(p.amplitude_error.has_value()) << p.problem;
        lo = std::min(lo, *p.amplitude_error);
        hi = std::max(hi, *p.amplitude_error);
      }
      // The linear problem scales exactly with |u|; only round-off differs.
      EXPECT_LT(hi / lo - 1.0, 1e-6) << key << " " << dem::scheme_info(s.scheme).keyword;
    }
  }
}

TEST_F(IntegratorStudy, Rk2At20StepsIsAboutAsAccurateAsAb2AndBd2At40) {
  ASSERT_TRUE(study_->resolution.has_value());
  const auto& r = *study_->resolution;
  for (const double ratio : {r.ab2_at_40 / r.rk2_at_20, r.bd2_at_40 / r.rk2_at_20}) {
    EXPECT_GT(ratio, 1.0 / 3.0);
    EXPECT_LT(ratio, 3.0);
  }
}

TEST(IntegratorStudyScaling, StiffnessTimesMActsLikeTimeStepTimesRootM) {
  // Thesis §4.4.3: ε depends on ωΔt only, so k/4 at Δt matches k at Δt/2.
  auto options = studies::default_options();
  options.timesteps = {2.5e-5, 1.25e-5};
  options.stiffnesses = {1e5 / 4.0, 1e5 / 16.0};
  options.velocities = {4.0};
  options.nfm_values = {10.0};
  const auto study = studies::run_integrator_study(options);
  for (const char* nfm : {"nfm_10", "nfm_10_5"}) {
    const auto* by_dt = studies::find_sweep(study, std::string("dt_") + nfm);
    const auto* by_k = studies::find_sweep(study, std::string("k_") + nfm);
    ASSERT_NE(by_dt, nullptr);
    ASSERT_NE(by_k, nullptr);
    for (std::size_t s = 0; s < by_dt->schemes.size(); ++s) {
      for (std::size_t i = 0; i < 2; ++i) {
        const double a = *by_dt->schemes[s].points[i].amplitude_error;
        const double b = *by_k->schemes[s].points[i].amplitude_error;
        EXPECT_NEAR(a / b, 1.0, 1e-6) << nfm << " " << dem::scheme_info(by_dt->schemes[s].scheme).keyword;
      }
    }
  }
}

TEST_F(IntegratorStudy, WritesOrdersJsonAndAReportWithPlots) {
  const auto dir = std::filesystem::temp_directory_path() / "demwb_study_test";
  std::filesystem::remove_all(dir);
  const char* argv[] = {"demwb", "study", "integrators"};
  studies::write_integrator_study(*study_, dir, 3, argv);
  const auto orders = nlohmann::json::parse(support::read_file(dir / "orders.json"));
  for (const auto id : dem::thesis_schemes()) {
    const auto& row = orders.at(std::string(dem::scheme_info(id).keyword));
    for (const char* k : {"nfm_10", "nfm_10_5", "sandwich"}) EXPECT_TRUE(row.at(k).is_number()) << k;
  }
  EXPECT_NEAR(orders["rk4"]["sandwich"].get<double>(), order("dt_sandwich", SchemeId::rk4), 1e-12);
  const std::string report = support::read_file(dir / "report.md");
  EXPECT_NE(report.find("Global order of accuracy"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "plots" / "dt_nfm_10_5_fourth.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "study_data.csv"));
}

}  // namespace
