// SPDX-License-Identifier: MIT
// Loading the physics-library keys: walls and boxes, fluid fields, prescribed motion, charge,
// model policies, effect radius from the interaction ratio, wall traces and energy traces.
#include <algorithm>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"

namespace case_loader_physics_test {

constexpr const char* kCase = R"(
[case]
name = "physics_keys"

[model]
normal = "linear"
damping = "restitution"
clamp_tensile = true
friction_limit = "elastic_damping"
jkr_rupture = "load"
wall_lever_arm = "radius"
mindlin_radius = "contact_radius"

[materials.lactose]
density = 1550.0
normal_stiffness = 1.0e3
restitution = 0.8
interaction_ratio = 1.1

[materials.pmma]
density = 1190.0
normal_stiffness = 1.0e3
restitution = 0.8

[[particles]]
radius = 2.0e-4
material = "lactose"
position = [1.0e-3, 3.0e-3, 1.0e-3]
velocity = [0.0, 0.0, -0.1]
charge = 1.0e-15

[[particles]]
radius = 2.0e-4
material = "lactose"
position = [1.0e-3, 1.0e-3, 1.0e-3]
fixed = true
motion = [{ duration = 1.0e-3, velocity = [0.0, 0.0, 1.0e-3] }, { velocity = [0.0, 0.0, -1.0e-3] }]

[[walls]]
type = "box"
min = [0.0, 0.0, 0.0]
max = [2.0e-3, 6.0e-3, 2.0e-3]
material = "pmma"
open_faces = ["z+"]

[[walls]]
type = "plane"
name = "lid"
point = [0.0, 0.0, 4.0e-3]
normal = [0.0, 0.0, -2.0]
velocity = [0.0, 0.0, -0.01]
material = "pmma"

[fields]
gravity = [0.0, 0.0, -9.81]

[fields.fluid]
buoyancy = true
virtual_mass = true

[fields.fluid.plug_flow]
speed = 30.0
ramp_time = 13.0e-3
zones = [{ min = [0.0, 0.0, 0.0], max = [2.0e-3, 6.0e-3, 2.0e-3], direction = [0.0, -1.0, 0.0] }]

[integration]
scheme = "velocity_verlet"
timestep = 1.0e-6
duration = 2.0e-3

[output]
trace_walls = [[0, 4]]
trace_energy = true

[compare]
subject = 0
wall_contact = [0, 4]
metrics = ["restitution"]
)";

TEST(CaseLoaderPhysics, ReadsPoliciesIntoTheModelChoice) {
  const auto s = cases::load_case_text(kCase, "p.toml");
  EXPECT_TRUE(s.model.clamp_tensile);
  EXPECT_EQ(s.model.friction_limit, dem::FrictionLimit::elastic_damping);
  EXPECT_EQ(s.model.jkr_rupture, dem::JkrRupture::load);
  EXPECT_EQ(s.model.wall_lever_arm, dem::WallLeverArm::radius);
  EXPECT_EQ(s.model.mindlin_radius, dem::MindlinRadius::contact_radius);
}

TEST(CaseLoaderPhysics, AnUnknownMindlinRadiusIsAnErrorNamingTheKey) {
  std::string text(kCase);
  const std::string from = "mindlin_radius = \"contact_radius\"";
  text.replace(text.find(from), from.size(), "mindlin_radius = \"jkr\"");
  try {
    (void)cases::load_case_text(text, "p.toml");
    FAIL() << "accepted mindlin_radius = 'jkr'";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("mindlin_radius"), std::string::npos) << what;
    EXPECT_NE(what.find("contact_radius"), std::string::npos) << what;  // the admissible values
  }
}

TEST(CaseLoaderPhysics, TheCodeReplicationPoliciesAreReadAndBadValuesNameTheKey) {
  const std::string from = "mindlin_radius = \"contact_radius\"";
  std::string text(kCase);
  text.replace(text.find(from), from.size(),
               "unloaded_slider = \"zero\"\nadhesive_dashpot = \"pulloff_cap\"\nmindlin_form = \"incremental\"\n"
               "pair_lever_arm = \"yade_incident\"\ntangential_history = \"yade_rotate\"\ncoulomb_test = \"spring\"\n"
               "constant_torque_form = \"projected\"");
  text.replace(text.find("wall_lever_arm = \"radius\""), std::string("wall_lever_arm = \"radius\"").size(),
               "wall_lever_arm = \"yade_incident\"");
  const auto s = cases::load_case_text(text, "p.toml");
  EXPECT_EQ(s.model.unloaded_slider, dem::UnloadedSlider::zero);
  EXPECT_EQ(s.model.adhesive_dashpot, dem::AdhesiveDashpot::pulloff_cap);
  EXPECT_EQ(s.model.mindlin_form, dem::MindlinForm::incremental);
  EXPECT_EQ(s.model.pair_lever_arm, dem::PairLeverArm::yade_incident);
  EXPECT_EQ(s.model.wall_lever_arm, dem::WallLeverArm::yade_incident);
  EXPECT_EQ(s.model.tangential_history, dem::TangentialHistory::yade_rotate);
  EXPECT_EQ(s.model.coulomb_test, dem::CoulombTest::spring);
  EXPECT_EQ(s.model.constant_torque_form, dem::ConstantTorqueForm::projected);
  EXPECT_EQ(cases::load_case_text(kCase, "p.toml").model.coulomb_test, dem::CoulombTest::total);  // the default
  EXPECT_EQ(cases::load_case_text(kCase, "p.toml").model.constant_torque_form, dem::ConstantTorqueForm::tangent);
  for (const auto& [key, bad, admissible] :
       {std::tuple<std::string, std::string, std::string>{"unloaded_slider", "drop", "zero"},
        {"adhesive_dashpot", "cap", "pulloff_cap"},
        {"mindlin_form", "force", "incremental"},
        {"coulomb_test", "elastic", "spring"},
        {"constant_torque_form", "unit", "projected"}}) {
    std::string broken(kCase);
    broken.replace(broken.find(from), from.size(), key + " = \"" + bad + "\"");
    try {
      (void)cases::load_case_text(broken, "p.toml");
      ADD_FAILURE() << "accepted " << key << " = '" << bad << "'";
    } catch (const std::exception& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(key), std::string::npos) << what;
      EXPECT_NE(what.find(admissible), std::string::npos) << what;
    }
  }
}

