// SPDX-License-Identifier: MIT
// The sweeps run outside CI store their results under cases/baselines/sweeps/<name>/ with a
// fingerprint (sweep.json). These checks fail when a sweep file or its case changed since its
// results were stored, when the stored sweep.csv is not the one fingerprinted, or when a
// committed sweep has no stored results: run `demwb refresh --sweep FILE` (scripts/refresh-sweeps.sh runs them all).
#include <filesystem>
#include <map>
#include <set>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cases/case_loader.hpp"
#include "support/sha256.hpp"
#include "support/text_file.hpp"
#include "sweeps/stored_ensembles.hpp"
#include "sweeps/sweep_spec.hpp"

namespace committed_sweeps_test {

namespace fs = std::filesystem;

const fs::path kSource = DEMWB_SOURCE_DIR;

TEST(CommittedSweeps, EverySweepHasResultsFingerprintedByItsCurrentFiles) {
  std::set<std::string> sweeps;
  for (const auto& e : fs::directory_iterator(kSource / "cases" / "sweeps")) {
    if (e.path().extension() == ".toml") sweeps.insert(e.path().stem().string());
  }
  ASSERT_FALSE(sweeps.empty());
  for (const auto& name : sweeps) {
    SCOPED_TRACE(name);
    const fs::path sweep_file = kSource / "cases" / "sweeps" / (name + ".toml");
    const fs::path stored = kSource / "cases" / "baselines" / "sweeps" / name;
    ASSERT_TRUE(fs::exists(stored / "sweep.json")) << "no stored results: run demwb refresh --sweep " << sweep_file;
    const auto j = nlohmann::json::parse(support::read_file(stored / "sweep.json"));
    const sweeps::SweepSpec spec = sweeps::load_sweep(sweep_file);
    EXPECT_EQ(j.at("sweep"), spec.name);
    EXPECT_EQ(j.at("sweep_sha256"), support::sha256_hex(support::read_file(sweep_file)))
        << "the sweep file changed since its results were stored: demwb refresh --sweep " << sweep_file;
    EXPECT_EQ(j.at("case_sha256"), support::sha256_hex(support::read_file(spec.case_file)))
        << spec.case_file << " changed since the sweep's results were stored: demwb refresh --sweep " << sweep_file;
    // The meshes the case reads, by their files' bytes (a sweep stored before meshes has none).
    const auto meshes = sweeps::mesh_sha256(cases::load_case(spec.case_file));
    const auto stored_meshes = j.contains("mesh_sha256") ? j.at("mesh_sha256").get<std::map<std::string, std::string>>()
                                                         : std::map<std::string, std::string>{};
    EXPECT_EQ(stored_meshes, meshes) << "a mesh file of " << spec.case_file
                                     << " changed since the sweep's results were stored: demwb refresh --sweep " << sweep_file;
    const std::string csv = support::read_file(stored / "sweep.csv");
    EXPECT_EQ(j.at("sweep_csv_sha256"), support::sha256_hex(csv)) << "sweep.csv is not the fingerprinted one";
    EXPECT_EQ(j.at("rows_not_ok"), 0) << "stored results with failed runs";
    std::size_t points = 1;
    for (const auto& a : spec.axes) points *= a.values.size();
    EXPECT_EQ(j.at("points"), points);
    std::size_t lines = 0;
    for (const char c : csv) lines += c == '\n' ? 1 : 0;
    EXPECT_EQ(lines, 1 + j.at("rows").get<std::size_t>());
    EXPECT_TRUE(fs::exists(stored / "report.md"));
    if (j.contains("bed_csv_sha256")) {
      ASSERT_TRUE(fs::exists(stored / "bed.csv")) << "the fingerprint names a bed.csv that is not stored";
      EXPECT_EQ(j.at("bed_csv_sha256"), support::sha256_hex(support::read_file(stored / "bed.csv")))
          << "bed.csv is not the fingerprinted one";
    }
  }
}

TEST(CommittedSweeps, EverySweepIsListedInTheSweepsGuide) {
  // docs/sweeps.md's table of committed sweeps is where a user finds what each one is for.
  const std::string guide = support::read_file(kSource / "docs" / "sweeps.md");
  for (const auto& e : fs::directory_iterator(kSource / "cases" / "sweeps")) {
    if (e.path().extension() != ".toml") continue;
    const std::string row = "| `cases/sweeps/" + e.path().filename().string() + "` |";
    EXPECT_NE(guide.find(row), std::string::npos) << "docs/sweeps.md has no row " << row;
  }
}

}  // namespace
