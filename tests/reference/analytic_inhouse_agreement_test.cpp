// SPDX-License-Identifier: MIT
// The analytic engine speaks the in-house engine's trace dialect and feeds its exact start-up.
#include <cmath>

#include <gtest/gtest.h>

#include "analytic_scenes.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/registry.hpp"

namespace analytic_inhouse_agreement_test {

using demwb_test::CollisionParameters;
using demwb_test::mobile_mass;

TEST(AnalyticAndInhouse, ShareTraceColumnsAndSampleTimesBitForBit) {
  cases::Scene scene = demwb_test::single_collision();
  scene.integration.scheme = dem::SchemeId::rk4;
  scene.output.trace_every = 4;
  const auto analytic = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  const auto inhouse = reference::run_engine(reference::InhouseEngine{}, scene, {});
  ASSERT_EQ(analytic.status, cases::RunStatus::ok) << analytic.reason;
  ASSERT_EQ(inhouse.status, cases::RunStatus::ok) << inhouse.reason;
  EXPECT_EQ(analytic.trace.columns(), inhouse.trace.columns());
  ASSERT_EQ(analytic.trace.rows(), inhouse.trace.rows());
  EXPECT_EQ(*analytic.trace.column("time"), *inhouse.trace.column("time"));
}

TEST(AnalyticAndInhouse, ExactStartupLetsAdamsBashforthFollowTheSandwich) {
  // Thesis §4.2.2: multi-step schemes started from exact data; the sandwich has no free motion,
  // so AB4 stays close to the harmonic solution (fig. 4.15).
  const CollisionParameters c;
  cases::Scene scene = demwb_test::sandwich(c);
  scene.integration.scheme = dem::SchemeId::ab4;
  scene.integration.startup = dem::StartupPolicy::exact;
  const auto analytic = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  // The registry's in-house engine is the one wired to the closed forms' exact states.
  const auto inhouse = reference::run_engine(*reference::make_engine("inhouse"), scene, {});
  ASSERT_EQ(analytic.status, cases::RunStatus::ok) << analytic.reason;
  ASSERT_EQ(inhouse.status, cases::RunStatus::ok) << inhouse.reason;
  const double amplitude = c.speed / std::sqrt(c.stiffness / mobile_mass(c));
  const auto& exact = *analytic.trace.column("p0.x");
  const auto& numeric = *inhouse.trace.column("p0.x");
  ASSERT_EQ(exact.size(), numeric.size());
  for (std::size_t k = 0; k < exact.size(); ++k) {
    EXPECT_NEAR(numeric[k], exact[k], 1e-4 * amplitude) << "row " << k;
  }
}

TEST(AnalyticAndInhouse, AnInhouseEngineWithoutExactStatesSaysWhereToGetThem) {
  cases::Scene scene = demwb_test::sandwich(CollisionParameters{});
  scene.integration.scheme = dem::SchemeId::ab4;
  scene.integration.startup = dem::StartupPolicy::exact;
  const auto bare = reference::run_engine(reference::InhouseEngine{}, scene, {});
  EXPECT_EQ(bare.status, cases::RunStatus::error);
  EXPECT_NE(bare.reason.find("integration.startup = \"exact\""), std::string::npos) << bare.reason;
  EXPECT_NE(bare.reason.find("make_engine(\"inhouse\")"), std::string::npos) << bare.reason;
}

}  // namespace
