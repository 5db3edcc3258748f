// SPDX-License-Identifier: MIT
// The settle stage (thesis §6.3): a pour settles in the core until its kinetic energy is below
// the threshold, the spheres above the skim height are removed, and the result is deterministic,
// cached by its inputs, and refused with the stage's key when it cannot be had.
#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "prepare/prepare_scene.hpp"
#include "prepare/settle.hpp"
#include "same_particles.hpp"
#include "../small_pour.hpp"

namespace settle_test {

/// 48 spheres of radius 1 mm on a simple cubic grid (pitch 2.2 mm, 3 × 3 a layer) in a box
/// 6.6 mm wide, falling under gravity onto its floor; linear springs with restitution damping.
/// `stage` is the [[stages]] table's body, `extra` more case text.
std::string pour(const std::string& stage, const std::string& extra = "");

/// The end of the settle tests' case files: gravity, velocity Verlet at Δt = 2e-5 s for 10 ms,
/// and a settle stage whose body is `stage`.
std::string settle_tail(const std::string& stage) {
  return R"([fields]
gravity = [0.0, 0.0, -9.81]
[integration]
scheme = "velocity_verlet"
timestep = 2.0e-5
duration = 0.01
[[stages]]
kind = "settle"
)" + stage;
}

std::string pour(const std::string& stage, const std::string& extra) {
  return test_support::small_pour_head("small_pour") + settle_tail(stage) + extra;
}

constexpr const char* kSettle = "kinetic_energy = 1.0e-8\nmin_duration = 0.05\nmax_duration = 2.0\n";

cases::Scene load(const std::string& text) { return cases::load_case_text(text, "small_pour.toml"); }

using test_support::same_particles;

/// The figure `name` of a stage record.
double figure(const cases::StageRecord& r, const std::string& name) {
  for (const auto& [n, v] : r.figures) {
    if (n == name) return v;
  }
  ADD_FAILURE() << "no figure " << name;
  return -1.0;
}

TEST(SettleStage, SettlesBelowTheThresholdAfterTheLeastDurationAndSkimsAboveTheHeight) {
  const cases::Scene raw = load(pour(std::string(kSettle) + "remove_above = 4.0e-3\n"));
  ASSERT_EQ(raw.stages.size(), 1U);
  // The settled pour itself, before the skim.
  const prepare::Settled settled =
      prepare::settle(raw, std::get<cases::SettleStageSpec>(raw.stages[0].action), 1);
  EXPECT_LT(settled.kinetic_energy, 1.0e-8);
  EXPECT_GE(settled.time, 0.05 - 1e-12);
  EXPECT_LT(settled.time, 2.0);
  std::size_t above = 0;
  double top = 0.0;
  for (const auto& p : settled.particles) {
    above += p.position[2] > 4.0e-3 ? 1 : 0;
    top = std::max(top, p.position[2]);
  }
  ASSERT_GT(above, 0U);  // the bed (about 4 layers of 2 mm spheres) reaches above 4 mm
  ASSERT_LT(above, raw.particles.size());
  double start_top = 0.0;
  for (const auto& p : raw.particles) start_top = std::max(start_top, p.position[2]);
  EXPECT_LT(top, start_top - 2.0e-3);  // it fell and compacted: the grid's top layer came down

  const cases::Scene s = prepare::prepare_scene(raw, {});
  EXPECT_TRUE(s.stages.empty());
  ASSERT_EQ(s.stage_log.size(), 1U);
  EXPECT_EQ(s.stage_log[0].kind, "settle");
  EXPECT_EQ(figure(s.stage_log[0], "removed"), static_cast<double>(above));
  EXPECT_EQ(figure(s.stage_log[0], "remaining"), static_cast<double>(raw.particles.size() - above));
  ASSERT_EQ(s.particles.size(), raw.particles.size() - above);
  // The kept spheres are the settled ones at or below the height, in their order.
  std::size_t k = 0;
  for (const auto& p : settled.particles) {
    if (p.position[2] > 4.0e-3) continue;
    EXPECT_EQ(s.particles[k].position, p.position) << k;
    EXPECT_EQ(s.particles[k].velocity, p.velocity) << k;
    ++k;
  }
  EXPECT_EQ(s.population_first, (std::vector<std::size_t>{0}));
}

