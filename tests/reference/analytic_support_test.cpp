// SPDX-License-Identifier: MIT
// What the closed forms can express, and the reasons given for everything else.
#include <algorithm>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "analytic_scenes.hpp"
#include "reference/analytic/analytic_engine.hpp"
#include "reference/analytic/collinear_solver.hpp"
#include "reference/registry.hpp"
#include "reference/analytic/model_support.hpp"

namespace analytic_support_test {

using demwb_test::head_on;
using demwb_test::sandwich;
using demwb_test::single_collision;

/// The collinear solver's reasons (the engine adds every other solver's reasons after them).
std::vector<std::string> reasons(const cases::Scene& scene) {
  return reference::analytic::CollinearSolver{}.unsupported_reasons(scene);
}

bool mentions(const std::vector<std::string>& all, const std::string& text) {
  return std::any_of(all.begin(), all.end(),
                     [&](const std::string& r) { return r.find(text) != std::string::npos; });
}

TEST(AnalyticSupport, AcceptsTheCanonicalCollinearScenes) {
  EXPECT_TRUE(reasons(single_collision()).empty());
  EXPECT_TRUE(reasons(sandwich()).empty());
  EXPECT_TRUE(reasons(head_on(0.01, 0.02, 1.0, -1.0, 1e-3, 0.5)).empty());
}

TEST(AnalyticSupport, RejectsGravity) {
  cases::Scene scene = single_collision();
  scene.gravity = {0.0, 0.0, -9.81};
  const auto r = reasons(scene);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0],
            "analytic: gravity (0, 0, -9.81) m/s² must be exactly zero (the closed forms have no "
            "body force)");
}

TEST(AnalyticSupport, RejectsANormalModelWithoutClosedForm) {
  cases::Scene scene = single_collision();
  scene.model.normal = "hertz";  // not (yet) in the registry: must not reach the PairTable
  const auto r = reasons(scene);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0], "analytic (collinear collision): normal model 'hertz' is not solved here (only 'linear')");
}

TEST(AnalyticSupport, RejectsOtherDampingFrictionCohesionAndRolling) {
  cases::Scene scene = single_collision();
  scene.model.damping = "tsuji";
  scene.model.tangential = "spring_coulomb";
  scene.model.cohesion = "jkr";
  scene.model.rolling = "sds";
  const auto r = reasons(scene);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0],
            "analytic (collinear collision): damping model 'tsuji' is not solved here (only 'none', "
            "'restitution')");
  EXPECT_TRUE(mentions(r, "tangential model 'spring_coulomb'"));
  EXPECT_TRUE(mentions(r, "cohesion model 'jkr'"));
  EXPECT_TRUE(mentions(r, "rolling model 'sds'"));
}

// What each solver supports is data (reference/analytic/model_support.hpp): a policy the closed
// forms do not reproduce is refused by every solver it would change, never silently ignored.
TEST(AnalyticSupport, RefusesThePoliciesASolverDoesNotReproduce) {
  cases::Scene scene = single_collision();
  scene.model.damping = "restitution";
  scene.model.clamp_tensile = true;  // the collinear closed form is the unclamped dashpot
  auto r = reasons(scene);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NE(r[0].find("clamp_tensile"), std::string::npos) << r[0];
  const reference::analytic::ModelSupport wall{"oblique impact", {"linear"}, {"none"}, {"spring_coulomb"}, {"none"},
                                               {"none"}, false, {dem::WallLeverArm::contact_point}};
  dem::ModelChoice m;
  m.tangential = "spring_coulomb";
  m.wall_lever_arm = dem::WallLeverArm::yade_incident;
  r = reference::analytic::model_reasons(m, wall);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0], "analytic (oblique impact): wall_lever_arm = 'yade_incident' is not solved here (only 'contact_point')");
  m.wall_lever_arm = dem::WallLeverArm::contact_point;
  EXPECT_TRUE(reference::analytic::model_reasons(m, wall).empty());
  // An empty slot list accepts every sub-model of the slot.
  const reference::analytic::ModelSupport any_damping{"x", {"linear"}, {}, {"spring_coulomb"}, {"none"}, {"none"}};
  m.damping = "tsuji";
  EXPECT_TRUE(reference::analytic::model_reasons(m, any_damping).empty());
}

TEST(AnalyticSupport, RejectsAFixedSphereOffTheLineOfMotion) {
  cases::Scene scene = single_collision();
  scene.particles[1].position[1] = 1e-3;
  const auto r = reasons(scene);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(mentions(r, "fixed particle 1 lies 0.001 m off the line of motion of mobile "
                          "particle 0"))
      << r[0];
}

