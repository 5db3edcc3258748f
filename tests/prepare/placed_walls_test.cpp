// SPDX-License-Identifier: MIT
// Walls placed when the run starts (`in_preparation = false`: a lid or channel walls closed over a
// bed poured without them) and the skim by the spheres' tops (`remove_by = "top"`) that lets such a
// wall clear the bed.
#include <string>

#include <gtest/gtest.h>

#include "cases/case_loader.hpp"
#include "cases/core_wall.hpp"
#include "dem/contact/wall.hpp"
#include "prepare/prepare_scene.hpp"
#include "prepare/settle.hpp"
#include "same_particles.hpp"
#include "../small_pour.hpp"

namespace placed_walls_test {

/// 48 spheres of radius 1 mm on a simple cubic grid (pitch 2.2 mm, 3 × 3 a layer) falling from up
/// to 2.4 cm into a box 6.6 mm wide; `settle` is the settle stage's body, `walls` more walls.
std::string pour(const std::string& settle, const std::string& walls = "") {
  return test_support::small_pour_head("placed_walls") + walls + R"([fields]
gravity = [0.0, 0.0, -9.81]
[integration]
scheme = "velocity_verlet"
timestep = 2.0e-5
duration = 0.01
[[stages]]
kind = "settle"
kinetic_energy = 1.0e-8
min_duration = 0.05
max_duration = 2.0
)" + settle;
}

/// A lid over the whole box at height z, placed when the run starts unless `in_preparation`.
std::string lid(double z, bool in_preparation = false) {
  return "[[walls]]\ntype = \"rectangle\"\nname = \"lid\"\ncentre = [3.3e-3, 3.3e-3, " + std::to_string(z) +
         "]\nnormal = [0.0, 0.0, 1.0]\naxis = [1.0, 0.0, 0.0]\nsize = [6.6e-3, 6.6e-3]\nmaterial = \"glass\"\n" +
         (in_preparation ? "" : "in_preparation = false\n");
}

cases::Scene load(const std::string& text) { return cases::load_case_text(text, "placed_walls.toml"); }

/// The error text of loading and preparing `text`, with its key; fails the test when there is none.
std::pair<std::string, std::string> error_of(const std::string& text) {
  try {
    prepare::prepare_scene(load(text), {});
  } catch (const cases::CaseError& e) {
    return {e.key(), e.what()};
  }
  ADD_FAILURE() << "expected an error";
  return {};
}

TEST(RemoveByTop, KeepsOnlyTheSpheresWhoseTopsLieBelowTheHeight) {
  const cases::Scene raw = load(pour("remove_above = 4.0e-3\nremove_by = \"top\"\n"));
  const prepare::Settled settled = prepare::settle(raw, std::get<cases::SettleStageSpec>(raw.stages[0].action), 1);
  std::size_t reaching = 0;
  std::size_t centre_above = 0;
  for (const auto& p : settled.particles) {
    reaching += p.position[2] + p.radius > 4.0e-3 ? 1 : 0;
    centre_above += p.position[2] > 4.0e-3 ? 1 : 0;
  }
  ASSERT_GT(reaching, centre_above);  // the top's rule removes more than the centre's
  const cases::Scene s = prepare::prepare_scene(raw, {});
  ASSERT_EQ(s.particles.size(), raw.particles.size() - reaching);
  for (const auto& p : s.particles) EXPECT_LE(p.position[2] + p.radius, 4.0e-3);
  // The rule is part of the stage's inputs (the stage cache tells the two skims apart).
  const cases::Scene by_centre = load(pour("remove_above = 4.0e-3\n"));
  EXPECT_NE(prepare::stage_key(raw, 0, "test"), prepare::stage_key(by_centre, 0, "test"));
}

TEST(PlacedWalls, AreAbsentWhileTheBedSettlesAndStandInTheRun) {
  // A lid 3 mm up cuts through the grid and the settled bed: were it there, the pour would land on
  // it. The preparation with it is bit-identical to the preparation without it.
  const std::string skim = "remove_above = 2.9e-3\nremove_by = \"top\"\n";
  const cases::Scene with_lid = prepare::prepare_scene(load(pour(skim, lid(3.0e-3))), {});
  const cases::Scene without = prepare::prepare_scene(load(pour(skim)), {});
  EXPECT_TRUE(test_support::same_particles(with_lid, without));
  ASSERT_EQ(with_lid.walls.size(), without.walls.size() + 1);
  const cases::WallSpec& placed = with_lid.walls.back();
  EXPECT_EQ(placed.name, "lid");
  EXPECT_FALSE(placed.in_preparation);
  EXPECT_FALSE(placed.removed_at);
  EXPECT_TRUE(cases::core_wall(placed).present(0.0));  // the engines' run has it from its first step
}

TEST(PlacedWalls, APreparedBedReachingIntoOneIsAnErrorNamingTheWall) {
  // Skimmed by centres at 4 mm, the bed's top spheres reach 1 mm above a lid placed at 4 mm.
  const auto [key, what] = error_of(pour("remove_above = 4.0e-3\n", lid(4.0e-3)));
  EXPECT_EQ(key, "walls");
  EXPECT_NE(what.find("wall 'lid' (in_preparation = false)"), std::string::npos) << what;
  EXPECT_NE(what.find("remove_by = \"top\""), std::string::npos) << what;
  // Skimmed by tops, it clears the lid.
  EXPECT_NO_THROW(prepare::prepare_scene(load(pour("remove_above = 4.0e-3\nremove_by = \"top\"\n", lid(4.0e-3))), {}));
}

TEST(PlacedWalls, TheInitialOverlapCheckLeavesThemToTheBedThePreparationMakes) {
  // The lid at 3 mm cuts through the grid's second layer (centres at 3.2 mm).
  EXPECT_NO_THROW(load(pour("", lid(3.0e-3))));
  try {
    load(pour("", lid(3.0e-3, true)));
    ADD_FAILURE() << "expected an overlap error";
  } catch (const cases::CaseError& e) {
    EXPECT_NE(std::string(e.what()).find("overlaps wall 'lid'"), std::string::npos) << e.what();
  }
}

TEST(PlacedWalls, BadKeysAreLoadTimeErrorsNamingTheKey) {
  const auto expect_error = [](const std::string& text, const std::string& words) {
    try {
      load(text);
      ADD_FAILURE() << "expected an error with " << words;
    } catch (const cases::CaseError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  // Without preparation stages a placed wall would simply stand throughout.
  std::string no_stages = pour("", lid(0.03));
  no_stages.erase(no_stages.find("[[stages]]"));
  expect_error(no_stages, "in_preparation: false places the wall when the run starts");
  expect_error(pour("", lid(0.03) + "remove_at = 0.0\n"), "never stands");
  expect_error(pour("", lid(0.03, true) + "in_preparation = 1\n"), "in_preparation");
  expect_error(pour("remove_by = \"top\"\n"), "remove_by: needs remove_above");
  expect_error(pour("remove_above = 4.0e-3\nremove_by = \"middle\"\n"), "remove_by");
}

}  // namespace placed_walls_test