TEST(SettleStage, IsDeterministicForAnyThreadCountAndCachedWithItsSkim) {
  const cases::Scene raw = load(pour(std::string(kSettle) + "remove_above = 4.0e-3\n"));
  prepare::PrepareOptions one;
  prepare::PrepareOptions two;
  two.threads = 2;
  const cases::Scene a = prepare::prepare_scene(raw, one);
  EXPECT_TRUE(same_particles(a, prepare::prepare_scene(raw, two)));

  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "demwb-settle-cache";
  std::filesystem::remove_all(dir);
  prepare::PrepareOptions cached;
  cached.cache_dir = dir;
  cached.core_revision = "test";
  const cases::Scene fresh = prepare::prepare_scene(raw, cached);
  const cases::Scene again = prepare::prepare_scene(raw, cached);
  EXPECT_FALSE(fresh.stage_log[0].cached);
  EXPECT_TRUE(again.stage_log[0].cached);
  EXPECT_TRUE(same_particles(a, fresh));
  EXPECT_TRUE(same_particles(fresh, again));
  EXPECT_EQ(fresh.stage_log[0].figures, again.stage_log[0].figures);
  // The skim height is part of the stage's inputs.
  const cases::Scene lower = load(pour(std::string(kSettle) + "remove_above = 3.0e-3\n"));
  EXPECT_NE(prepare::stage_key(raw, 0, "test"), prepare::stage_key(lower, 0, "test"));
  std::filesystem::remove_all(dir);
}

TEST(SettleStage, ARestitutionDampsTheSettlingOnly) {
  const cases::Scene raw = load(pour("restitution = 0.1\n" + std::string(kSettle)));
  const auto& stage = std::get<cases::SettleStageSpec>(raw.stages[0].action);
  const cases::Scene settling = prepare::settle_scene(raw, stage);
  EXPECT_EQ(settling.materials[0].restitution, 0.1);
  const cases::Scene s = prepare::prepare_scene(raw, {});
  EXPECT_EQ(s.materials[0].restitution, 0.5);  // the engines run the case's own material
  EXPECT_EQ(s.particles.size(), raw.particles.size());  // no remove_above: nothing removed
}

TEST(SettleStage, TracedParticlesAreRenumberedAndARemovedOneIsAnError) {
  const cases::Scene settled = prepare::prepare_scene(load(pour(kSettle)), {});
  // Find a sphere that ends above 4 mm and one below it after the last.
  std::size_t high = settled.particles.size(), low_after = settled.particles.size();
  for (std::size_t i = 0; i < settled.particles.size(); ++i) {
    if (settled.particles[i].position[2] > 4.0e-3 && high == settled.particles.size()) high = i;
  }
  ASSERT_LT(high, settled.particles.size());
  for (std::size_t i = high + 1; i < settled.particles.size(); ++i) {
    if (settled.particles[i].position[2] <= 4.0e-3) {
      low_after = i;
      break;
    }
  }
  ASSERT_LT(low_after, settled.particles.size());
  std::size_t removed_before = 0;
  for (std::size_t i = 0; i < low_after; ++i) removed_before += settled.particles[i].position[2] > 4.0e-3 ? 1 : 0;

  const std::string skim = std::string(kSettle) + "remove_above = 4.0e-3\n";
  const cases::Scene kept = prepare::prepare_scene(
      load(pour(skim, "[output]\ntrace_particles = [" + std::to_string(low_after) + "]\n")), {});
  ASSERT_EQ(kept.output.trace_particles.size(), 1U);
  EXPECT_EQ(kept.output.trace_particles[0], low_after - removed_before);
  EXPECT_EQ(kept.particles[kept.output.trace_particles[0]].position, settled.particles[low_after].position);
  try {
    prepare::prepare_scene(load(pour(skim, "[output]\ntrace_particles = [" + std::to_string(high) + "]\n")), {});
    ADD_FAILURE() << "expected an error";
  } catch (const cases::CaseError& e) {
    EXPECT_EQ(e.key(), "stages[0]");
    EXPECT_NE(std::string(e.what()).find("output.trace_particles"), std::string::npos) << e.what();
  }
}

