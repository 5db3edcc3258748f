// SPDX-License-Identifier: MIT
// What the YADE driver can express (phase 1), and why not, without running YADE.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "reference/yade/model_mapping.hpp"
#include "reference/yade/yade_engine.hpp"
#include "reference/yade/yade_installation.hpp"

namespace yade_support_test {

const std::filesystem::path kCanonical = std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/canonical";

/// The engine with an installation that does not exist: supports() needs no YADE.
reference::YadeEngine offline_engine() {
  return reference::YadeEngine{{"/nonexistent/python3.11", "/nonexistent/yade-double/py"}};
}

bool mentions(const reference::Support& s, const std::string& what) {
  return s.explain().find(what) != std::string::npos;
}

TEST(YadeSupport, CanonicalLinearCasesAreSupported) {
  for (const char* file : {"single_collision.toml", "sandwich.toml"}) {
    const auto s = offline_engine().supports(cases::load_case(kCanonical / file));
    EXPECT_TRUE(s.supported()) << file << ": " << s.explain();
  }
}

TEST(YadeSupport, EachUnmappedFeatureHasItsOwnReason) {
  cases::Scene scene = cases::load_case(kCanonical / "single_collision.toml");
  cases::WallSpec tilted;
  tilted.name = "tilted";
  tilted.normal = {0.0, 0.6, 0.8};
  scene.walls.push_back(tilted);
  scene.fluid = cases::FluidSpec{};
  scene.particles[0].charge = 1e-9;
  scene.particles[1].motion.push_back({});
  const auto s = offline_engine().supports(scene);
  EXPECT_EQ(s.reasons.size(), 4u) << s.explain();
  EXPECT_TRUE(mentions(s, "wall 'tilted' is not normal to a coordinate axis"));
  EXPECT_TRUE(mentions(s, "fluid forces"));
  EXPECT_TRUE(mentions(s, "electric charges"));
  EXPECT_TRUE(mentions(s, "prescribed motion"));
}

TEST(YadeSupport, Phase2CanonicalCasesAreSupportedAndJkrIsNot) {
  for (const char* file : {"hertz_collision.toml", "oblique_wall_impact.toml"}) {
    const auto s = offline_engine().supports(cases::load_case(kCanonical / file));
    EXPECT_TRUE(s.supported()) << file << ": " << s.explain();
  }
  const auto jkr = offline_engine().supports(cases::load_case(kCanonical / "jkr_pulloff.toml"));
  EXPECT_FALSE(jkr.supported());
  EXPECT_TRUE(mentions(jkr, "YADE 2023.02a has no JKR law")) << jkr.explain();
}

TEST(YadeSupport, HertzAgainstAWallIsRefusedForMindlinsWallRadius) {
  cases::Scene scene = cases::load_case(kCanonical / "hertz_collision.toml");
  cases::WallSpec floor;
  floor.name = "floor";
  floor.normal = {0.0, 0.0, 1.0};
  scene.walls.push_back(floor);
  const auto s = offline_engine().supports(scene);
  EXPECT_TRUE(mentions(s, "R* = r/2 instead of r")) << s.explain();
}

TEST(YadeSupport, WallAxisAndSenseFollowTheNormal) {
  using reference::yade::wall_axis;
  EXPECT_EQ(wall_axis({0.0, 0.0, 1.0}).axis, 2);
  EXPECT_EQ(wall_axis({0.0, 0.0, 1.0}).sense, 1);
  EXPECT_EQ(wall_axis({-1.0, 0.0, 0.0}).axis, 0);
  EXPECT_EQ(wall_axis({-1.0, 0.0, 0.0}).sense, -1);
  EXPECT_EQ(wall_axis({0.0, 0.6, 0.8}).axis, -1);
}

TEST(YadeSupport, MindlinModulusIsTheHarmonicSumOfEq313) {
  const double e = reference::yade::yade_effective_modulus(8.4e7, 0.3, 8.4e7, 0.3);
  EXPECT_NEAR(e, 8.4e7 / (2.0 * (1.0 - 0.09)), 1e-7);
}

TEST(YadeSupport, RestitutionIsMappedWithTheAlphaWarning) {
  cases::Scene scene = cases::load_case(kCanonical / "single_collision.toml");
  scene.model.damping = "restitution";
  scene.materials[0].restitution = 0.5;
  const auto m = reference::yade::map_contact_model(scene);
  EXPECT_TRUE(m.reasons.empty());
  EXPECT_TRUE(m.viscous);
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("α = (r_p + r_q)/(r_p + r_q − δ)"), std::string::npos);
  EXPECT_NE(m.conventions.at("contact damping").find("FrictViscoMat"), std::string::npos);
}

