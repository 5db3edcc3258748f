// SPDX-License-Identifier: MIT
// The discharge metrics: mass past an outlet plane, the least-squares flow rate over the fit
// window, and both metrics of a constructed run whose spheres leave at known times.
#include "compare/metrics_discharge.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "compare/metrics.hpp"

namespace {

TEST(DischargeMetrics, MassPastCountsCentresBeyondThePlane) {
  const std::vector<cases::Vector3> centres{{0, 0, 1.0}, {0, 0, -0.5}, {3, 4, -2.0}, {0, 0, 0.0}};
  const std::vector<double> masses{1.0, 2.0, 4.0, 8.0};
  // Outlet z = 0, out of the hopper is −z: spheres 1 and 2 have left; a centre on the plane has not.
  EXPECT_EQ(comparison::mass_past(centres, masses, {0, 0, 0}, {0, 0, -1}), 6.0);
  EXPECT_EQ(comparison::mass_past(centres, masses, {0, 0, -1}, {0, 0, -1}), 4.0);
  EXPECT_EQ(comparison::mass_past(centres, masses, {0, 0, 0}, {0, 0, 1}), 1.0);
}

TEST(DischargeMetrics, TheFlowRateIsTheSlopeOverTheWindow) {
  // Mass leaves at 2 kg/s from t = 1 s until all 10 kg are out at t = 6 s; sampled every 0.5 s.
  std::vector<double> t;
  std::vector<double> m;
  for (int k = 0; k <= 16; ++k) {
    t.push_back(0.5 * k);
    m.push_back(std::clamp(2.0 * (t.back() - 1.0), 0.0, 10.0));
  }
  // In [0.2, 0.6] of 10 kg: the samples with 2…6 kg (t = 2…4 s), on the line.
  const auto fit = comparison::fit_flow_rate(t, m, 10.0, 0.2, 0.6, 3);
  ASSERT_TRUE(fit.has_value());
  EXPECT_EQ(fit->points, 5U);
  EXPECT_NEAR(fit->slope, 2.0, 1e-12);
  EXPECT_NEAR(fit->intercept, -2.0, 1e-12);
  // The whole record would bend the line with the plateaus at both ends.
  const auto all = comparison::fit_flow_rate(t, m, 10.0, 0.0, 1.0, 3);
  ASSERT_TRUE(all.has_value());
  EXPECT_LT(all->slope, 1.9);
  // Too few samples in a narrow window: no rate.
  EXPECT_FALSE(comparison::fit_flow_rate(t, m, 10.0, 0.41, 0.49, 3).has_value());
}

/// Ten unit-density spheres of radius r stacked on the z axis above an outlet at z = 0, falling
/// at 1 m/s: sphere k (centre at z = k + 0.5) passes the outlet at t = k + 0.5 s. Snapshots
/// every 0.25 s for 12 s.
struct Column {
  cases::Scene scene;
  cases::RunResult run;
};

Column column() {
  Column c;
  dem::MaterialProperties m;
  m.density = 1.0;
  c.scene.materials = {m};
  const double r = 0.1;
  for (int k = 0; k < 10; ++k) {
    cases::ParticleSpec p;
    p.radius = r;
    p.position = {0.0, 0.0, k + 0.5};
    c.scene.particles.push_back(p);
  }
  cases::ParticleSpec fixed;  // a fixed sphere below the outlet is never counted
  fixed.radius = 1.0;
  fixed.fixed = true;
  fixed.position = {5.0, 0.0, -3.0};
  c.scene.particles.push_back(fixed);
  c.scene.compare.discharge = cases::DischargeSpec{{0, 0, 0}, {0, 0, -1}, 0.15, 0.65};
  c.scene.compare.metrics = {"mass_flow_rate", "discharged_fraction"};
  c.run.status = cases::RunStatus::ok;
  for (int s = 0; s <= 48; ++s) {
    cases::Snapshot snap;
    snap.time = 0.25 * s;
    for (int k = 0; k < 10; ++k) snap.position.push_back({0.0, 0.0, k + 0.5 - snap.time});
    snap.position.push_back(fixed.position);
    c.run.snapshots.push_back(snap);
  }
  return c;
}

TEST(DischargeMetrics, OfARunWhoseSpheresLeaveOneASecond) {
  Column c = column();
  const double sphere = 4.0 / 3.0 * std::numbers::pi * 0.1 * 0.1 * 0.1;
  const comparison::MetricSet all = comparison::compute_metrics(c.scene, c.run, nullptr);
  EXPECT_DOUBLE_EQ(*all.at("discharged_fraction").value, 1.0);
  // Between 2 and 6 spheres out (t in (1.5, 6.5]): a staircase of one sphere a second, whose
  // least-squares slope over five whole steps of four samples is (1 − Var_step/Var_all) = 1 − 0.0781/2.078
  // sphere masses a second.
  EXPECT_NEAR(*all.at("mass_flow_rate").value, sphere * (1.0 - 0.078125 / 2.078125), 1e-12 * sphere);

  // Stopped at 2 s: 20 % out, and only two snapshots (1.75 and 2 s) in [0.15, 0.65] to fit.
  c.run.snapshots.resize(9);
  const comparison::MetricSet early = comparison::compute_metrics(c.scene, c.run, nullptr);
  EXPECT_DOUBLE_EQ(*early.at("discharged_fraction").value, 0.2);
  EXPECT_FALSE(early.at("mass_flow_rate").value.has_value());
  EXPECT_NE(early.at("mass_flow_rate").problem.find("run longer"), std::string::npos)
      << early.at("mass_flow_rate").problem;

  // No outlet: the metric is missing with the reason.
  c.scene.compare.discharge.reset();
  EXPECT_NE(comparison::compute_metrics(c.scene, c.run, nullptr).at("mass_flow_rate").problem.find("compare.discharge"),
            std::string::npos);
}

}  // namespace
