// SPDX-License-Identifier: MIT
// What the LAMMPS engine can express, and how it reports a binary that is not installed.
#include <string>

#include <gtest/gtest.h>

#include "lammps_scenes.hpp"
#include "reference/engine.hpp"
#include "reference/lammps/lammps_engine.hpp"

namespace {

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
  scene.walls.push_back(cases::WallSpec{"floor", {0, 0, -1}, {0, 0, 1}, {0, 0, 0}, 0});
  scene.fluid = cases::FluidSpec{};
  scene.particles[3].motion.push_back(cases::MotionSegmentSpec{1.0, {1.0, 0.0, 0.0}});
  const auto s = LammpsEngine{}.supports(scene);
  EXPECT_EQ(s.reasons.size(), 3u) << s.explain();
  EXPECT_TRUE(mentions(s, "LAMMPS driver: walls are not mapped yet"));
  EXPECT_TRUE(mentions(s, "fluid forces"));
  EXPECT_TRUE(mentions(s, "prescribed motion of particle 3"));
}

TEST(LammpsEngineSupport, NamesEverySubModelThatIsNotMappedYet) {
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
  const auto s = LammpsEngine{}.supports(scene);
  EXPECT_EQ(s.reasons.size(), 3u) << s.explain();
  EXPECT_TRUE(mentions(s, "LAMMPS driver: normal model 'hertz' is not mapped yet"));
  EXPECT_TRUE(mentions(s, "LAMMPS driver: damping model 'restitution' is mapped only with normal "
                          "model 'linear'"));
  EXPECT_TRUE(mentions(s, "LAMMPS driver: tangential model 'spring_coulomb' is not mapped yet"));
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