TEST(SettleStage, FailuresNameTheStage) {
  const auto expect_error = [](const std::string& text, const std::string& key, const std::string& words) {
    try {
      prepare::prepare_scene(load(text), {});
      ADD_FAILURE() << "expected an error with " << words;
    } catch (const cases::CaseError& e) {
      EXPECT_EQ(e.key(), key) << e.what();
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  // Never below the threshold within max_duration.
  expect_error(pour("kinetic_energy = 1.0e-30\nmax_duration = 0.01\n"), "stages[0]", "had not settled");
  // A skim below every sphere.
  expect_error(pour(std::string(kSettle) + "remove_above = -1.0\n"), "stages[0]", "removes every mobile sphere");
}

/// One sphere (r = 1 mm) resting on a frictional floor and spinning about the vertical at
/// 100 rad/s: its one contact's normal is the spin axis, and no contact model twists it back.
std::string spinning_top(const std::string& stage) {
  return R"([case]
name = "spinning_top"
[model]
normal = "linear"
damping = "restitution"
tangential = "spring_coulomb"
[materials.glass]
density = 2500.0
normal_stiffness = 2000.0
restitution = 0.5
tangential_stiffness = 2000.0
friction = 0.5
tangential_damping_ratio = 0.0
[[particles]]
radius = 1.0e-3
material = "glass"
position = [0.0, 0.0, 0.99995e-3]
angular_velocity = [0.0, 0.0, 100.0]
[[walls]]
type = "plane"
name = "floor"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
material = "glass"
)" + settle_tail("kinetic_energy = 1.0e-12\nmax_duration = 0.2\n" + stage);
}

TEST(SettleStage, ASphereSpinningAboutItsContactNormalIsNamedAndCountSpinFalseLetsTheStageEnd) {
  // Spin energy ½Iω² = ½ · 0.4 m r² · 100² ≈ 2.1e-8 J never decays: the stage fails, naming it.
  try {
    prepare::prepare_scene(load(spinning_top("")), {});
    ADD_FAILURE() << "expected the settle stage to fail";
  } catch (const cases::CaseError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("had not settled"), std::string::npos) << what;
    EXPECT_NE(what.find("the most energetic sphere is particle 0 "), std::string::npos) << what;
    EXPECT_NE(what.find("J of spin (|ω| = 100 rad/s)"), std::string::npos) << what;
  }
  // Translation alone: the sphere comes to rest on the floor, still spinning, and the engines get
  // that spin.
  const cases::Scene scene = load(spinning_top("count_spin = false\n"));
  const auto& stage = std::get<cases::SettleStageSpec>(scene.stages[0].action);
  EXPECT_FALSE(stage.count_spin);
  const prepare::Settled settled = prepare::settle(scene, stage, 1);
  EXPECT_LT(settled.kinetic_energy, 1.0e-12);
  EXPECT_LT(settled.time, 0.2);
  ASSERT_EQ(settled.particles.size(), 1U);
  EXPECT_NEAR(settled.particles[0].angular_velocity[2], 100.0, 1e-9);
  EXPECT_TRUE(std::get<cases::SettleStageSpec>(load(spinning_top("")).stages[0].action).count_spin);
}

TEST(SettleStage, BadKeysAreLoadTimeErrorsNamingTheKey) {
  const auto expect_error = [](const std::string& text, const std::string& words) {
    try {
      load(text);
      ADD_FAILURE() << "expected an error with " << words;
    } catch (const cases::CaseError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  expect_error(pour("kinetic_energy = 1.0e-8\nmin_duration = 0.5\nmax_duration = 0.5\n"), "max_duration");
  expect_error(pour("kinetic_energy = -1.0\nmax_duration = 0.5\n"), "kinetic_energy");
  expect_error(pour("kinetic_energy = 1.0e-8\n"), "max_duration");
  expect_error(pour("kinetic_energy = 1.0e-8\nmax_duration = 0.5\nrestitution = 1.5\n"), "restitution");
  expect_error(pour("kinetic_energy = 1.0e-8\nmax_duration = 0.5\nskim = 1.0\n"), "skim");
  expect_error(pour("kinetic_energy = 1.0e-8\nmax_duration = 0.5\nremove_above = nan\n"), "remove_above");
  expect_error(pour("kinetic_energy = 1.0e-8\nmax_duration = 0.5\ncount_spin = \"no\"\n"), "count_spin");
  std::string weightless = pour(kSettle);
  weightless.replace(weightless.find("gravity = [0.0, 0.0, -9.81]"), 27, "gravity = [0.0, 0.0, 0.0]");
  expect_error(weightless, "needs gravity");
}

}  // namespace settle_test
