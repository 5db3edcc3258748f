// SPDX-License-Identifier: MIT
// The YADE script writer and run plan, without YADE: the script's text says what YADE will do.
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "dem/particles/particles.hpp"
#include "reference/yade/python_literals.hpp"
#include "reference/yade/run_plan.hpp"
#include "reference/yade/runner_script.hpp"
#include "reference/yade/script_writer.hpp"

namespace yade_script_writer_test {

using reference::yade::make_run_plan;
using reference::yade::write_yade_script;

/// Two materials (k_e 1e5 and 3e5 N/m, mixed harmonically to 1.5e5 for the pair), a mobile
/// sphere of each, one fixed sphere, gravity along −z.
cases::Scene two_material_scene() {
  cases::Scene s;
  s.name = "two_materials";
  dem::MaterialProperties soft;
  soft.name = "soft";
  soft.density = 1000.0;
  soft.normal_stiffness = 1e5;
  dem::MaterialProperties hard = soft;
  hard.name = "hard";
  hard.density = 2500.0;
  hard.normal_stiffness = 3e5;
  s.materials = {soft, hard};
  auto sphere = [](double r, std::size_t mat, cases::Vector3 x, cases::Vector3 v, bool fixed) {
    cases::ParticleSpec p;
    p.radius = r;
    p.effect_radius = r;
    p.material = mat;
    p.position = x;
    p.velocity = v;
    p.fixed = fixed;
    return p;
  };
  s.particles = {sphere(0.01, 0, {0.0, 0.0, 0.05}, {0.1, 0.0, -1.0}, false),
                 sphere(0.02, 1, {0.1, 0.0, 0.05}, {0.0, 0.0, 0.0}, false),
                 sphere(0.1, 1, {0.0, 0.0, -0.2}, {0.0, 0.0, 0.0}, true)};
  s.gravity = {0.0, 0.0, -9.81};
  s.integration.scheme = dem::SchemeId::velocity_verlet;
  s.integration.timestep = 1e-5;
  s.integration.duration = 1e-3;
  s.integration.rotation = false;
  s.output.trace_every = 10;
  s.output.trace_particles = {0};
  s.output.trace_pairs = {{0, 2}};
  s.output.snapshot_times = {5e-4, 0.0};
  return s;
}

bool contains(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

TEST(YadeScriptWriter, SetsGlobalDampingToZeroAndRecordsBeforeTheIntegrator) {
  const cases::Scene scene = two_material_scene();
  const std::string s = write_yade_script(scene, make_run_plan(reference::PreparedScene(scene)));
  EXPECT_TRUE(contains(s, "NewtonIntegrator(damping=0.0, gravity=GRAVITY)"));
  EXPECT_TRUE(contains(s, "GRAVITY = Vector3(0.0, 0.0, -9.81)"));
  const auto law = s.find("InteractionLoop(");
  const auto recorder = s.find("PyRunner(command='record_trace()', iterPeriod=TRACE_EVERY, initRun=True)");
  const auto newton = s.find("NewtonIntegrator(");
  ASSERT_NE(recorder, std::string::npos);
  EXPECT_LT(law, recorder);
  EXPECT_LT(recorder, newton);
  EXPECT_TRUE(contains(s, "TRACE_EVERY = 10\n"));
  EXPECT_TRUE(contains(s, "STEPS = 100 "));
  EXPECT_TRUE(contains(s, "O.run(STEPS + 1 - O.iter, True)"));
  EXPECT_TRUE(contains(s, "SNAPSHOT_ITERATIONS = [0, 50]\n"));
  EXPECT_TRUE(contains(s, "'time,p0.x,p0.y,p0.z,p0.vx,p0.vy,p0.vz,p0.wx,p0.wy,p0.wz,p0.fx,p0.fy,p0.fz,"
                          "c0-2.overlap,c0-2.fn'"));
}

TEST(YadeScriptWriter, StepsInItsOwnThreadOnlyWhenAPythonForceRunsEveryIteration) {
  // The linear cohesion is a PyRunner in every iteration: the script steps with O.step() in a
  // loop of its own rather than O.run's worker thread (script_writer.cpp, write_run).
  const cases::Scene cohesive =
      cases::load_case(std::filesystem::path(DEMWB_SOURCE_DIR) / "cases/canonical/linear_cohesion_pair.toml");
  const std::string c = write_yade_script(cohesive, make_run_plan(reference::PreparedScene(cohesive)));
  EXPECT_TRUE(contains(c, "PyRunner(command='apply_cohesion()', iterPeriod=1, initRun=True)"));
  EXPECT_TRUE(contains(c, "def steps(count):\n"));
  EXPECT_TRUE(contains(c, "        O.step()\n"));
  EXPECT_TRUE(contains(c, "        steps(n - O.iter)\n"));
  EXPECT_TRUE(contains(c, "\nsteps(STEPS + 1 - O.iter)\n"));
  EXPECT_FALSE(contains(c, "O.run("));
  // Without a per-iteration Python force the run stays in YADE's own loop.
  const cases::Scene plain = two_material_scene();
  const std::string s = write_yade_script(plain, make_run_plan(reference::PreparedScene(plain)));
  EXPECT_TRUE(contains(s, "        O.run(n - O.iter, True)  # wait=True"));
  EXPECT_TRUE(contains(s, "\nO.run(STEPS + 1 - O.iter, True)\n"));
  EXPECT_FALSE(contains(s, "O.step()"));
}

TEST(YadeScriptWriter, WritesEveryMaterialPairStiffnessFromThePairTable) {
  const cases::Scene scene = two_material_scene();
  const std::string s = write_yade_script(scene, make_run_plan(reference::PreparedScene(scene)));
  // harmonic mix 2·1e5·3e5/(4e5) for the mixed pair
  EXPECT_TRUE(contains(s, "KN = MatchMaker(matches=((0, 0, 100000.0), (0, 1, 150000.0), (1, 1, "
                          "300000.0), ), algo='val', val=float('nan'))"));
  EXPECT_TRUE(contains(s, "KS = MatchMaker(matches=((0, 0, 0.0), (0, 1, 0.0), (1, 1, 0.0), ), "));
  EXPECT_TRUE(contains(s, "Ip2_FrictMat_FrictMat_FrictPhys(kn=KN, ks=KS, frictAngle=FRICTION_ANGLE)"));
  EXPECT_TRUE(contains(s, "Law2_ScGeom_FrictPhys_CundallStrack()"));
  EXPECT_FALSE(contains(s, "FrictViscoMat"));
}

TEST(YadeScriptWriter, GivesTheWorkbenchMassAndHalfStepStartVelocity) {
  const cases::Scene scene = two_material_scene();
  const std::string s = write_yade_script(scene, make_run_plan(reference::PreparedScene(scene)));
  const double m = dem::sphere_mass(1000.0, 0.01);
  // Free of contacts at t = 0 with gravity: v(−Δt/2) = v(0) − Δt/2·g.
  EXPECT_TRUE(contains(s, "(0.01, 0, Vector3(0.0, 0.0, 0.05), Vector3(0.1, 0.0, " +
                              reference::yade::py_float(-1.0 + 0.5 * 1e-5 * 9.81) +
                              "), Vector3(0.0, 0.0, 0.0), False, " + reference::yade::py_float(m)));
  EXPECT_TRUE(contains(s, "(0.1, 1, Vector3(0.0, 0.0, -0.2), Vector3(0.0, 0.0, 0.0), Vector3(0.0, 0.0, 0.0), True, "));
  EXPECT_TRUE(contains(s, "b.state.mass = mass\n"));
  EXPECT_TRUE(contains(s, "b.state.blockedDOFs = 'XYZ'"));  // rotation = false
}

TEST(YadeScriptWriter, MatchedSceneKeepsTheGivenVelocityAsHalfStep) {
  cases::Scene scene = two_material_scene();
  scene.integration.scheme = dem::SchemeId::leapfrog;
  scene.integration.leapfrog_start = dem::LeapfrogStart::given_is_half_step;
  const auto plan = make_run_plan(reference::PreparedScene(scene));
  EXPECT_EQ(plan.start_velocities[0][2], -1.0);
  EXPECT_TRUE(contains(plan.conventions.at("start velocity"), "unchanged"));
}

TEST(YadeScriptWriter, NeverUsesTheLauncherOrItsServers) {
  const cases::Scene scene = two_material_scene();
  const std::string s = write_yade_script(scene, make_run_plan(reference::PreparedScene(scene))) +
                        reference::yade::yade_runner_script("/usr/lib/x86_64-linux-gnu/yade-double/py");
  for (const char* forbidden : {"/usr/bin/yade", "yade -", "yade.remote", "runServers", "xmlrpc", "socket"}) {
    EXPECT_FALSE(contains(s, forbidden)) << forbidden;
  }
  EXPECT_TRUE(contains(s, "import yade\n"));
  EXPECT_TRUE(contains(s, "sys.path.insert(1, '/usr/lib/x86_64-linux-gnu/yade-double/py')"));
  EXPECT_TRUE(contains(s, "os.environ.setdefault('OMP_NUM_THREADS', '1')"));
}

TEST(YadeScriptWriter, IsAPureFunctionOfSceneAndPlan) {
  const cases::Scene scene = two_material_scene();
  EXPECT_EQ(write_yade_script(scene, make_run_plan(reference::PreparedScene(scene))), write_yade_script(scene, make_run_plan(reference::PreparedScene(scene))));
}

TEST(YadeScriptWriter, RestitutionUsesFrictViscoWithHalfTheCoreDampingFactor) {
  cases::Scene scene = two_material_scene();
  scene.model.damping = "restitution";
  scene.materials[0].restitution = 0.5;
  scene.materials[1].restitution = 0.5;
  const auto plan = make_run_plan(reference::PreparedScene(scene));
  ASSERT_TRUE(plan.model.reasons.empty());
  const std::string s = write_yade_script(scene, plan);
  const double ln = std::log(0.5);
  const double betan = -ln / std::sqrt(std::numbers::pi * std::numbers::pi + ln * ln);
  EXPECT_NEAR(plan.model.material_damping_ratio[0], betan, 1e-16);
  EXPECT_TRUE(contains(s, "FrictViscoMat(young=young, poisson=poisson, density=density, frictionAngle=0.0,"));
  EXPECT_TRUE(contains(s, "Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(kn=KN, kRatio=KRATIO, frictAngle=FRICTION_ANGLE)"));
  EXPECT_TRUE(contains(s, "Law2_ScGeom_FrictViscoPhys_CundallStrackVisco()"));
  EXPECT_TRUE(contains(s, "('soft', 1000.0, 1.0, 0.25, " + reference::yade::py_float(plan.model.material_damping_ratio[0]) + "),"));
}

TEST(YadeScriptWriter, PlaneWallBecomesAnAxisAlignedYadeWallWithItsOwnMaterial) {
  const cases::Scene scene = cases::load_case(std::filesystem::path(DEMWB_SOURCE_DIR) /
                                              "cases/canonical/oblique_wall_impact.toml");
  const auto plan = make_run_plan(reference::PreparedScene(scene));
  ASSERT_TRUE(plan.model.reasons.empty());
  const std::string s = write_yade_script(scene, plan);
  EXPECT_TRUE(contains(s, "    (0.0, 2, 1, 0),\n"));  // z = 0, axis z, sense +1, material 0
  EXPECT_TRUE(contains(s, "utils.wall(position, axis=axis, sense=sense, material=material)"));
  EXPECT_TRUE(contains(s, "TRACED_WALLS = [(0, 1)]"));
  EXPECT_TRUE(contains(s, "Ig2_Wall_Sphere_ScGeom()"));
  EXPECT_TRUE(contains(s, "KRATIO = MatchMaker(matches=((0, 0, 10.0), ), "));
  EXPECT_TRUE(contains(s, "FRICTION_ANGLE = MatchMaker(matches=((0, 0, " +
                          reference::yade::py_float(std::atan(0.2)) + "), ), "));
  EXPECT_EQ(plan.trace_columns.back(), "c0-w0.fn");
}

TEST(YadeScriptWriter, HertzUsesMindlinWithTheCaseModuli) {
  const cases::Scene scene = cases::load_case(std::filesystem::path(DEMWB_SOURCE_DIR) /
                                              "cases/canonical/hertz_collision.toml");
  const auto plan = make_run_plan(reference::PreparedScene(scene));
  ASSERT_TRUE(plan.model.reasons.empty());
  const std::string s = write_yade_script(scene, plan);
  EXPECT_TRUE(contains(s, "('agglomerate', 8000.0, 84000000.0, 0.3, 0.0),"));
  EXPECT_TRUE(contains(s, "IP2 = Ip2_FrictMat_FrictMat_MindlinPhys(frictAngle=FRICTION_ANGLE)"));
  EXPECT_TRUE(contains(s, "LAW2 = Law2_ScGeom_MindlinPhys_Mindlin()"));
}

TEST(YadePythonLiterals, RoundTripExactly) {
  using reference::yade::py_float;
  EXPECT_EQ(py_float(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(py_float(1e5), "100000.0");
  EXPECT_EQ(py_float(-0.0), "-0.0");
  EXPECT_EQ(py_float(5e-06), "5e-06");
  EXPECT_EQ(py_float(std::numeric_limits<double>::quiet_NaN()), "float('nan')");
  EXPECT_EQ(py_float(-std::numeric_limits<double>::infinity()), "float('-inf')");
  EXPECT_EQ(reference::yade::py_string("it's a \\ name\n"), "'it\\'s a \\\\ name\\x0a'");
}

TEST(YadeRunPlan, SnapshotIterationsFollowTheInhouseRule) {
  using reference::yade::snapshot_iterations;
  // n·Δt ≥ t − Δt/2 for the first n; times past the last step get none.
  EXPECT_EQ(snapshot_iterations({0.0, 3.7e-4, 8e-4}, 5e-6, 160), (std::vector<std::uint64_t>{0, 74, 160}));
  EXPECT_EQ(snapshot_iterations({2.4e-5, 2.6e-5}, 5e-6, 10), (std::vector<std::uint64_t>{5, 5}));
  EXPECT_EQ(snapshot_iterations({1.0}, 5e-6, 10), (std::vector<std::uint64_t>{}));
}

TEST(YadeRunPlan, ParticleStartingInContactKeepsItsVelocityWithAWarning) {
  cases::Scene scene = two_material_scene();
  scene.particles[0].position = {0.0, 0.0, -0.1};  // overlaps the fixed sphere by 0.01 m
  const auto start = reference::yade::start_velocities(scene, 1e-5);
  EXPECT_EQ(start.velocity[0][2], -1.0);
  ASSERT_EQ(start.warnings.size(), 1u);
  EXPECT_TRUE(contains(start.warnings[0], "particles 0 start in contact"));
}

}  // namespace