TEST(CaseLoaderPhysics, BoxBecomesInnerPlanesWithoutItsOpenFaces) {
  const auto s = cases::load_case_text(kCase, "p.toml");
  ASSERT_EQ(s.walls.size(), 6U);  // five box faces (z+ open) and the lid
  EXPECT_EQ(s.walls[0].name, "box0.x-");
  EXPECT_EQ(s.walls[0].normal, (cases::Vector3{1.0, 0.0, 0.0}));
  EXPECT_EQ(s.walls[3].normal, (cases::Vector3{0.0, -1.0, 0.0}));
  EXPECT_EQ(s.walls[3].point[1], 6.0e-3);
  EXPECT_EQ(s.walls[4].name, "box0.z-");
  EXPECT_EQ(s.walls[5].name, "lid");
  EXPECT_EQ(s.walls[5].normal, (cases::Vector3{0.0, 0.0, -1.0}));  // normalised
  EXPECT_EQ(s.walls[5].velocity[2], -0.01);
  EXPECT_EQ(s.walls[5].material, 1U);
}

TEST(CaseLoaderPhysics, EffectRadiusDefaultsToInteractionRatioTimesRadius) {
  const auto s = cases::load_case_text(kCase, "p.toml");
  EXPECT_DOUBLE_EQ(s.particles[0].effect_radius, 1.1 * 2.0e-4);
}

TEST(CaseLoaderPhysics, ReadsChargeAndPrescribedMotion) {
  const auto s = cases::load_case_text(kCase, "p.toml");
  EXPECT_EQ(s.particles[0].charge, 1.0e-15);
  ASSERT_EQ(s.particles[1].motion.size(), 2U);
  EXPECT_EQ(s.particles[1].motion[0].duration, 1.0e-3);
  EXPECT_EQ(s.particles[1].motion[1].velocity[2], -1.0e-3);
  EXPECT_EQ(s.particles[1].velocity[2], 1.0e-3);  // the first segment's velocity
}

TEST(CaseLoaderPhysics, ReadsTheFluidAndItsPlugFlow) {
  const auto s = cases::load_case_text(kCase, "p.toml");
  ASSERT_TRUE(s.fluid.has_value());
  EXPECT_EQ(s.fluid->density, 1.205);  // air unless given
  EXPECT_TRUE(s.fluid->drag);
  EXPECT_TRUE(s.fluid->buoyancy);
  EXPECT_TRUE(s.fluid->virtual_mass);
  EXPECT_EQ(s.fluid->plug_speed, 30.0);
  EXPECT_EQ(s.fluid->ramp_time, 13.0e-3);
  ASSERT_EQ(s.fluid->zones.size(), 1U);
  EXPECT_EQ(s.fluid->zones[0].direction, (cases::Vector3{0.0, -1.0, 0.0}));
}

TEST(CaseLoaderPhysics, ReadsWallTracesEnergyTraceAndTheComparedWallContact) {
  const auto s = cases::load_case_text(kCase, "p.toml");
  EXPECT_EQ(s.output.trace_walls, (std::vector<cases::ParticlePair>{{0, 4}}));
  EXPECT_TRUE(s.output.trace_energy);
  ASSERT_TRUE(s.compare.wall_contact.has_value());
  EXPECT_EQ(s.compare.wall_contact->second, 4U);
}

TEST(CaseLoaderPhysics, WallTracesDefaultToTheComparedWallContact) {
  std::string text = kCase;
  text.replace(text.find("trace_walls = [[0, 4]]\n"), 23, "");
  const auto s = cases::load_case_text(text, "p.toml");
  EXPECT_EQ(s.output.trace_walls, (std::vector<cases::ParticlePair>{{0, 4}}));
}

TEST(CaseLoaderPhysics, YoungsModulusIsUsedWhenAModelNeedsTheEffectiveModulus) {
  // With the linear model E and ν are unused and warned about.
  std::string text = kCase;
  text.replace(text.find("interaction_ratio = 1.1\n"), 24,
               "interaction_ratio = 1.1\nyoungs_modulus = 3.2e9\npoisson_ratio = 0.3\n");
  const auto s = cases::load_case_text(text, "p.toml");
  const bool warned = std::any_of(s.warnings.begin(), s.warnings.end(), [](const std::string& w) {
    return w.find("materials.lactose.youngs_modulus") != std::string::npos;
  });
  EXPECT_TRUE(warned);
}

}  // namespace
