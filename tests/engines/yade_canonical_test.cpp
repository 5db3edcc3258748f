// SPDX-License-Identifier: MIT
// YADE driver phase 2 on the canonical cases: Hertz–Mindlin (hertz_collision), a FrictVisco
// sphere–wall impact with Coulomb friction (oblique_wall_impact), the α-scaled restitution
// dashpot (single_collision with ε = 0.5) and JKR (n/a). Native runs against the analytic engine
// within the case tolerances; matched runs against the core (inhouse@yade) within 1e-8.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "compare/case_outcome.hpp"
#include "compare/metrics.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/matching.hpp"
#include "reference/yade/run_plan.hpp"
#include "reference/yade/script_writer.hpp"
#include "reference/yade/yade_process.hpp"
#include "support/text_file.hpp"
#include "yade_test_support.hpp"

namespace yade_canonical_test {

using namespace demwb_yade_test;

/// Native YADE against the analytic engine: every metric of the case passes its tolerance.
void expect_native_within_tolerances(const cases::Scene& scene, const std::string& name) {
  const auto analytic = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  const auto yade = reference::run_engine(reference::YadeEngine{}, scene, {scratch(name), 300.0});
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  const auto outcome = comparison::evaluate_runs(scene, {analytic, yade});
  ASSERT_FALSE(outcome.comparisons.empty());
  for (const auto& c : outcome.comparisons) {
    std::printf("  %-24s yade %.9g  analytic %.9g  abs %.3g  rel %.3g  %s\n", c.metric.c_str(),
                c.value.value_or(NAN), c.reference_value.value_or(NAN), c.abs_diff.value_or(NAN),
                c.rel_diff.value_or(NAN), c.note.c_str());
    EXPECT_EQ(c.status, comparison::Status::pass) << c.metric << ": " << c.note;
  }
}

/// Matched numerics: the core with YADE's numerics (inhouse@yade) and YADE on the case
/// agree within 1e-8 on every metric (relative; absolute on restitutions) and on the position
/// trace relative to the largest overlap.
void expect_matched_within_1e8(const cases::Scene& original, const std::string& name) {
  const cases::Scene scene = reference::matched_scene(original, "yade");
  const auto inhouse = reference::run_engine(reference::InhouseEngine{}, scene, {});
  // As `demwb compare --match yade`: YADE runs the case itself (native, calibrated where the
  // driver calibrates), the core runs the matched scene (which repeats the calibration).
  const auto yade = reference::run_engine(reference::YadeEngine{}, original, {scratch(name), 300.0});
  ASSERT_EQ(inhouse.status, cases::RunStatus::ok) << inhouse.reason;
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  const auto a = comparison::compute_metrics(scene, inhouse, nullptr);
  // As the matched rows do: a metric YADE declares natively inexpressible (the restitution of
  // linear_cohesion_pair) is still compared under YADE's own rule.
  cases::RunResult yade_raw = yade;
  yade_raw.inexpressible_metrics.clear();
  const auto b = comparison::compute_metrics(scene, yade_raw, nullptr);
  int compared = 0;
  for (const auto& [metric, value] : a) {
    if (!value.value || !b.at(metric).value) continue;
    const double x = *value.value;
    const double y = *b.at(metric).value;
    const bool absolute = metric.find("restitution") != std::string::npos || metric == "rebound_angle";
    const double diff = absolute ? std::abs(x - y) : std::abs(x - y) / std::max(std::abs(x), 1e-300);
    std::printf("  %-24s inhouse@yade %.15g  yade %.15g  %s diff %.3g\n", metric.c_str(), x, y,
                absolute ? "abs" : "rel", diff);
    EXPECT_LE(diff, 1e-8) << metric;
    ++compared;
  }
  EXPECT_GT(compared, 2);
  std::string problem;
  const auto deviation = comparison::trace_deviation(scene, yade, inhouse, problem);
  ASSERT_TRUE(deviation) << problem;
  std::printf("  trace_deviation %.3g\n", deviation->whole);
  EXPECT_LE(deviation->whole, 1e-8);
}

TEST(YadeHertz, NativeMindlinMeetsTheCaseTolerances) {
  DEMWB_REQUIRE_YADE();
  expect_native_within_tolerances(canonical("hertz_collision.toml"), "hertz-native");
}

TEST(YadeHertz, MatchedMindlinAgreesWithin1em8) {
  DEMWB_REQUIRE_YADE();
  expect_matched_within_1e8(canonical("hertz_collision.toml"), "hertz-matched");
}

TEST(YadeObliqueWall, NativeFrictViscoWallMeetsTheCaseTolerances) {
  DEMWB_REQUIRE_YADE();
  expect_native_within_tolerances(canonical("oblique_wall_impact.toml"), "oblique-native");
}

TEST(YadeObliqueWall, NativeRunRecordsTheRestitutionCalibration) {
  DEMWB_REQUIRE_YADE();
  const auto yade = reference::run_engine(reference::YadeEngine{}, canonical("oblique_wall_impact.toml"),
                                          {scratch("oblique-calibration"), 300.0});
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  ASSERT_EQ(yade.calibrations.size(), 1u);
  const auto& c = yade.calibrations.front();
  for (const auto& [betan, e] : c.samples) std::printf("  betan %.12g -> e %.12g\n", betan, e);
  EXPECT_EQ(c.target, 0.8);
  ASSERT_GE(c.samples.size(), 2u);
  EXPECT_LT(c.samples.front().second, 0.8);  // the textbook betan: YADE's α lowers the rebound
  EXPECT_NEAR(c.samples.back().second, 0.8, 1e-10);
  EXPECT_EQ(c.chosen, c.samples.back().first);
}

TEST(YadeObliqueWall, MatchedFrictViscoWallAgreesWithin1em8) {
  DEMWB_REQUIRE_YADE();
  expect_matched_within_1e8(canonical("oblique_wall_impact.toml"), "oblique-matched");
}

TEST(YadeDampedCollision, MatchedAlphaDashpotAgreesWithin1em8) {
  DEMWB_REQUIRE_YADE();
  cases::Scene scene = canonical("single_collision.toml");
  scene.model.damping = "restitution";
  scene.materials[0].restitution = 0.5;
  expect_matched_within_1e8(scene, "damped-matched-1e8");
}

TEST(YadeHertz, MatchedMindlinDampingAgreesWithin1em8) {
  // damping 'yade_mindlin' = YADE's en → β_n (Thornton 2013 B6–B7), clipped F_n ≥ 0.
  DEMWB_REQUIRE_YADE();
  cases::Scene scene = canonical("hertz_collision.toml");
  scene.model.damping = "yade_mindlin";
  scene.model.clamp_tensile = true;
  scene.materials[0].restitution = 0.5;
  expect_matched_within_1e8(scene, "mindlin-damped-matched");
}

TEST(YadeHertz, MatchedDmtAdhesionAgreesWithin1em8) {
  // cohesion 'dmt' = Mindlin's includeAdhesion with gamma = γ: F = k_no δ^{3/2} − 4πγR*.
  DEMWB_REQUIRE_YADE();
  cases::Scene scene = canonical("hertz_collision.toml");
  scene.model.cohesion = "dmt";
  scene.materials[0].surface_energy = 0.05;
  expect_matched_within_1e8(scene, "dmt-matched");
}

TEST(YadeLinearCohesion, MatchedPythonCohesionForceAgreesWithin1em8) {
  // cohesion 'linear' = a per-step Python force (O.forces.addF) between InteractionLoop and
  // NewtonIntegrator; 10 000 of the case's 200 000 steps keep the test short.
  DEMWB_REQUIRE_YADE();
  cases::Scene scene = canonical("linear_cohesion_pair.toml");
  scene.integration.duration = 0.01;
  scene.compare.metrics = {"contact_duration", "max_overlap", "restitution"};
  expect_matched_within_1e8(scene, "cohesion-matched");
}

TEST(YadeLinearCohesion, SteppingInTheScriptsThreadGivesTheTrajectoryOfORunBitForBit) {
  // A script with a Python force in every iteration steps YADE with O.step() in its own thread
  // (twice as fast as O.run: no Python thread state per PyRunner call). The same script run by
  // O.run writes the same trace, byte for byte, over an approach, a contact and a rebound.
  DEMWB_REQUIRE_YADE();
  cases::Scene scene = canonical("linear_cohesion_pair.toml");
  scene.integration.duration = 0.03;  // contact at ~9 ms, lasting ~0.7 ms
  const std::string stepped = reference::yade::write_yade_script(
      scene, reference::yade::make_run_plan(reference::PreparedScene(scene)));
  ASSERT_NE(stepped.find("O.step()"), std::string::npos);
  std::string threaded = stepped;
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"steps(n - O.iter)", "O.run(n - O.iter, True)"},
                                 {"\nsteps(STEPS + 1 - O.iter)", "\nO.run(STEPS + 1 - O.iter, True)"}}) {
    const auto at = threaded.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    threaded.replace(at, from.size(), to);
  }
  const auto install = reference::yade::default_yade_installation();
  const auto a = reference::yade::run_yade_script(install, stepped, scratch("stepped"), 120.0);
  const auto b = reference::yade::run_yade_script(install, threaded, scratch("threaded"), 120.0);
  ASSERT_TRUE(a.failure.empty()) << a.failure << "\n" << a.log_tail;
  ASSERT_TRUE(b.failure.empty()) << b.failure << "\n" << b.log_tail;
  const std::string trace = support::read_file(a.directory / "trace.csv");
  EXPECT_GT(std::count(trace.begin(), trace.end(), '\n'), 1000);
  EXPECT_EQ(trace, support::read_file(b.directory / "trace.csv"));
  EXPECT_EQ(support::read_file(a.directory / "snapshots.csv"), support::read_file(b.directory / "snapshots.csv"));
}

