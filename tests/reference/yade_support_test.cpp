// SPDX-License-Identifier: MIT
// What the YADE driver can express (phase 1), and why not, without running YADE.
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "reference/yade/model_mapping.hpp"
#include "reference/yade/run_plan.hpp"
#include "reference/yade/script_writer.hpp"
#include "reference/yade/yade_engine.hpp"
#include "reference/yade/yade_installation.hpp"
#include "reference/registry.hpp"

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

TEST(YadeSupport, AcceptsYadesOwnConventionsAndRefusesLammpsOnes) {
  cases::Scene scene = cases::load_case(kCanonical / "oblique_wall_impact.toml");
  scene.model.pair_lever_arm = dem::PairLeverArm::yade_incident;
  scene.model.wall_lever_arm = dem::WallLeverArm::yade_incident;
  scene.model.tangential_history = dem::TangentialHistory::yade_rotate;
  EXPECT_TRUE(offline_engine().supports(scene).supported()) << offline_engine().supports(scene).explain();
  cases::Scene lammps = scene;
  lammps.model.wall_lever_arm = dem::WallLeverArm::radius;
  EXPECT_TRUE(mentions(offline_engine().supports(lammps), "LAMMPS conventions"));
  scene.model.tangential_history = dem::TangentialHistory::increment_project;
  EXPECT_TRUE(mentions(offline_engine().supports(scene), "LAMMPS conventions"));
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

/// YADE's Mindlin stiffness factors against a wall material: E* and G* as
/// Ip2_FrictMat_FrictMat_MindlinPhys forms them (G = E/(2(1 + ν)) per material).
struct YadeMix {
  double e_star;
  double g_star;
};
YadeMix yade_mix(double e_s, double nu_s, double e_w, double nu_w) {
  const double g_s = e_s / (2.0 * (1.0 + nu_s)), g_w = e_w / (2.0 * (1.0 + nu_w));
  return {reference::yade::yade_effective_modulus(e_s, nu_s, e_w, nu_w),
          1.0 / ((2.0 - nu_s) / g_s + (2.0 - nu_w) / g_w)};
}

TEST(YadeSupport, AHertzWallGetsAMaterialThatRestoresRStarEqualToR) {
  // Sphere E = 8.4e7, ν = 0.3 against (a) a compliant wall of the same material and (b) a rigid
  // one: YADE's R = r/2 needs E* and G* √2 times the case's.
  const double e_s = 8.4e7, nu_s = 0.3;
  const double g_s = e_s / (2.0 * 1.3);
  struct Wall {
    double e_star, g_star;
  };
  for (const Wall w : {Wall{e_s / (2.0 * 0.91), 1.0 / (2.0 * (2.0 - nu_s) / g_s)},
                       Wall{e_s / 0.91, g_s / (2.0 - nu_s)}}) {
    const auto m = reference::yade::compensated_wall_material(e_s, nu_s, w.e_star, w.g_star);
    ASSERT_TRUE(m.has_value());
    const YadeMix mix = yade_mix(e_s, nu_s, m->young, m->poisson);
    EXPECT_NEAR(mix.e_star * std::sqrt(0.005 / 2.0), w.e_star * std::sqrt(0.005), 1e-14 * w.e_star * 0.1);
    EXPECT_NEAR(mix.g_star * std::sqrt(0.005 / 2.0), w.g_star * std::sqrt(0.005), 1e-14 * w.g_star * 0.1);
  }
  // The rigid wall's material: E′ = −(2 + √2) E_s, ν′ = ν_s.
  const auto rigid = reference::yade::compensated_wall_material(e_s, nu_s, e_s / 0.91, g_s / (2.0 - nu_s));
  EXPECT_NEAR(rigid->young, -(2.0 + std::sqrt(2.0)) * e_s, 1e-6);
  EXPECT_NEAR(rigid->poisson, nu_s, 1e-14);
  // Without a tangential law only E* matters; ν′ = ν_s.
  const auto normal_only = reference::yade::compensated_wall_material(e_s, nu_s, e_s / 0.91, std::nullopt);
  EXPECT_EQ(normal_only->poisson, nu_s);
}

TEST(YadeSupport, HertzAgainstAWallIsMappedWithoutFrictionAndRefusedWithIt) {
  cases::Scene scene = cases::load_case(kCanonical / "hertz_collision.toml");
  cases::WallSpec floor;
  floor.name = "floor";
  floor.normal = {0.0, 0.0, 1.0};
  floor.point = {0.0, 0.0, -1.0};
  scene.walls.push_back(floor);
  EXPECT_TRUE(offline_engine().supports(scene).supported()) << offline_engine().supports(scene).explain();
  const auto mapping = reference::yade::map_contact_model(reference::PreparedScene(scene));
  ASSERT_EQ(mapping.wall_materials.size(), 1U);
  ASSERT_EQ(mapping.wall_material_ids.size(), 1U);
  EXPECT_EQ(mapping.wall_material_ids[0], scene.materials.size());  // its own O.materials entry
  scene.model.tangential = "mindlin_8g";
  scene.materials[0].friction = 0.3;
  scene.materials[0].tangential_damping_ratio = 0.0;
  const auto s = offline_engine().supports(scene);
  EXPECT_TRUE(mentions(s, "lever arm r − δ")) << s.explain();
  // A wall of its own frictionless material: μ mixes to 0 there, no torque, mapped.
  cases::Scene smooth_wall = scene;
  dem::MaterialProperties smooth = scene.materials[0];
  smooth.name = "smooth";
  smooth.friction = 0.0;
  smooth_wall.materials.push_back(smooth);
  smooth_wall.walls.back().material = smooth_wall.materials.size() - 1;
  EXPECT_TRUE(offline_engine().supports(smooth_wall).supported()) << offline_engine().supports(smooth_wall).explain();
}

/// The Hertz collision's spheres with Mindlin friction in YADE's form over a mesh `m` of two
/// facets (the square z = −1 cm cut along a diagonal), of the spheres' own material.
cases::Scene scene_over_a_mesh() {
  cases::Scene scene = cases::load_case(kCanonical / "hertz_collision.toml");
  scene.model.tangential = "mindlin_8g";
  scene.model.mindlin_form = dem::MindlinForm::incremental;
  scene.model.clamp_tensile = true;
  scene.materials[0].friction = 0.3;
  scene.materials[0].tangential_damping_ratio = 0.0;
  scene.meshes.push_back({"m", "m.stl", "", 2});
  const cases::Vector3 a{-0.1, -0.1, -0.01}, b{0.1, -0.1, -0.01}, c{0.1, 0.1, -0.01}, d{-0.1, 0.1, -0.01};
  for (const auto& corners : {std::array<cases::Vector3, 3>{a, b, c}, std::array<cases::Vector3, 3>{a, c, d}}) {
    cases::WallSpec facet;
    facet.name = "m." + std::to_string(scene.walls.size());
    facet.shape = dem::WallShape::triangle;
    facet.corners = corners;
    facet.point = corners[0];
    facet.normal = {0.0, 0.0, 1.0};
    facet.mesh = 0;
    scene.walls.push_back(facet);
  }
  return scene;
}

TEST(YadeSupport, AMeshIsFacetsOfOneCompensatedMaterialWithFriction) {
  const cases::Scene scene = scene_over_a_mesh();
  ASSERT_TRUE(offline_engine().supports(scene).supported()) << offline_engine().supports(scene).explain();
  const auto mapping = reference::yade::map_contact_model(reference::PreparedScene(scene));
  // One YADE material for the whole mesh, both facets on it.
  ASSERT_EQ(mapping.wall_materials.size(), 1U);
  ASSERT_EQ(mapping.wall_material_ids.size(), 2U);
  EXPECT_EQ(mapping.wall_material_ids[0], scene.materials.size());
  EXPECT_EQ(mapping.wall_material_ids[1], scene.materials.size());
  // At YADE's facet radius R = 2r/3 the material gives k_no = 4/3 E* √r and k_so = 8 G* √r with
  // the case's sphere–wall E* = E/(2(1 − ν²)) and G* = G/(2(2 − ν)).
  const double e_s = 8.4e7, nu_s = 0.3, g_s = e_s / (2.0 * (1.0 + nu_s));
  const double e_star = e_s / (2.0 * (1.0 - nu_s * nu_s)), g_star = g_s / (2.0 * (2.0 - nu_s));
  const YadeMix mix = yade_mix(e_s, nu_s, mapping.wall_materials[0].young, mapping.wall_materials[0].poisson);
  EXPECT_NEAR(mix.e_star * std::sqrt(2.0 / 3.0), e_star, 1e-13 * e_star);
  EXPECT_NEAR(mix.g_star * std::sqrt(2.0 / 3.0), g_star, 1e-13 * g_star);
  EXPECT_TRUE(mapping.conventions.contains("facet contact radius"));
  EXPECT_TRUE(mapping.conventions.contains("mesh facets"));
  EXPECT_FALSE(mapping.conventions.contains("wall contact radius"));  // no plane wall
  // The script: both facets with their corners, their bounds and their functor.
  const std::string script =
      reference::yade::write_yade_script(scene, reference::yade::make_run_plan(reference::PreparedScene(scene)));
  EXPECT_NE(script.find("('facet', (Vector3(-0.1, -0.1, -0.01), Vector3(0.1, -0.1, -0.01), Vector3(0.1, 0.1, -0.01)), 1)"),
            std::string::npos);
  EXPECT_NE(script.find("('facet', (Vector3(-0.1, -0.1, -0.01), Vector3(0.1, 0.1, -0.01), Vector3(-0.1, 0.1, -0.01)), 1)"),
            std::string::npos);
  EXPECT_NE(script.find("utils.facet(list(shape), material=material, fixed=True)"), std::string::npos);
  EXPECT_NE(script.find("Bo1_Facet_Aabb()"), std::string::npos);
  EXPECT_NE(script.find("Ig2_Facet_Sphere_ScGeom()"), std::string::npos);
}

TEST(YadeSupport, AWallRemovedBeforeTheRunIsLeftOutAndTheBodyIdsCloseUp) {
  // A shutter disc removed at t = 0 before the mesh, a traced floor after it: the disc stood
  // through the preparation only, so the script leaves it out (a disc would be n/a) and the floor
  // is body n + 2 (the two facets come first).
  cases::Scene scene = scene_over_a_mesh();
  cases::WallSpec shutter;
  shutter.name = "shutter";
  shutter.shape = dem::WallShape::annulus;
  shutter.point = {0.0, 0.0, -0.02};
  shutter.normal = {0.0, 0.0, 1.0};
  shutter.size_v = 0.01;
  shutter.removed_at = 0.0;
  scene.walls.insert(scene.walls.begin(), shutter);
  cases::WallSpec floor;
  floor.name = "floor";
  floor.normal = {0.0, 0.0, 1.0};
  floor.point = {0.0, 0.0, -0.03};
  scene.walls.push_back(floor);
  scene.model.tangential = "none";  // friction against a plane wall is n/a under Hertz–Mindlin
  scene.output.trace_walls = {{0, 3}};
  ASSERT_TRUE(offline_engine().supports(scene).supported()) << offline_engine().supports(scene).explain();
  const std::string script =
      reference::yade::write_yade_script(scene, reference::yade::make_run_plan(reference::PreparedScene(scene)));
  // Three walls in WALLS: the two facets and the floor; the disc is not among them.
  std::size_t entries = 0;
  for (const char* kind : {"    ('facet', ", "    ('plane', "}) {
    for (auto at = script.find(kind); at != std::string::npos; at = script.find(kind, at + 1)) ++entries;
  }
  EXPECT_EQ(entries, 3U);
  EXPECT_NE(script.find(fmt::format("TRACED_WALLS = [(0, {})]", scene.particles.size() + 2)), std::string::npos);
  EXPECT_NE(script.find("('plane', (-0.03, 2, 1), "), std::string::npos);
  // Without the mesh the plane-only layout: the floor is body n + 0 and the first WALLS entry.
  cases::Scene planes = scene;
  planes.meshes.clear();
  planes.walls = {scene.walls.front(), scene.walls.back()};
  planes.output.trace_walls = {{0, 1}};
  ASSERT_TRUE(offline_engine().supports(planes).supported()) << offline_engine().supports(planes).explain();
  const std::string plane_script =
      reference::yade::write_yade_script(planes, reference::yade::make_run_plan(reference::PreparedScene(planes)));
  EXPECT_NE(plane_script.find(fmt::format("TRACED_WALLS = [(0, {})]", planes.particles.size())), std::string::npos);
  EXPECT_NE(plane_script.find("WALLS = [\n    (-0.03, 2, 1, "), std::string::npos);
  EXPECT_NE(plane_script.find("    position, axis, sense, _ = WALLS[w - len(PARTICLES)]"), std::string::npos);
  // Removed later, the disc is in the run and not mapped; tracing the one removed at 0 is refused.
  scene.walls[0].removed_at = 0.01;
  EXPECT_TRUE(mentions(offline_engine().supports(scene), "'shutter' is a disc"));
  scene.walls[0].removed_at = 0.0;
  scene.output.trace_walls = {{0, 0}};
  EXPECT_TRUE(mentions(offline_engine().supports(scene), "names wall 'shutter', which is removed before the run"));
}

TEST(YadeSupport, TheRestitutionCalibrationFindsItsWallAmongTheWallsInTheRun) {
  // The oblique wall impact (restitution dashpot, compare.wall_contact = [0, 0]) with a shutter
  // removed at t = 0 put before its floor: the calibration's two-body run takes WALLS[0], the
  // floor, not the scene index 1.
  cases::Scene scene = cases::load_case(kCanonical / "oblique_wall_impact.toml");
  cases::WallSpec shutter = scene.walls[0];
  shutter.name = "shutter";
  shutter.removed_at = 0.0;
  scene.walls.insert(scene.walls.begin(), shutter);
  scene.compare.wall_contact = cases::ParticlePair{0, 1};
  scene.output.trace_walls = {{0, 1}};
  const auto plan = reference::yade::make_run_plan(reference::PreparedScene(scene));
  ASSERT_TRUE(plan.calibration.has_value());
  EXPECT_EQ(plan.calibration->partner_wall, 1U);
  EXPECT_EQ(plan.calibration->partner_wall_entry, 0U);
  const std::string script = reference::yade::write_yade_script(scene, plan);
  EXPECT_NE(script.find("partner_wall=0,"), std::string::npos);
  EXPECT_NE(script.find(fmt::format("TRACED_WALLS = [(0, {})]", scene.particles.size())), std::string::npos);
}

TEST(YadeSupport, AMovingOrRemovedMeshATracedFacetAndTheRestitutionDashpotAreRefused) {
  cases::Scene moving = scene_over_a_mesh();
  for (auto& w : moving.walls) w.velocity = {0.0, 0.0, 0.1};
  EXPECT_TRUE(mentions(offline_engine().supports(moving), "moving mesh 'm' is not mapped"));
  cases::Scene removed = scene_over_a_mesh();
  for (auto& w : removed.walls) w.removed_at = 0.001;
  EXPECT_TRUE(mentions(offline_engine().supports(removed), "mesh 'm' is removed during the run"));
  cases::Scene traced = scene_over_a_mesh();
  traced.output.trace_walls.push_back({0, 1});
  EXPECT_TRUE(mentions(offline_engine().supports(traced), "trace_walls names facet 'm.1'"));
  // The linear law with the restitution dashpot: FrictViscoPhys' α is 3r/(3r − δ) at a facet.
  cases::Scene linear = cases::load_case(kCanonical / "single_collision.toml");
  linear.model.damping = "restitution";
  linear.materials[0].restitution = 0.8;
  const cases::Scene mesh = scene_over_a_mesh();
  linear.meshes = mesh.meshes;
  linear.walls = mesh.walls;
  const auto refused = offline_engine().supports(linear);
  EXPECT_TRUE(mentions(refused, "α = 3r/(3r − δ)")) << refused.explain();
  // Without the dashpot the linear law maps a mesh as it is: the pair's kn and ks.
  linear.model.damping = "none";
  EXPECT_TRUE(offline_engine().supports(linear).supported()) << offline_engine().supports(linear).explain();
}

TEST(YadeSupport, TsujiMapsOnlyWhenTheNormalForceIsClipped) {
  cases::Scene scene = cases::load_case(kCanonical / "hertz_damped_collision.toml");
  ASSERT_EQ(scene.model.damping, "tsuji");
  const auto unclipped = offline_engine().supports(scene);
  EXPECT_TRUE(mentions(unclipped, "clips the normal force")) << unclipped.explain();
  scene.model.clamp_tensile = true;
  const auto mapping = reference::yade::map_contact_model(reference::PreparedScene(scene));
  ASSERT_TRUE(mapping.reasons.empty()) << mapping.reasons.front();
  ASSERT_FALSE(mapping.pairs.empty());
  // β_n = α/(2√1.5), α = −√5 ln ε/√(π² + ln² ε) for the case's ε = 0.5.
  const double l = std::log(0.5);
  const double alpha = -std::sqrt(5.0) * l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
  EXPECT_NEAR(mapping.pairs[0].damping_ratio, alpha / (2.0 * std::sqrt(1.5)), 1e-15);
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
  const auto m = reference::yade::map_contact_model(reference::PreparedScene(scene));
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
  const auto m = reference::yade::map_contact_model(reference::PreparedScene(scene));
  EXPECT_TRUE(m.python_cohesion);
  EXPECT_NE(m.conventions.at("friction limit").find("elastic + damping"), std::string::npos);
  for (const auto& w : m.warnings) EXPECT_EQ(w.find("friction limit:"), std::string::npos) << w;
}

TEST(YadeSupport, LinearCohesionAgainstACohesiveWallIsRefused) {
  const auto s = offline_engine().supports(cases::load_case(kCanonical / "agglomerate_linear.toml"));
  EXPECT_TRUE(mentions(s, "linear cohesion against walls is not mapped")) << s.explain();
}

TEST(YadeSupport, TotalFrictionBasisWithPythonCohesionIsFlagged) {
  // The core's `total` basis includes the cohesive pull, which YADE's cap never sees.
  cases::Scene scene = cases::load_case(kEnsembles / "agglomerate_linear_yade.toml");
  scene.model.friction_limit = dem::FrictionLimit::total;
  const auto m = reference::yade::map_contact_model(reference::PreparedScene(scene));
  bool flagged = false;
  for (const auto& w : m.warnings) flagged = flagged || w.find("friction limit: YADE caps with the elastic + damping") != std::string::npos;
  EXPECT_TRUE(flagged);
}

TEST(YadeSupport, LinearCohesionRestitutionIsAStatedConventionGap) {
  // The betan calibration runs two bodies without the Python cohesion, so it cannot be made; the
  // restitution is n/a with the reason, the other metrics of the case are compared.
  const cases::Scene scene = cases::load_case(kCanonical / "linear_cohesion_pair.toml");
  ASSERT_TRUE(offline_engine().supports(scene).supported()) << offline_engine().supports(scene).explain();
  const auto plan = reference::yade::make_run_plan(reference::PreparedScene(scene));
  EXPECT_FALSE(plan.calibration.has_value());
  ASSERT_EQ(plan.inexpressible_metrics.size(), 1U);
  EXPECT_NE(plan.inexpressible_metrics.at("restitution").find("known convention gap"), std::string::npos);
  // Without cohesion the same dashpot is calibrated and nothing is declared.
  const cases::Scene single_scene = cases::load_case(kCanonical / "single_collision.toml");
  const auto single = reference::yade::make_run_plan(reference::PreparedScene(single_scene));
  EXPECT_TRUE(single.inexpressible_metrics.empty());
}

}  // namespace
