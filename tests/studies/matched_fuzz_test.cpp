// SPDX-License-Identifier: MIT
// The random matched scenes: a seed gives one case file, always the same; every generated case
// is one the loader accepts (a refused one would be the generator's defect, not a finding); and
// over a few hundred seeds every sub-model of every slot is drawn.
#include "studies/matched_fuzz.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "cases/case_loader.hpp"
#include "dem/contact/registry.hpp"
#include "support/text_file.hpp"

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

/// Distance from `x` to the segment (a, b).
double segment_distance(const cases::Vector3& x, const cases::Vector3& a, const cases::Vector3& b) {
  double ee = 0.0, xe = 0.0;
  for (int k = 0; k < 3; ++k) {
    ee += (b[k] - a[k]) * (b[k] - a[k]);
    xe += (x[k] - a[k]) * (b[k] - a[k]);
  }
  const double t = std::clamp(xe / ee, 0.0, 1.0);
  double d = 0.0;
  for (int k = 0; k < 3; ++k) d += std::pow(x[k] - (a[k] + t * (b[k] - a[k])), 2);
  return std::sqrt(d);
}

TEST(MatchedFuzz, EveryGeneratedCaseLoadsAndEveryRowIsDrawn) {
  std::map<std::string, std::set<std::string>> drawn;  // slot → keywords
  std::map<std::string, int> meshes;                    // code → scenes with a mesh
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "demwb-matched-fuzz-test";
  std::filesystem::create_directories(dir);
  for (const char* code : {"lammps", "yade", "liggghts"}) {
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
      const studies::FuzzScene s = studies::random_matched_scene(code, seed);
      SCOPED_TRACE(s.name);
      for (const auto& [name, text] : s.files) support::write_file(dir / name, text);
      cases::Scene scene;
      ASSERT_NO_THROW(scene = cases::load_case_text(s.toml, (dir / (s.name + ".toml")).string())) << s.toml;
      EXPECT_EQ(static_cast<int>(scene.particles.size()), s.spheres);
      EXPECT_GE(s.spheres, 2);
      EXPECT_LE(s.spheres, 6);
      EXPECT_EQ(static_cast<int>(scene.walls.size()), s.walls + s.facets);
      EXPECT_EQ(scene.meshes.size(), s.facets > 0 ? 1U : 0U);
      if (s.facets > 0) {
        ++meshes[code];
        EXPECT_EQ(scene.meshes[0].facets, static_cast<std::size_t>(s.facets));
      }
      // The STL is the file the case names, and only a scene with a mesh has one.
      EXPECT_EQ(s.files.size(), s.facets > 0 ? 1U : 0U);
      if (s.facets > 0) {
        EXPECT_EQ(scene.meshes[0].file, s.files[0].first);
      }
      // YADE's folded meshes keep their shared edge clear of every sphere at the start.
      if (std::string(code) == "yade" && s.facets == 2) {
        const auto& corners = scene.walls.back().corners;  // the second facet: (c1, c0, c3)
        for (const auto& p : scene.particles) {
          EXPECT_GT(segment_distance(p.position, corners[0], corners[1]), p.radius + studies::kYadeMeshEdgeClearance);
        }
      }
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
  }  // About two scenes in five carry a mesh for the codes that have mesh walls, none for LAMMPS.
  EXPECT_EQ(meshes["lammps"], 0);
  EXPECT_GT(meshes["yade"], 90);
  EXPECT_GT(meshes["liggghts"], 90);
  std::filesystem::remove_all(dir);
}

}  // namespace