TEST(YadeJkr, PullOffIsNotApplicableWithTheReason) {
  DEMWB_REQUIRE_YADE();
  const cases::Scene scene = canonical("jkr_pulloff.toml");
  const auto s = reference::YadeEngine{}.supports(scene);
  EXPECT_FALSE(s.supported());
  EXPECT_NE(s.explain().find("YADE 2023.02a has no JKR law"), std::string::npos) << s.explain();
  const auto r = reference::run_engine(reference::YadeEngine{}, scene, {scratch("jkr"), 60.0});
  EXPECT_EQ(r.status, cases::RunStatus::not_applicable);
  EXPECT_NE(r.reason.find("YADE 2023.02a has no JKR law"), std::string::npos) << r.reason;
}

}  // namespace

namespace yade_canonical_test {

TEST(YadeLinearCohesion, ManyParticlesUseTheCollidersCandidatesAndStillMatch) {
  // 125 spheres of the cohesion benchmark's material, 0.3 r apart on a lattice: every neighbour
  // is inside the effect radius 1.5 r, so cohesion pulls the cluster together. The Python force
  // walks the collider's potential interactions (O(N)), so the scene is mapped at any size; the
  // core with YADE's numerics follows YADE to round-off over 2,000 steps.
  DEMWB_REQUIRE_YADE();
  cases::Scene scene = canonical("linear_cohesion_pair.toml");
  scene.particles.clear();
  const double r = 0.005;
  for (int k = 0; k < 125; ++k) {
    cases::ParticleSpec p;
    p.radius = r;
    p.effect_radius = 1.5 * r;
    p.position = {(k % 5) * 2.3 * r, (k / 5 % 5) * 2.3 * r, (k / 25) * 2.3 * r};
    p.velocity = {0.01 * (k % 3), -0.01 * (k % 2), 0.0};
    scene.particles.push_back(p);
  }
  scene.integration.duration = 2000 * 1e-6;
  scene.output.trace_particles = {0, 62, 124};
  scene.output.trace_pairs = {};
  scene.compare.subject = 0;
  scene.compare.pair.reset();
  scene.compare.metrics = {};
  ASSERT_TRUE(reference::YadeEngine{}.supports(scene).supported()) << reference::YadeEngine{}.supports(scene).explain();
  const cases::Scene matched = reference::matched_scene(scene, "yade");
  const auto inhouse = reference::run_engine(reference::InhouseEngine{}, matched, {});
  const auto yade = reference::run_engine(reference::YadeEngine{}, scene, {scratch("cohesion-many"), 300.0});
  ASSERT_EQ(inhouse.status, cases::RunStatus::ok) << inhouse.reason;
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  // Positions relative to the radius, velocities to the largest traced speed.
  double speed = 0.0;
  for (const char* c : {"p0.vx", "p124.vy"}) {
    for (const double v : *inhouse.trace.column(c)) speed = std::max(speed, std::abs(v));
  }
  double worst = 0.0;
  for (const char* c : {"p0.x", "p62.y", "p124.z", "p0.vx", "p124.vy"}) {
    const auto& a = *inhouse.trace.column(c);
    const auto& b = *yade.trace.column(c);
    ASSERT_EQ(a.size(), b.size());
    const double scale = std::string(c).find(".v") != std::string::npos ? speed : r;
    for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::abs(a[k] - b[k]) / scale);
  }
  std::printf("  largest relative trace difference %.3g\n", worst);
  EXPECT_LE(worst, 1e-8);
  // Cohesion acted: particle 124's velocity changed.
  const auto& vx = *inhouse.trace.column("p124.vx");
  EXPECT_GT(std::abs(vx.back() - vx.front()), 1e-4);
}

}  // namespace