TEST(AnalyticSupport, AcceptsAFixedSphereWithinTheCollinearTolerance) {
  cases::Scene scene = single_collision();
  scene.particles[1].position[1] = 1e-14;  // 1e-13 relative to the 0.11 m distance
  EXPECT_TRUE(reasons(scene).empty());
}

TEST(AnalyticSupport, RejectsThreeMobileSpheres) {
  cases::Scene scene = sandwich();
  scene.particles[1].fixed = false;
  scene.particles[2].fixed = false;
  const auto r = reasons(scene);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0],
            "analytic: 3 mobile spheres; closed forms exist for one mobile sphere among fixed "
            "ones, or for two mobile spheres alone");
}

TEST(AnalyticSupport, RejectsTwoMobileSpheresWithAFixedOne) {
  cases::Scene scene = sandwich();
  scene.particles[1].fixed = false;
  EXPECT_TRUE(mentions(reasons(scene), "2 mobile spheres together with 1 fixed ones"));
}

TEST(AnalyticSupport, RejectsAnObliqueImpactOfTwoMobileSpheres) {
  cases::Scene scene = head_on(0.01, 0.01, 1.0, -1.0, 1e-3, std::nullopt);
  scene.particles[0].velocity[1] = 0.1;
  const auto r = reasons(scene);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(mentions(r, "across their line of centres")) << r[0];
}

TEST(AnalyticSupport, RejectsASphereAtRestTouchingNothing) {
  cases::Scene scene = single_collision();
  scene.particles[0].velocity = {0.0, 0.0, 0.0};
  EXPECT_TRUE(mentions(reasons(scene), "is at rest and touches no fixed sphere"));
}

TEST(AnalyticSupport, AcceptsASphereAtRestPressedIntoAFixedOne) {
  cases::Scene scene = single_collision();
  scene.particles[0].velocity = {0.0, 0.0, 0.0};
  scene.particles[0].position = {scene.particles[1].position[0] - 0.109, 0.0, 0.0};
  EXPECT_TRUE(reasons(scene).empty());
  // Released from 1 mm overlap, it springs off with |v| = δ0 ω.
  const cases::RunResult r = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  ASSERT_EQ(r.status, cases::RunStatus::ok) << r.reason;
  const auto& v = *r.trace.column("p0.vx");
  EXPECT_NEAR(v.back(), -1e-3 * std::sqrt(1e5 / dem::sphere_mass(1000.0, 0.01)), 1e-12);
}

TEST(AnalyticSupport, RejectsAMovingFixedSphere) {
  cases::Scene scene = single_collision();
  scene.particles[1].velocity = {1.0, 0.0, 0.0};
  EXPECT_TRUE(mentions(reasons(scene), "fixed particle 1 has velocity (1, 0, 0) m/s"));
}

TEST(AnalyticSupport, ReportsAMissingPairPropertyFromTheModel) {
  cases::Scene scene = single_collision();
  scene.model.damping = "restitution";  // the material sets no restitution
  const auto r = reasons(scene);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(mentions(r, "restitution")) << r[0];
  EXPECT_EQ(r[0].rfind("analytic: ", 0), 0u);
}

TEST(AnalyticSupport, GivesOneReasonPerViolatedCondition) {
  cases::Scene scene = sandwich();
  scene.gravity = {0.0, -9.81, 0.0};
  scene.model.normal = "hertz";
  scene.particles[1].fixed = false;
  scene.particles[2].fixed = false;
  EXPECT_EQ(reasons(scene).size(), 3u);
}

TEST(AnalyticSupport, UnsupportedScenesAreNotApplicableWithTheReasons) {
  cases::Scene scene = single_collision();
  scene.gravity = {0.0, 0.0, -9.81};
  const cases::RunResult r = reference::run_engine(reference::AnalyticEngine{}, scene, {});
  EXPECT_EQ(r.status, cases::RunStatus::not_applicable);
  EXPECT_NE(r.reason.find("gravity"), std::string::npos);
  EXPECT_EQ(r.version, "closed-form 1");
}

TEST(AnalyticSupport, ExactStatesThrowInvalidArgumentWithTheReasons) {
  cases::Scene scene = single_collision();
  scene.model.normal = "hertz";
  scene.gravity = {0.0, 0.0, -9.81};
  try {
    static_cast<void>(reference::exact_states(reference::PreparedScene(scene), {-1e-5}));
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("normal model 'hertz'"), std::string::npos) << what;
    EXPECT_NE(what.find("gravity"), std::string::npos) << what;
  }
}

TEST(AnalyticSupport, TheEngineFactoryKnowsTheAnalyticEngine) {
  const auto engine = reference::make_engine("analytic");
  ASSERT_NE(engine, nullptr);
  EXPECT_EQ(engine->name(), "analytic");
  EXPECT_EQ(engine->version(), std::optional<std::string>("closed-form 1"));
}

}  // namespace
