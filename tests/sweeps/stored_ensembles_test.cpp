// SPDX-License-Identifier: MIT
// The suite report's stored cross-code ensembles: found from the committed sweeps, checked
// against their fingerprints, and flagged (never dropped) when stale, missing or unreadable.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/sha256.hpp"
#include "support/text_file.hpp"
#include "sweeps/stored_ensembles.hpp"
#include "sweeps/sweep_spec.hpp"

namespace stored_ensembles_test {

namespace fs = std::filesystem;

const fs::path kSource = DEMWB_SOURCE_DIR;

TEST(StoredEnsembles, TheCommittedCrossCodeSweepsAreFoundCurrentAndWithinTwoStandardErrors) {
  const auto found = sweeps::stored_ensembles(kSource / "cases/sweeps", kSource / "cases/baselines/sweeps");
  std::size_t lammps = 0, yade = 0, three_codes = 0;
  for (const auto& e : found) {
    SCOPED_TRACE(e.name);
    EXPECT_GE(e.engines.size(), 2u);
    EXPECT_TRUE(e.current) << e.problem;
    EXPECT_EQ(e.beyond_two, 0u);
    // A header, the separator and one row per point and engine compared with the first.
    const sweeps::SweepSpec spec = sweeps::load_sweep(e.sweep_file);
    std::size_t points = 1;
    for (const auto& axis : spec.axes) points *= axis.values.size();
    std::size_t lines = 0;
    for (const char c : e.comparison_table) lines += c == '\n' ? 1 : 0;
    EXPECT_EQ(lines, 2u + points * (e.engines.size() - 1));
    lammps += e.name == "agglomerate_jkr_vs_lammps" ? 1 : 0;
    yade += e.name == "agglomerate_linear_vs_yade" ? 1 : 0;
    three_codes += e.name == "packing_box_vs_codes" && e.engines.size() == 3 ? 1 : 0;
  }
  EXPECT_EQ(lammps, 1u);
  EXPECT_EQ(yade, 1u);
  EXPECT_EQ(three_codes, 1u);
  const std::string md = sweeps::stored_ensembles_section(found, kSource / "out");
  EXPECT_NE(md.find("## Cross-code ensembles (stored)"), std::string::npos);
  EXPECT_NE(md.find("Store: current."), std::string::npos);
}

/// A scratch copy of one committed sweep (its file, case and stored results) to tamper with.
struct Scratch {
  fs::path root = fs::temp_directory_path() / ("demwb_stored_ensembles_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                               "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::path sweeps = root / "sweeps";
  fs::path stored = root / "stored";
  fs::path case_file = root / "case.toml";

  Scratch() {
    fs::remove_all(root);
    fs::create_directories(sweeps);
    fs::create_directories(stored);
    fs::copy_file(kSource / "cases/ensembles/agglomerate_linear_yade.toml", case_file);
    std::string sweep = support::read_file(kSource / "cases/sweeps/agglomerate_linear_vs_yade.toml");
    const std::string from = "case = \"../ensembles/agglomerate_linear_yade.toml\"";
    sweep.replace(sweep.find(from), from.size(), "case = \"" + case_file.string() + "\"");
    write(sweeps / "agglomerate_linear_vs_yade.toml", sweep);
    fs::copy(kSource / "cases/baselines/sweeps/agglomerate_linear_vs_yade", stored / "agglomerate_linear_vs_yade",
             fs::copy_options::recursive);
    // Fingerprint the scratch files as the refresh script would have.
    const fs::path json_file = stored / "agglomerate_linear_vs_yade/sweep.json";
    auto j = nlohmann::json::parse(support::read_file(json_file));
    j["sweep_sha256"] = support::sha256_hex(sweep);
    j["case_sha256"] = support::sha256_hex(support::read_file(case_file));
    write(json_file, j.dump(2));
  }
  ~Scratch() { fs::remove_all(root); }
  static void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }
};

TEST(StoredEnsembles, AChangedCaseMakesTheStoreStaleWithTheCommandThatRenewsIt) {
  Scratch s;
  ASSERT_TRUE(sweeps::stored_ensembles(s.sweeps, s.stored).at(0).current);
  Scratch::write(s.case_file, support::read_file(s.case_file) + "\n# changed\n");
  const auto found = sweeps::stored_ensembles(s.sweeps, s.stored);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_FALSE(found[0].current);
  EXPECT_NE(found[0].problem.find("stale"), std::string::npos) << found[0].problem;
  EXPECT_NE(found[0].problem.find("demwb refresh --sweep"), std::string::npos);
  EXPECT_NE(sweeps::stored_ensembles_section(found, s.root).find("Store: **stale"), std::string::npos);
}

TEST(StoredEnsembles, ATamperedCsvMissingResultsAndABrokenSweepFileAreReported) {
  Scratch s;
  Scratch::write(s.stored / "agglomerate_linear_vs_yade/sweep.csv", "point,seed\n");
  EXPECT_NE(sweeps::stored_ensembles(s.sweeps, s.stored).at(0).problem.find("sweep.csv"), std::string::npos);
  fs::remove_all(s.stored / "agglomerate_linear_vs_yade");
  EXPECT_NE(sweeps::stored_ensembles(s.sweeps, s.stored).at(0).problem.find("no stored results"), std::string::npos);
  Scratch::write(s.sweeps / "agglomerate_linear_vs_yade.toml", "[sweep]\nname = \n");
  const auto found = sweeps::stored_ensembles(s.sweeps, s.stored);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NE(found[0].problem.find("cannot be read"), std::string::npos) << found[0].problem;
}

}  // namespace
