// SPDX-License-Identifier: MIT
// Preparation stages end to end: formation settles into one agglomerate, is deterministic for a
// seed and any thread count, and is cached by its inputs; failures name the stage.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "compare/metrics_breakup_run.hpp"
#include "prepare/prepare_scene.hpp"
#include "same_particles.hpp"
#include "../small_agglomerate.hpp"

namespace prepare_scene_test {

cases::Scene load(int count = 8, int seed = 1) {
  return cases::load_case_text(test_support::small_agglomerate(count, seed), "small.toml");
}

/// A fresh, empty cache directory for one test.
std::filesystem::path scratch(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("demwb-prepare-" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

using test_support::same_particles;

/// Fragments of the prepared scene's spheres under its own bond rule.
std::uint32_t fragments_of(const cases::Scene& s) {
  std::vector<std::size_t> mobile;
  std::vector<comparison::breakup::SnapshotSphere> spheres;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    mobile.push_back(i);
    const auto& x = s.particles[i].position;
    spheres.push_back({dem::Vec3(x[0], x[1], x[2]), s.particles[i].radius});
  }
  return static_cast<std::uint32_t>(
      comparison::breakup::fragments(spheres, comparison::scene_bond_rule(s, mobile)).volume.size());
}

TEST(Formation, GathersTheGridIntoOneTouchingAgglomerateAndLaunchesIt) {
  const cases::Scene raw = load();
  ASSERT_EQ(raw.stages.size(), 2U);
  const cases::Scene s = prepare::prepare_scene(raw, {});
  EXPECT_TRUE(s.stages.empty());
  ASSERT_EQ(s.stage_log.size(), 2U);
  EXPECT_EQ(s.stage_log[0].kind, "formation");
  EXPECT_FALSE(s.stage_log[0].cached);
  // Every sphere touches another (pitch 20 mm, radii ≤ 7 mm: none touched at the start).
  std::vector<comparison::breakup::SnapshotSphere> spheres;
  for (const auto& p : s.particles) spheres.push_back({dem::Vec3(p.position[0], p.position[1], p.position[2]), p.radius});
  const auto contacts = comparison::breakup::bonded_pairs(spheres, comparison::breakup::body_contact(spheres));
  std::vector<int> touching(s.particles.size(), 0);
  for (const auto& [i, j] : contacts) touching[i] = touching[j] = 1;
  for (std::size_t i = 0; i < touching.size(); ++i) EXPECT_EQ(touching[i], 1) << "sphere " << i;
  EXPECT_EQ(fragments_of(s), 1U);
  // The launch: duration from eq 5.1 and the snapshots the breakup metrics read.
  const auto& launch = s.stage_log[1].figures;
  ASSERT_EQ(launch[0].first, "enclosing_diameter");
  const double la = launch[0].second;
  EXPECT_GT(la, 0.02);
  EXPECT_LT(la, 0.06);
  EXPECT_DOUBLE_EQ(s.integration.duration, 4.0 * la / (3.0 * std::sin(std::numbers::pi / 4.0)));
  EXPECT_EQ(s.output.snapshot_times, (std::vector<double>{0.0, s.integration.duration}));
  for (const auto& p : s.particles) {
    EXPECT_NEAR(p.velocity[0], 3.0 / std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(p.velocity[2], -3.0 / std::sqrt(2.0), 1e-12);
  }
}

TEST(Formation, IsDeterministicForASeedAndAnyThreadCount) {
  const cases::Scene raw = load(27, 3);
  prepare::PrepareOptions one;
  prepare::PrepareOptions two;
  two.threads = 2;
  const cases::Scene a = prepare::prepare_scene(raw, one);
  EXPECT_TRUE(same_particles(a, prepare::prepare_scene(raw, one)));
  EXPECT_TRUE(same_particles(a, prepare::prepare_scene(raw, two)));
  EXPECT_FALSE(same_particles(a, prepare::prepare_scene(load(27, 4), one)));
}

TEST(Formation, IsCachedByItsInputs) {
  const std::filesystem::path dir = scratch("cache");
  prepare::PrepareOptions options;
  options.cache_dir = dir;
  options.core_revision = "test";
  const cases::Scene raw = load();
  const cases::Scene fresh = prepare::prepare_scene(raw, options);
  const cases::Scene again = prepare::prepare_scene(raw, options);
  EXPECT_FALSE(fresh.stage_log[0].cached);
  EXPECT_TRUE(again.stage_log[0].cached);
  EXPECT_TRUE(same_particles(fresh, again));
  EXPECT_EQ(fresh.stage_log[0].figures, again.stage_log[0].figures);
  // Another input, another key: the pull, the seed, the core revision.
  const std::string key = prepare::stage_key(raw, 0, "test");
  EXPECT_NE(key, prepare::stage_key(raw, 0, "other"));
  EXPECT_NE(key, prepare::stage_key(load(8, 2), 0, "test"));
  cases::Scene stronger = raw;
  std::get<cases::FormationStageSpec>(stronger.stages[0].action).pull = 2.5;
  EXPECT_NE(key, prepare::stage_key(stronger, 0, "test"));
  // …but not the impact: the launch speed and what is traced leave the formation alone.
  cases::Scene faster = raw;
  std::get<cases::LaunchStageSpec>(faster.stages[1].action).speed = 5.0;
  faster.output.trace_every = 7;
  EXPECT_EQ(key, prepare::stage_key(faster, 0, "test"));
  // A damaged cache file is ignored and replaced.
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::ofstream(entry.path()) << "{ not json";
  }
  const cases::Scene repaired = prepare::prepare_scene(raw, options);
  EXPECT_FALSE(repaired.stage_log[0].cached);
  EXPECT_TRUE(same_particles(fresh, repaired));
  std::filesystem::remove_all(dir);
}

TEST(Formation, ThatNeverSettlesIsAnErrorNamingTheStage) {
  const cases::Scene raw = cases::load_case_text(
      test_support::small_agglomerate(8, 1,
                                      "pull = 2.0\npull_time = 0.05\nrestitution = 0.1\n"
                                      "kinetic_energy = 1.0e-8\nmax_duration = 0.06"),
      "short.toml");
  try {
    static_cast<void>(prepare::prepare_scene(raw, {}));
    FAIL() << "expected an error";
  } catch (const cases::CaseError& e) {
    EXPECT_EQ(e.key(), "stages[0]");
    EXPECT_NE(std::string(e.what()).find("had not settled after max_duration = 0.06 s"), std::string::npos) << e.what();
  }
}

TEST(Prepare, LeavesASceneWithoutStagesUnchanged) {
  cases::Scene raw = load();
  raw.stages.clear();
  raw.duration_from_launch = false;
  raw.integration.duration = 0.1;
  const cases::Scene s = prepare::prepare_scene(raw, {});
  EXPECT_TRUE(same_particles(raw, s));
  EXPECT_TRUE(s.stage_log.empty());
}

}  // namespace
