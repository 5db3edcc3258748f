// SPDX-License-Identifier: MIT
// The canonical case files of thesis ch. 4, loaded from disk and solved in closed form.
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "dem/particles/particles.hpp"
#include "reference/analytic/analytic_engine.hpp"

namespace analytic_canonical_cases_test {

const std::filesystem::path kCanonical = std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/canonical";

cases::RunResult run_case(const char* file) {
  const cases::Scene scene = cases::load_case(kCanonical / file);
  const reference::AnalyticEngine engine;
  EXPECT_TRUE(engine.supports(scene).supported()) << engine.supports(scene).explain();
  const cases::RunResult r = reference::run_engine(engine, scene, {});
  EXPECT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  return r;
}

TEST(AnalyticCanonicalCases, SingleCollisionFileGivesTheTable42ClosedForms) {
  const cases::RunResult r = run_case("single_collision.toml");
  const double m = dem::sphere_mass(1000.0, 0.01);
  const double root = std::sqrt(m / 1e5);
  EXPECT_NEAR(r.exact_metrics.at("contact_duration"), std::numbers::pi * root, 1e-12 * root);
  EXPECT_NEAR(r.exact_metrics.at("max_overlap"), 4.0 * root, 1e-12 * root);
  EXPECT_NEAR(r.exact_metrics.at("restitution"), 1.0, 1e-12);
  EXPECT_NEAR(r.exact_metrics.at("max_force"), 1e5 * 4.0 * root, 1e-7);
}

TEST(AnalyticCanonicalCases, SandwichFileIsOneHarmonicOscillation) {
  const cases::RunResult r = run_case("sandwich.toml");
  const double omega = std::sqrt(1e5 / dem::sphere_mass(1000.0, 0.01));
  const double amplitude = 4.0 / omega;
  const auto& time = *r.trace.column("time");
  const auto& x = *r.trace.column("p0.x");
  ASSERT_GT(time.size(), 200u);
  for (std::size_t k = 0; k < time.size(); ++k) {
    EXPECT_NEAR(x[k], amplitude * std::sin(omega * time[k]), 1e-13 * amplitude);
  }
}

}  // namespace
