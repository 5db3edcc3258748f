// SPDX-License-Identifier: MIT
// What the LAMMPS engine can express, and how it reports a binary that is not installed.
#include <string>

#include <gtest/gtest.h>

#include "lammps_scenes.hpp"
#include "reference/common/engine.hpp"
#include "reference/registry.hpp"
#include "reference/lammps/lammps_engine.hpp"

namespace lammps_engine_support_test {

using reference::LammpsEngine;

bool mentions(const reference::Support& s, const std::string& text) {
  return s.explain().find(text) != std::string::npos;
}

TEST(LammpsEngineSupport, ExpressesTheLinearSpringDashpotWithFixedSpheresAndGravity) {
  const auto s = LammpsEngine{}.supports(demwb_lammps_unit::mixed_scene());
  EXPECT_TRUE(s.supported()) << s.explain();
}

TEST(LammpsEngineSupport, GivesOneReasonPerUnsupportedFeature) {
  cases::Scene scene = demwb_lammps_unit::mixed_scene();
  scene.walls.push_back(
      cases::WallSpec{"ramp", {0, 0, -1}, {0, 0.6, 0.8}, {0, 0, 0}, 0});  // tilted
  scene.fluid = cases::FluidSpec{};
  scene.particles[3].fixed = false;
  scene.particles[3].motion.push_back(cases::MotionSegmentSpec{1.0, {1.0, 0.0, 0.0}});
  const auto s = LammpsEngine{}.supports(scene);
  EXPECT_EQ(s.reasons.size(), 3u) << s.explain();
  EXPECT_TRUE(mentions(s, "fix wall/gran has only xplane/yplane/zplane walls"));
  EXPECT_TRUE(mentions(s, "fluid forces"));
  EXPECT_TRUE(mentions(s, "particle 3 has a prescribed motion but is not fixed"));
}

TEST(LammpsEngineSupport, NamesEverySubModelThatIsNotMapped) {
  cases::Scene scene = demwb_lammps_unit::mixed_scene();
  for (auto& m : scene.materials) {
    m.youngs_modulus = 1e7;
    m.poisson_ratio = 0.3;
    m.tangential_stiffness = 1e4;
    m.tangential_damping_ratio = 0.0;
    m.friction = 0.3;
  }
  scene.model.normal = "hertz";
  scene.model.tangential = "spring_coulomb";
  EXPECT_TRUE(LammpsEngine{}.supports(scene).supported());  // phase 2 maps all three
  scene.model.rolling = "constant_torque";
  for (auto& m : scene.materials) {
    m.rolling_friction = 0.1;
  }
  const auto s = LammpsEngine{}.supports(scene);
  EXPECT_EQ(s.reasons.size(), 1u) << s.explain();
  EXPECT_TRUE(mentions(s, "rolling model 'constant_torque' is not mapped"));
}

TEST(LammpsEngineSupport, RefusesYadesConventionsAndPoliciesPairGranularDoesNotHave) {
  cases::Scene scene = demwb_lammps_unit::mixed_scene();
  scene.model.pair_lever_arm = dem::PairLeverArm::yade_incident;
  EXPECT_TRUE(mentions(LammpsEngine{}.supports(scene), "'yade_incident'"));
  scene.model.pair_lever_arm = dem::PairLeverArm::contact_point;
  scene.model.tangential_history = dem::TangentialHistory::yade_rotate;
  EXPECT_TRUE(mentions(LammpsEngine{}.supports(scene), "'yade_rotate'"));
  scene.model.tangential_history = dem::TangentialHistory::project_rescale;
  scene.model.tangential = "mindlin_8g";
  scene.model.mindlin_form = dem::MindlinForm::incremental;  // written as `mindlin/force`
  EXPECT_FALSE(mentions(LammpsEngine{}.supports(scene), "mindlin_form"));
  scene.model = {};
  scene.model.normal = "hertz";
  scene.model.cohesion = "jkr";
  scene.model.damping = "lammps_velocity";
  scene.model.adhesive_dashpot = dem::AdhesiveDashpot::pulloff_cap;
  EXPECT_TRUE(mentions(LammpsEngine{}.supports(scene), "adhesive_dashpot = 'pulloff_cap'"));
}

TEST(LammpsEngineSupport, IsMissingWhenTheBinaryIsNotInstalled) {
  const LammpsEngine engine(reference::LammpsOptions{"demwb-no-such-lammps", ""});
  EXPECT_FALSE(engine.version().has_value());
  const auto r = reference::run_engine(engine, demwb_lammps_unit::mixed_scene(), {});
  EXPECT_EQ(r.status, cases::RunStatus::missing);
  EXPECT_EQ(r.engine, "lammps");
}

TEST(LammpsEngineSupport, IsRegisteredAsLammps) {
  const auto engine = reference::make_engine("lammps");
  ASSERT_NE(engine, nullptr);
  EXPECT_EQ(engine->name(), "lammps");
}

}  // namespace
