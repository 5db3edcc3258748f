// SPDX-License-Identifier: MIT
// The analytic engine's Hertz two-body solver: which scenes it takes, its exact metrics and
// traces (elastic closed form, damped ODE), the canonical Hertz cases, and agreement with the
// in-house core at 100 steps per collision.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "analytic_scenes.hpp"
#include "cases/case_loader.hpp"
#include "dem/contact/laws/hertz.hpp"
#include "dem/particles/particles.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/analytic/hertz_solver.hpp"
#include "reference/inhouse/inhouse_engine.hpp"

namespace analytic_hertz_solver_test {

using demwb_test::at;
using demwb_test::sphere;

constexpr double kYoungs = 1e7;
constexpr double kPoisson = 0.3;
constexpr double kEffective = kYoungs / (2.0 * (1.0 - kPoisson * kPoisson));

/// The Hertz impact measured with LAMMPS, as a scene: r = 0.01 m (ρ = 1000) at `speed` onto a
/// fixed r = 0.1 m sphere (or, with `wall`, a plane wall) whose surface is 10.37 speed·Δt away.
cases::Scene hertz_scene(const std::string& damping, double speed = 1.0, bool wall = false,
                         double dt = 1e-5) {
  cases::Scene s;
  s.name = "hertz";
  dem::MaterialProperties m;
  m.name = "soft";
  m.density = 1000.0;
  m.youngs_modulus = kYoungs;
  m.poisson_ratio = kPoisson;
  m.restitution = 0.5;
  m.viscous_modulus = 20.0;  // kuwabara_kono: E' [Pa·s]
  s.materials = {m};
  s.model.normal = "hertz";
  s.model.damping = damping;
  s.integration.scheme = dem::SchemeId::velocity_verlet;
  s.integration.timestep = dt;
  s.integration.duration = 3e-3;
  s.integration.rotation = false;
  const double gap = 10.37 * speed * dt;
  s.particles.push_back(sphere(0.01, {0.0, 0.0, 0.0}, {speed, 0.0, 0.0}, false));
  if (wall) {
    cases::WallSpec w;
    w.name = "right";
    w.point = {0.01 + gap, 0.0, 0.0};
    w.normal = {-1.0, 0.0, 0.0};
    s.walls.push_back(w);
    s.output.trace_walls = {{0, 0}};
    s.compare.wall_contact = cases::ParticlePair{0, 0};
  } else {
    s.particles.push_back(sphere(0.1, {0.11 + gap, 0.0, 0.0}, {0.0, 0.0, 0.0}, true));
    s.output.trace_pairs = {{0, 1}};
    s.compare.pair = cases::ParticlePair{0, 1};
  }
  s.output.trace_particles = {0};
  s.compare.subject = 0;
  return s;
}

double mass() { return dem::sphere_mass(1000.0, 0.01); }

cases::RunResult analytic(const cases::Scene& scene) {
  const cases::RunResult r = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  EXPECT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  return r;
}

/// The Hertz solver's reasons (the engine's first solver declines every Hertz scene).
std::vector<std::string> reasons(const cases::Scene& scene) {
  return reference::analytic::HertzSolver().unsupported_reasons(scene);
}

bool mentions(const std::vector<std::string>& all, const std::string& text) {
  return std::any_of(all.begin(), all.end(), [&](const std::string& r) {
    return r.rfind("analytic (Hertz two-body): ", 0) == 0 && r.find(text) != std::string::npos;
  });
}

TEST(AnalyticHertzSolver, TakesHertzCollisionsWithAFixedSphereAWallOrTwoMobileSpheres) {
  EXPECT_TRUE(reasons(hertz_scene("none")).empty());
  EXPECT_TRUE(reasons(hertz_scene("tsuji", 1.0, true)).empty());
  cases::Scene two = hertz_scene("lammps_tsuji");
  two.particles[1].fixed = false;
  EXPECT_TRUE(reasons(two).empty());
  EXPECT_TRUE(reference::AnalyticEngine{}.supports(hertz_scene("kuwabara_kono")).supported());
}

TEST(AnalyticHertzSolver, DeclinesWhatItCannotSolveWithReasons) {
  cases::Scene linear = demwb_test::single_collision();
  EXPECT_TRUE(mentions(reasons(linear), "normal model 'linear'"));
  cases::Scene gravity = hertz_scene("none");
  gravity.gravity = {0.0, 0.0, -9.81};
  EXPECT_TRUE(mentions(reasons(gravity), "gravity"));
  cases::Scene oblique = hertz_scene("none");
  oblique.particles[0].velocity = {1.0, 0.3, 0.0};
  EXPECT_TRUE(mentions(reasons(oblique), "head-on"));
  cases::Scene three = hertz_scene("none");
  three.particles.push_back(sphere(0.01, {-0.5, 0.0, 0.0}, {0.0, 0.0, 0.0}, true));
  EXPECT_TRUE(mentions(reasons(three), "exactly two bodies"));
  cases::Scene overlapping = hertz_scene("none");
  overlapping.particles[1].position[0] = 0.1099;
  EXPECT_TRUE(mentions(reasons(overlapping), "overlap"));
  cases::Scene friction = hertz_scene("none");
  friction.model.tangential = "spring_coulomb";
  EXPECT_TRUE(mentions(reasons(friction), "tangential model"));
}

TEST(AnalyticHertzSolver, ElasticImpactGivesTheClosedFormMetrics) {
  const cases::RunResult r = analytic(hertz_scene("none"));
  const double r_star = 0.01 * 0.1 / 0.11;
  const double tc = dem::laws::hertz_contact_duration(mass(), kEffective, r_star, 1.0);
  const double dmax = dem::laws::hertz_max_overlap(mass(), kEffective, r_star, 1.0);
  EXPECT_NEAR(r.exact_metrics.at("contact_duration"), tc, 1e-15);
  EXPECT_NEAR(r.exact_metrics.at("contact_duration"), 1.654862e-3, 3e-9);  // LAMMPS, dt = 1e-6
  EXPECT_NEAR(r.exact_metrics.at("max_overlap"), dmax, 1e-18);
  EXPECT_NEAR(r.exact_metrics.at("max_force"), dem::laws::hertz_force(kEffective, r_star, dmax), 1e-12);
  EXPECT_EQ(r.exact_metrics.at("restitution"), 1.0);
  EXPECT_NE(r.conventions.at("solution").find("ibetac_inv"), std::string::npos);
  EXPECT_EQ(r.conventions.at("solver"), "Hertz two-body contact");
}

TEST(AnalyticHertzSolver, ElasticTraceMovesTheSphereByTheOverlapAndRebounds) {
  const cases::Scene scene = hertz_scene("none");
  const cases::RunResult r = analytic(scene);
  const double dt = 1e-5, gap = 10.37 * dt;
  ASSERT_EQ(r.trace.rows(), 301U);
  for (std::size_t k = 0; k < r.trace.rows(); ++k) {
    const double overlap = at(r.trace, "c0-1.overlap", k);
    EXPECT_NEAR(at(r.trace, "p0.x", k), overlap + gap, 1e-15) << k;  // x_p = δ + gap
    const double force = at(r.trace, "c0-1.fn", k);
    if (overlap > 0.0) {
      EXPECT_NEAR(force, dem::laws::hertz_force(kEffective, 0.01 * 0.1 / 0.11, overlap), 1e-12) << k;
      EXPECT_NEAR(at(r.trace, "p0.fx", k), -force, 1e-15) << k;
    } else {
      EXPECT_EQ(force, 0.0) << k;
    }
  }
  EXPECT_NEAR(at(r.trace, "p0.vx", r.trace.rows() - 1), -1.0, 1e-13);
}

TEST(AnalyticHertzSolver, TsujiDampedImpactReboundsWithTheRequestedRestitution) {
  for (const double v : {0.2, 3.0}) {
    const cases::RunResult r = analytic(hertz_scene("tsuji", v));
    EXPECT_NEAR(r.exact_metrics.at("restitution"), 0.5, 1e-9) << "v = " << v;
    EXPECT_NEAR(at(r.trace, "p0.vx", r.trace.rows() - 1), -0.5 * v, 1e-9 * v) << "v = " << v;
    EXPECT_NE(r.conventions.at("solution").find("Dormand–Prince"), std::string::npos);
  }
}

TEST(AnalyticHertzSolver, LammpsTsujiDampingGivesLammpsReboundOfPointSixOneSix) {
  const cases::RunResult r = analytic(hertz_scene("lammps_tsuji", 4.0));
  EXPECT_NEAR(r.exact_metrics.at("restitution"), 0.6160760, 1e-7);
}

TEST(AnalyticHertzSolver, ClippedYadeMindlinDampingFollowsThorntonsFit) {
  cases::Scene scene = hertz_scene("yade_mindlin");
  scene.model.clamp_tensile = true;
  EXPECT_NEAR(analytic(scene).exact_metrics.at("restitution"), 0.500011, 1e-6);
}

TEST(AnalyticHertzSolver, WallImpactUsesRStarEqualToTheRadius) {
  const cases::RunResult r = analytic(hertz_scene("none", 1.0, true));
  EXPECT_NEAR(r.exact_metrics.at("contact_duration"),
              dem::laws::hertz_contact_duration(mass(), kEffective, 0.01, 1.0), 1e-15);
  EXPECT_GT(at(r.trace, "c0-w0.overlap", 100), 0.0);
  EXPECT_EQ(r.trace.columns(), cases::trace_layout(hertz_scene("none", 1.0, true)).columns());
}

TEST(AnalyticHertzSolver, ObliqueWallImpactKeepsTheVelocityAlongTheWall) {
  // 1 m/s into the wall plus 0.4 m/s along it: the normal problem is the head-on one, the
  // sphere slides uniformly along the frictionless wall. Between two spheres it stays refused.
  cases::Scene scene = hertz_scene("none", 1.0, true);
  scene.particles[0].velocity = {1.0, 0.4, 0.0};
  ASSERT_TRUE(reasons(scene).empty()) << reasons(scene).front();
  const cases::RunResult r = analytic(scene);
  EXPECT_NEAR(r.exact_metrics.at("contact_duration"),
              dem::laws::hertz_contact_duration(mass(), kEffective, 0.01, 1.0), 1e-15);
  for (std::size_t k = 0; k < r.trace.rows(); k += 11) {
    const double t = at(r.trace, "time", k);
    EXPECT_DOUBLE_EQ(at(r.trace, "p0.vy", k), 0.4) << k;
    EXPECT_NEAR(at(r.trace, "p0.y", k), 0.4 * t, 1e-15) << k;
    EXPECT_EQ(at(r.trace, "p0.fy", k), 0.0) << k;
  }
  const std::size_t last = r.trace.rows() - 1;
  EXPECT_NEAR(at(r.trace, "p0.vx", last), -1.0, 1e-12);
}

TEST(AnalyticHertzSolver, TwoMobileSpheresConserveMomentum) {
  cases::Scene scene = hertz_scene("tsuji");
  scene.particles[1] = sphere(0.02, {0.03 + 10.37e-5, 0.0, 0.0}, {-0.5, 0.0, 0.0}, false);
  scene.particles[0].velocity = {0.5, 0.0, 0.0};
  scene.output.trace_particles = {0, 1};
  const cases::RunResult r = analytic(scene);
  const double m_a = mass(), m_b = dem::sphere_mass(1000.0, 0.02);
  const double p0 = m_a * 0.5 - m_b * 0.5;
  for (std::size_t k = 0; k < r.trace.rows(); k += 7) {
    EXPECT_NEAR(m_a * at(r.trace, "p0.vx", k) + m_b * at(r.trace, "p1.vx", k), p0, 1e-14) << k;
    EXPECT_NEAR(at(r.trace, "p0.fx", k), -at(r.trace, "p1.fx", k), 1e-12) << k;
  }
  // Relative rebound −ε times the approach speed.
  const std::size_t last = r.trace.rows() - 1;
  EXPECT_NEAR(at(r.trace, "p1.vx", last) - at(r.trace, "p0.vx", last), 0.5, 1e-9);
}

TEST(AnalyticHertzSolver, InhouseVelocityVerletFollowsTheTraceAt100StepsPerCollision) {
  const double tc = dem::laws::hertz_contact_duration(mass(), kEffective, 0.01 * 0.1 / 0.11, 1.0);
  const cases::Scene scene = hertz_scene("none", 1.0, false, tc / 100.0);
  const auto exact = analytic(scene);
  const auto core = reference::run_engine(reference::InhouseEngine{}, scene, {});
  ASSERT_EQ(core.status, cases::RunStatus::ok) << core.reason;
  ASSERT_EQ(exact.trace.rows(), core.trace.rows());
  const double dmax = exact.exact_metrics.at("max_overlap");
  double worst = 0.0;
  for (std::size_t k = 0; k < exact.trace.rows(); ++k) {
    worst = std::max(worst, std::abs(at(core.trace, "c0-1.overlap", k) - at(exact.trace, "c0-1.overlap", k)));
  }
  EXPECT_LT(worst, 2e-3 * dmax);
}

const std::filesystem::path kCanonical = std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/canonical";

TEST(AnalyticHertzCanonical, HertzCollisionFileGivesTheFiguresItsHeaderStates) {
  const cases::RunResult r = analytic(cases::load_case(kCanonical / "hertz_collision.toml"));
  EXPECT_NEAR(r.exact_metrics.at("contact_duration"), 6.93061e-4, 1e-9);
  EXPECT_NEAR(r.exact_metrics.at("max_overlap"), 2.35473e-4, 1e-9);
  EXPECT_NEAR(r.exact_metrics.at("max_force"), 11.1180, 1e-4);
}

TEST(AnalyticHertzCanonical, HertzDampedCollisionFileReboundsAtOneHalf) {
  const cases::RunResult r = analytic(cases::load_case(kCanonical / "hertz_damped_collision.toml"));
  EXPECT_NEAR(r.exact_metrics.at("restitution"), 0.5, 1e-9);
  EXPECT_NEAR(r.exact_metrics.at("contact_duration"), 7.57771e-4, 1e-9);
  EXPECT_NEAR(r.exact_metrics.at("max_overlap"), 1.85428e-4, 1e-9);
  EXPECT_NEAR(r.exact_metrics.at("max_force"), 8.40193, 1e-5);
}

}  // namespace

namespace analytic_hertz_solver_test {

TEST(AnalyticHertzCanonical, RigidWallFileGivesTheFiguresItsHeaderStates) {
  const cases::RunResult r = analytic(cases::load_case(kCanonical / "rigid_wall_hertz.toml"));
  EXPECT_NEAR(r.exact_metrics.at("contact_duration"), 3.506510e-4, 1e-10);
  EXPECT_NEAR(r.exact_metrics.at("max_overlap"), 1.238101e-4, 1e-10);
  EXPECT_NEAR(r.exact_metrics.at("max_force"), 14.27304, 1e-5);
  EXPECT_NEAR(r.exact_metrics.at("restitution"), 1.0, 1e-15);
}

}  // namespace analytic_hertz_solver_test