TEST(YadeSupport, ClampedDashpotIsNotMappedYet) {
  cases::Scene scene = cases::load_case(kCanonical / "single_collision.toml");
  scene.model.damping = "restitution";
  scene.model.clamp_tensile = true;
  scene.materials[0].restitution = 0.5;
  const auto s = offline_engine().supports(scene);
  EXPECT_TRUE(mentions(s, "clamp_tensile = true is not mapped yet")) << s.explain();
}

TEST(YadeSupport, RestitutionThatYadeCannotMixIsRefused) {
  cases::Scene scene = cases::load_case(kCanonical / "single_collision.toml");
  scene.model.damping = "restitution";
  scene.materials[0].restitution = 0.5;
  dem::MaterialProperties other = scene.materials[0];
  other.name = "other";
  other.restitution = 0.9;
  scene.materials.push_back(other);
  scene.particles[1].material = 1;
  const auto s = offline_engine().supports(scene);
  EXPECT_TRUE(mentions(s, "FrictViscoMat mixes betan per material")) << s.explain();
}

TEST(YadeSupport, MixedDampingRatioFollowsYade) {
  using reference::yade::yade_mixed_damping_ratio;
  EXPECT_EQ(yade_mixed_damping_ratio(0.2, 0.4), 0.30000000000000004);
  EXPECT_EQ(yade_mixed_damping_ratio(0.0, 0.4), 0.4);
  EXPECT_EQ(yade_mixed_damping_ratio(0.2, 0.0), 0.2);
}

TEST(YadeInstallation, VersionComesFromConfigPy) {
  using reference::yade::parse_config_version;
  EXPECT_EQ(parse_config_version("revision='2023.02a'\nversion='2023.02a'\nsourceRoot='/x'\n"),
            "2023.02a");
  EXPECT_EQ(parse_config_version("version=\"1.0\"\n"), "1.0");
  EXPECT_FALSE(parse_config_version("revision='2023.02a'\n"));
  EXPECT_FALSE(parse_config_version("subversion='2'\n"));
  EXPECT_FALSE(parse_config_version("x=1\nversion=unquoted\n"));
}

TEST(YadeInstallation, MissingInterpreterMeansEngineMissing) {
  const auto engine = offline_engine();
  EXPECT_FALSE(engine.version());
  const auto scene = cases::load_case(kCanonical / "single_collision.toml");
  const auto r = reference::run_engine(engine, scene, {});
  EXPECT_EQ(r.status, cases::RunStatus::missing);
  EXPECT_EQ(r.engine, "yade");
}

TEST(YadeInstallation, MissingModuleMeansEngineMissing) {
  const reference::YadeEngine engine{{"/bin/sh", "/nonexistent/yade-double/py"}};
  EXPECT_FALSE(engine.version());
}

TEST(YadeInstallation, MakeEngineKnowsYade) {
  const auto engine = reference::make_engine("yade");
  ASSERT_NE(engine, nullptr);
  EXPECT_EQ(engine->name(), "yade");
}

}  // namespace

namespace yade_support_test {

const std::filesystem::path kEnsembles = std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/ensembles";

TEST(YadeSupport, LinearAgglomerateWithANonCohesiveWallIsMappedWithYadesFrictionCap) {
  // The Python cohesion acts between spheres only: a wall whose material pairs with k_c = 0 is
  // fine, and CundallStrackVisco caps friction with elastic + damping, the case's policy.
  const cases::Scene scene = cases::load_case(kEnsembles / "agglomerate_linear_yade.toml");
  const auto s = offline_engine().supports(scene);
  EXPECT_TRUE(s.supported()) << s.explain();
  const auto m = reference::yade::map_contact_model(scene);
  EXPECT_TRUE(m.python_cohesion);
  EXPECT_NE(m.conventions.at("friction limit").find("elastic + damping"), std::string::npos);
  for (const auto& w : m.warnings) EXPECT_EQ(w.find("friction limit:"), std::string::npos) << w;
}

TEST(YadeSupport, LinearCohesionAgainstACohesiveWallIsRefused) {
  const auto s = offline_engine().supports(cases::load_case(kCanonical / "agglomerate_linear.toml"));
  EXPECT_TRUE(mentions(s, "linear cohesion against plane walls is not mapped")) << s.explain();
}

TEST(YadeSupport, TotalFrictionBasisWithPythonCohesionIsFlagged) {
  // The core's `total` basis includes the cohesive pull, which YADE's cap never sees.
  cases::Scene scene = cases::load_case(kEnsembles / "agglomerate_linear_yade.toml");
  scene.model.friction_limit = dem::FrictionLimit::total;
  const auto m = reference::yade::map_contact_model(scene);
  bool flagged = false;
  for (const auto& w : m.warnings) flagged = flagged || w.find("friction limit: YADE caps with the elastic + damping") != std::string::npos;
  EXPECT_TRUE(flagged);
}

}  // namespace
