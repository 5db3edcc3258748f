// SPDX-License-Identifier: MIT
// Cohesion metrics from sampled force–separation traces: pull-off force, rupture separation and
// force, separation work (appendix E), equilibrium overlap.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "compare/metrics.hpp"
#include "compare/metrics_cohesion.hpp"
#include "dem/contact/laws/jkr.hpp"

namespace metrics_cohesion_test {

/// The agglomerate-benchmark JKR pair (E* = 4.6154e7 Pa, R* = 2.5 mm, γ = 121.5 J/m²).
const dem::laws::JkrParameters kJkr{8.4e7 / 1.82, 2.5e-3, 121.5};

/// A displacement-controlled JKR pull: δ from δ_max down in steps of `step`, the force on the
/// curve while δ ≥ δ_c, then 0 (docs/physics-cohesion.md).
struct Pull {
  std::vector<double> time, overlap, force;
};
Pull jkr_pull(double d_max, double step) {
  Pull p;
  const double dc = dem::laws::jkr_rupture_overlap(kJkr);
  for (int k = 0;; ++k) {
    const double d = d_max - step * k;
    if (d < 1.5 * dc) break;
    p.time.push_back(1e-3 * k);
    p.overlap.push_back(d);
    p.force.push_back(d >= dc ? dem::laws::jkr_force(dem::laws::jkr_contact_radius(d, kJkr), kJkr) : 0.0);
  }
  return p;
}

cases::Scene pair_scene(std::vector<std::string> metrics) {
  cases::Scene s;
  s.compare.pair = cases::ParticlePair{0, 1};
  s.compare.metrics = std::move(metrics);
  return s;
}

cases::Trace as_trace(const Pull& p) {
  cases::Trace t;
  t.add_column("time");
  t.add_column("c0-1.overlap");
  t.add_column("c0-1.fn");
  for (std::size_t k = 0; k < p.time.size(); ++k) t.append_row({p.time[k], p.overlap[k], p.force[k]});
  return t;
}

cases::RunResult ok_run(cases::Trace trace) {
  cases::RunResult r;
  r.engine = "inhouse";
  r.status = cases::RunStatus::ok;
  r.trace = std::move(trace);
  return r;
}

TEST(CohesionMetrics, RuptureAtTheFoldIsLocatedFarInsideTheSampleSpacing) {
  const double dc = dem::laws::jkr_rupture_overlap(kJkr);
  const double step = 1e-3 * std::abs(dc);
  for (const double phase : {0.0, 0.3, 0.77}) {
    const Pull p = jkr_pull(1.6e-4 + phase * step, step);
    const auto r = comparison::find_rupture(p.overlap, p.force);
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->fold_refined);
    EXPECT_NEAR(r->overlap, dc, 1e-5 * std::abs(dc)) << phase;
    const double f_c = -5.0 / 9.0 * dem::laws::jkr_pulloff_force(kJkr);
    EXPECT_NEAR(r->force, f_c, 1e-3 * std::abs(f_c)) << phase;  // unrefined: up to 3 %
  }
}

TEST(CohesionMetrics, RuptureFallsBackToTheMidpointWithoutAFold) {
  // Linear cohesion: F → 0 continuously at δ̂ = 0; no fold, the break lies between two samples.
  std::vector<double> overlap, force;
  for (int k = 0; k < 50; ++k) {
    const double d = 1e-4 - 2e-4 * k / 49.0 * 30.0;
    overlap.push_back(d);
    const double effect = d + 5e-3;
    force.push_back(effect > 0.0 ? 1e5 * std::max(d, 0.0) - 100.0 * effect : 0.0);
  }
  const auto r = comparison::find_rupture(overlap, force);
  ASSERT_TRUE(r);
  EXPECT_FALSE(r->fold_refined);
  EXPECT_NEAR(r->overlap, 0.5 * (overlap[r->last_attached] + overlap[r->last_attached + 1]), 1e-18);
  EXPECT_LT(overlap[r->last_attached + 1], -5e-3);
  EXPECT_GT(overlap[r->last_attached], -5e-3);
}

TEST(CohesionMetrics, PullOffRuptureAndWorkOfASampledJkrCurve) {
  const double dc = dem::laws::jkr_rupture_overlap(kJkr);
  const double f_po = dem::laws::jkr_pulloff_force(kJkr);
  const Pull p = jkr_pull(1.6e-4, 2e-4 * std::abs(dc));
  const auto m = comparison::compute_metrics(
      pair_scene({"pulloff_force", "rupture_separation", "force_at_rupture", "separation_work",
                  "equilibrium_overlap"}),
      ok_run(as_trace(p)), nullptr);
  EXPECT_NEAR(*m.at("pulloff_force").value, f_po, 1e-8 * f_po);
  EXPECT_NEAR(*m.at("rupture_separation").value, -dc, 1e-6 * std::abs(dc));
  EXPECT_NEAR(*m.at("force_at_rupture").value, -5.0 / 9.0 * f_po, 5e-5 * f_po);
  const double work = dem::laws::jkr_energy(dem::laws::jkr_contact_radius(1.6e-4, kJkr), kJkr) -
                      dem::laws::jkr_energy(dem::laws::jkr_critical_radius(kJkr), kJkr);
  EXPECT_NEAR(*m.at("separation_work").value, work, 1e-5 * std::abs(work));
  EXPECT_EQ(*m.at("equilibrium_overlap").value, p.overlap.back());
  EXPECT_EQ(m.at("pulloff_force").source, "trace");
}

TEST(CohesionMetrics, ProblemsAreReportedNotNaN) {
  Pull repulsive;
  for (int k = 0; k < 10; ++k) {
    repulsive.time.push_back(k);
    repulsive.overlap.push_back(1e-5 * (5 - k));
    repulsive.force.push_back(std::max(0.0, 1e5 * 1e-5 * (5 - k)));
  }
  const auto m = comparison::compute_metrics(pair_scene({"pulloff_force", "rupture_separation"}),
                                             ok_run(as_trace(repulsive)), nullptr);
  EXPECT_FALSE(m.at("pulloff_force").value);
  EXPECT_NE(m.at("pulloff_force").problem.find("never in tension"), std::string::npos);
  EXPECT_NE(m.at("rupture_separation").problem.find("never breaks"), std::string::npos);
  cases::Trace empty;
  empty.add_column("time");
  const auto none = comparison::cohesion_metric("pulloff_force", pair_scene({}), empty);
  ASSERT_TRUE(none);
  EXPECT_NE(none->problem.find("c0-1.overlap"), std::string::npos);
  EXPECT_FALSE(comparison::cohesion_metric("max_force", pair_scene({}), empty));
}

TEST(CohesionMetrics, ReadsThePairColumnsInEitherOrder) {
  const Pull p = jkr_pull(1.6e-4, 1e-7);
  cases::Trace t;
  t.add_column("time");
  t.add_column("c1-0.overlap");
  t.add_column("c1-0.fn");
  for (std::size_t k = 0; k < p.time.size(); ++k) t.append_row({p.time[k], p.overlap[k], p.force[k]});
  const auto v = comparison::cohesion_metric("pulloff_force", pair_scene({}), t);
  ASSERT_TRUE(v && v->value);
  EXPECT_NEAR(*v->value, dem::laws::jkr_pulloff_force(kJkr), 1e-6);
}

}  // namespace
