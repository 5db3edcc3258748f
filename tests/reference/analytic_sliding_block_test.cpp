// SPDX-License-Identifier: MIT
// The analytic sliding solver: deceleration μ g while sliding, rolling at v0/(1 + I/(m ℓ²)),
// refusal of a sphere that does not start at its static overlap; the canonical case file and the
// in-house core's sliding velocity (deceleration to 1e-6; the 0.1 % requirement is met by far).
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/analytic/sliding_solver.hpp"
#include "reference/inhouse/inhouse_engine.hpp"

namespace analytic_sliding_block_test {

constexpr double kRadius = 0.01;
constexpr double kGravity = 9.81;
const double kMass = 4.0 / 3.0 * std::numbers::pi * 1000.0 * std::pow(kRadius, 3);

cases::Scene sliding_scene(double mu, double v0, double overlap_factor = 1.0) {
  cases::Scene s;
  s.name = "sliding";
  dem::MaterialProperties m;
  m.name = "ball";
  m.density = 1000.0;
  m.normal_stiffness = 1e5;
  m.tangential_stiffness = 1e5;
  m.friction = mu;
  m.tangential_damping_ratio = 0.0;
  s.materials = {m};
  s.model.normal = "linear";
  s.model.tangential = "spring_coulomb";
  cases::ParticleSpec p;
  p.radius = kRadius;
  p.effect_radius = kRadius;
  p.position = {0.0, 0.0, kRadius - overlap_factor * kMass * kGravity / 1e5};
  p.velocity = {v0, 0.0, 0.0};
  s.particles = {p};
  s.walls = {cases::WallSpec{"floor", {0, 0, 0}, {0, 0, 1}, {0, 0, 0}, 0}};
  s.gravity = {0.0, 0.0, -kGravity};
  s.integration.scheme = dem::SchemeId::velocity_verlet;
  s.integration.timestep = 1e-5;
  s.integration.duration = 0.25;
  s.output.trace_every = 10;
  s.output.trace_particles = {0};
  s.output.trace_walls = {{0, 0}};
  s.compare.subject = 0;
  s.compare.wall_contact = cases::ParticlePair{0, 0};
  s.compare.metrics = {"deceleration"};
  return s;
}

TEST(AnalyticSliding, DeceleratesAtMuGThenRollsAtFiveSeventhsOfTheStartSpeed) {
  const double mu = 0.2, v0 = 1.0;
  const reference::analytic::SlidingSolver solver;
  const cases::Scene scene = sliding_scene(mu, v0);
  ASSERT_TRUE(solver.unsupported_reasons(scene).empty());
  const cases::RunResult r = solver.run(scene);
  EXPECT_DOUBLE_EQ(r.exact_metrics.at("deceleration"), mu * kGravity);
  const double lever = kRadius - 0.5 * kMass * kGravity / 1e5;
  const double inertia = 0.4 * kMass * kRadius * kRadius;
  const double v_roll = v0 / (1.0 + inertia / (kMass * lever * lever));
  const auto& t = *r.trace.column("time");
  const auto& vx = *r.trace.column("p0.vx");
  const auto& wy = *r.trace.column("p0.wy");
  const double t_roll = (v0 - v_roll) / (mu * kGravity);
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double ts = std::min(t[k], t_roll);
    EXPECT_NEAR(vx[k], v0 - mu * kGravity * ts, 1e-14);
    EXPECT_NEAR(wy[k], mu * kMass * kGravity * lever * ts / inertia, 1e-11);
  }
  EXPECT_NEAR(vx.back(), lever * wy.back(), 1e-13);  // rolling without slip
  EXPECT_NEAR(vx.back(), 5.0 / 7.0 * v0, 1e-4);
  const auto& fn = *r.trace.column("c0-w0.fn");
  EXPECT_NEAR(fn.front(), kMass * kGravity, 1e-15);
}

TEST(AnalyticSliding, DeclinesASphereAwayFromItsStaticOverlap) {
  const reference::analytic::SlidingSolver solver;
  const auto reasons = solver.unsupported_reasons(sliding_scene(0.2, 1.0, 1.01));
  ASSERT_FALSE(reasons.empty());
  EXPECT_NE(reasons.front().find("static overlap"), std::string::npos) << reasons.front();
  cases::Scene tilted = sliding_scene(0.2, 1.0);
  tilted.gravity = {1.0, 0.0, -kGravity};
  EXPECT_FALSE(solver.unsupported_reasons(tilted).empty());
}

TEST(AnalyticSliding, InhouseVelocityFollowsMuGWithinAMillionthWhileSliding) {
  for (const double mu : {0.1, 0.2, 0.5}) {
    cases::Scene scene = sliding_scene(mu, 1.0);
    scene.integration.duration = 0.35;  // rolling starts at 0.29 s for μ = 0.1
    const cases::RunResult core = reference::run_engine(reference::InhouseEngine{}, scene, {});
    const cases::RunResult exact = reference::analytic::SlidingSolver{}.run(scene);
    const auto& t = *core.trace.column("time");
    const auto& v = *core.trace.column("p0.vx");
    const auto& v_exact = *exact.trace.column("p0.vx");
    const double t_roll = (1.0 - 5.0 / 7.0) / (mu * kGravity);
    // Slope between two sliding rows; the first half kick (no slip yet) only shifts v by μ g Δt/2.
    const std::size_t a = 10, b = static_cast<std::size_t>(0.9 * t_roll / (t[1] - t[0]));
    ASSERT_LT(b, t.size());
    const double slope = (v[b] - v[a]) / (t[b] - t[a]);
    EXPECT_NEAR(-slope, mu * kGravity, 1e-6 * mu * kGravity) << "μ = " << mu;
    EXPECT_NEAR(v[b], v_exact[b], 0.51 * mu * kGravity * 1e-5) << "μ = " << mu;
  }
}

TEST(AnalyticSliding, CanonicalCaseFileIsSupportedAndExact) {
  const cases::Scene scene = cases::load_case(std::filesystem::path(DEMWB_SOURCE_DIR) /
                                              "cases/canonical/sliding_block.toml");
  const reference::AnalyticEngine engine;
  ASSERT_TRUE(engine.supports(scene).supported()) << engine.supports(scene).explain();
  const cases::RunResult r = reference::run_engine(engine, scene, {});
  ASSERT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  EXPECT_DOUBLE_EQ(r.exact_metrics.at("deceleration"), 0.2 * 9.81);
  EXPECT_EQ(r.conventions.at("solver"), "sphere sliding then rolling on a plane");
}

}  // namespace
