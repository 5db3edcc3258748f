// SPDX-License-Identifier: MIT
// The reference drivers' input fingerprints: the SHA-256 of the deck or script a run would feed
// the code, computed without the code. A committed baseline is trusted only while it holds.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cases/case_loader.hpp"
#include "lammps_scenes.hpp"
#include "reference/common/engine.hpp"
#include "reference/registry.hpp"
#include "reference/lammps/lammps_engine.hpp"
#include "reference/yade/yade_engine.hpp"
#include "support/text_file.hpp"

namespace input_fingerprint_test {

namespace fs = std::filesystem;

cases::Scene canonical(const std::string& name) {
  return cases::load_case(fs::path(DEMWB_SOURCE_DIR) / "cases/canonical" / (name + ".toml"));
}

bool is_sha256_hex(const std::string& text) {
  return text.size() == 64 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

TEST(InputFingerprint, IsTheSameForTheSameSceneAndChangesWithAnythingTheDeckCarries) {
  for (const char* code : {"lammps", "yade", "liggghts"}) {
    SCOPED_TRACE(code);
    // Binaries that do not exist: the fingerprint needs the driver, not the code.
    const auto engine =
        reference::make_engine(code, {"/nonexistent/lmp", "/nonexistent/yade", "/nonexistent/liggghts", 1.0});
    const cases::Scene scene = canonical("oblique_wall_impact");
    const std::string once = engine->input_fingerprint(scene);
    EXPECT_TRUE(is_sha256_hex(once)) << once;
    EXPECT_EQ(engine->input_fingerprint(canonical("oblique_wall_impact")), once);

    cases::Scene faster = scene;
    faster.particles[0].velocity[0] += 1e-9;
    EXPECT_NE(engine->input_fingerprint(faster), once);
    cases::Scene denser = scene;
    denser.materials[0].density *= 1.0 + 1e-12;
    EXPECT_NE(engine->input_fingerprint(denser), once);
    cases::Scene longer = scene;
    longer.integration.duration *= 2.0;
    EXPECT_NE(engine->input_fingerprint(longer), once);
  }
}

TEST(InputFingerprint, LeavesOutWhatTheDeckDoesNotCarry) {
  // Name, description and tier are not fed to the code.
  const auto lammps = reference::make_engine("lammps");
  const cases::Scene scene = canonical("single_collision");
  cases::Scene renamed = scene;
  renamed.description = "another description";
  renamed.tier = cases::Tier::full;
  EXPECT_EQ(lammps->input_fingerprint(renamed), lammps->input_fingerprint(scene));
}

TEST(InputFingerprint, IsEmptyForScenesTheCodeCannotExpressAndForBuiltInEngines) {
  cases::Scene tilted = demwb_lammps_unit::mixed_scene();
  tilted.walls.push_back(cases::WallSpec{"ramp", {0, 0, -1}, {0, 0.6, 0.8}, {0, 0, 0}, 0});
  EXPECT_EQ(reference::LammpsEngine{}.input_fingerprint(tilted), "");
  EXPECT_EQ(reference::make_engine("yade")->input_fingerprint(canonical("jkr_pulloff")), "");  // n/a on YADE
  EXPECT_EQ(reference::make_engine("liggghts")->input_fingerprint(canonical("jkr_pulloff")), "");  // n/a on LIGGGHTS
  EXPECT_EQ(reference::make_engine("inhouse")->input_fingerprint(canonical("single_collision")), "");
  EXPECT_EQ(reference::make_engine("analytic")->input_fingerprint(canonical("single_collision")), "");
}

TEST(InputFingerprint, DiffersBetweenTheCodes) {
  const cases::Scene scene = canonical("sandwich");
  EXPECT_NE(reference::make_engine("lammps")->input_fingerprint(scene),
            reference::make_engine("yade")->input_fingerprint(scene));
}

}  // namespace input_fingerprint_test

namespace input_fingerprint_test {

TEST(InputFingerprint, EveryCommittedBaselineRecordsTheInputTheDriverWritesNow) {
  // A driver change that alters a deck or script must come with refreshed baselines, or the
  // fast tier (and a machine without the code) would compare against results of another input.
  const fs::path root = fs::path(DEMWB_SOURCE_DIR) / "cases";
  std::size_t checked = 0;
  for (const auto& entry : fs::directory_iterator(root / "baselines")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const auto baseline = nlohmann::json::parse(support::read_file(entry.path()));
    const fs::path case_file = root / "canonical" / (baseline.at("case").get<std::string>() + ".toml");
    ASSERT_TRUE(fs::exists(case_file));
    const cases::Scene scene = cases::load_case(case_file);
    ASSERT_TRUE(baseline.contains("inputs")) << "run `demwb refresh canonical --write-baselines`";
    for (const auto& [engine, result] : baseline.at("references").items()) {
      ASSERT_TRUE(scene.stages.empty()) << "a prepared case: compare against its prepared scene";
      ASSERT_TRUE(baseline.at("inputs").contains(engine)) << engine;
      EXPECT_EQ(baseline.at("inputs").at(engine).get<std::string>(), reference::make_engine(engine)->input_fingerprint(scene))
          << engine << ": the driver now writes another input; run `demwb refresh canonical --write-baselines`";
      ++checked;
    }
  }
  EXPECT_GE(checked, 10u);  // LAMMPS and YADE results of the two-body cases
}

}  // namespace input_fingerprint_test
