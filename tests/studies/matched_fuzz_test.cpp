// SPDX-License-Identifier: MIT
// The random matched scenes: a seed gives one case file, always the same; every generated case
// is one the loader accepts (a refused one would be the generator's defect, not a finding); and
// over a few hundred seeds every sub-model of every slot is drawn.
#include "studies/matched_fuzz.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "cases/case_loader.hpp"
#include "dem/contact/registry.hpp"

namespace {

TEST(MatchedFuzz, ASeedAlwaysGivesTheSameScene) {
  for (const char* code : {"lammps", "yade", "liggghts"}) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      EXPECT_EQ(studies::random_matched_scene(code, seed).toml, studies::random_matched_scene(code, seed).toml);
      EXPECT_NE(studies::random_matched_scene(code, seed).toml, studies::random_matched_scene(code, seed + 1).toml);
    }
  }
  EXPECT_THROW((void)studies::random_matched_scene("lmp", 1), std::invalid_argument);
}

TEST(MatchedFuzz, MostSeedsRedrawUntilTheFilterAcceptsAndTheRestKeepTheirFirstDraft) {
  // A filter standing in for a code's mapping: only scenes with a linear normal model.
  const studies::ExpressibleFilter linear = [](const studies::FuzzScene& s) { return s.model.starts_with("linear/"); };
  int kept_first = 0;
  int filtered = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    const studies::FuzzScene s = studies::random_matched_scene("lammps", seed, linear);
    EXPECT_EQ(s.toml, studies::random_matched_scene("lammps", seed, linear).toml);  // deterministic
    EXPECT_EQ(s.name, "fuzz_lammps_" + std::to_string(seed));
    if (s.draws == 1) {
      EXPECT_EQ(s.toml, studies::random_matched_scene("lammps", seed).toml);
      ++kept_first;
    }
    if (linear(s)) ++filtered;
    if (s.draws > 1) {
      EXPECT_TRUE(linear(s));
      EXPECT_NE(s.toml.find(", draft " + std::to_string(s.draws)), std::string::npos);
    }
  }
  // About 80 % of the seeds must be accepted; the first draft is linear for about half of them.
  EXPECT_GT(filtered, 150);
  EXPECT_GT(kept_first, 60);
  EXPECT_LT(filtered, 200);  // the other seeds keep n/a scenes too
  // A filter that accepts nothing stops after kMaxDrafts drafts.
  const auto none = [](const studies::FuzzScene&) { return false; };
  int longest = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) longest = std::max(longest, studies::random_matched_scene("yade", seed, none).draws);
  EXPECT_EQ(longest, studies::kMaxDrafts);
}

TEST(MatchedFuzz, EveryGeneratedCaseLoadsAndEveryRowIsDrawn) {
  std::map<std::string, std::set<std::string>> drawn;  // slot → keywords
  for (const char* code : {"lammps", "yade", "liggghts"}) {
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
      const studies::FuzzScene s = studies::random_matched_scene(code, seed);
      SCOPED_TRACE(s.name);
      cases::Scene scene;
      ASSERT_NO_THROW(scene = cases::load_case_text(s.toml, s.name + ".toml")) << s.toml;
      EXPECT_EQ(static_cast<int>(scene.particles.size()), s.spheres);
      EXPECT_GE(s.spheres, 2);
      EXPECT_LE(s.spheres, 6);
      EXPECT_EQ(static_cast<int>(scene.walls.size()), s.walls);
      EXPECT_EQ(scene.compare.matched, std::vector<std::string>{code});
      drawn["normal"].insert(scene.model.normal);
      drawn["damping"].insert(scene.model.damping);
      drawn["tangential"].insert(scene.model.tangential);
      drawn["cohesion"].insert(scene.model.cohesion);
      drawn["rolling"].insert(scene.model.rolling);
    }
  }
  for (const dem::Slot slot : dem::all_slots()) {
    for (const dem::SubModelInfo& row : dem::sub_models(slot)) {
      EXPECT_TRUE(drawn[std::string(dem::to_string(slot))].contains(std::string(row.keyword)))
          << dem::to_string(slot) << " = " << row.keyword << " never drawn";
    }
  }
}

}  // namespace
