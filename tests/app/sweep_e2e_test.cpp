// SPDX-License-Identifier: MIT
// End to end: `demwb sweep` over a small agglomerate, 2 points × 2 seeds, run with -j 2 and -j 1.
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "../small_agglomerate.hpp"
#include "demwb_process.hpp"
#include "support/sha256.hpp"
#include "support/text_file.hpp"

namespace sweep_e2e_test {

using demwb_e2e::demwb;
using demwb_e2e::scratch;
namespace fs = std::filesystem;

std::vector<std::vector<std::string>> csv_rows(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream cells(line);
    while (std::getline(cells, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    rows.push_back(fields);
  }
  return rows;
}

TEST(DemwbSweep, TwoPointsTwoSeedsWriteOneRowEachIdenticallyForAnyJobCount) {
  const fs::path dir = scratch("sweep_files");
  support::write_file(dir / "small.toml", test_support::small_agglomerate(8, 1));
  support::write_file(dir / "tiny.toml", R"(
[sweep]
name = "tiny"
case = "small.toml"
seeds = [5, 6]
metrics = ["kappa_vol", "kappa_damage", "fragments", "cohesive_work"]
[[parameters]]
key = "materials.m.cohesive_stiffness"
label = "k_c"
values = [30.0, 300.0]
scale = "log"
)");
  const fs::path cache = scratch("sweep_cache");
  const fs::path two = scratch("sweep_two");
  const fs::path one = scratch("sweep_one");
  const auto r2 = demwb({"sweep", (dir / "tiny.toml").string(), "-j", "2", "-o", two.string(), "--cache", cache.string()});
  ASSERT_EQ(r2.exit_code, 0) << r2.out << r2.err;
  EXPECT_NE(r2.err.find("[4/4]"), std::string::npos) << r2.err;
  const auto r1 = demwb({"sweep", (dir / "tiny.toml").string(), "-j", "1", "-o", one.string(), "--no-cache"});
  ASSERT_EQ(r1.exit_code, 0) << r1.out << r1.err;
  const std::string csv = support::read_file(two / "sweep.csv");
  EXPECT_EQ(csv, support::read_file(one / "sweep.csv"));  // cached or fresh, 1 or 2 jobs
  const auto rows = csv_rows(csv);
  ASSERT_EQ(rows.size(), 5U) << csv;
  EXPECT_EQ(rows[0], (std::vector<std::string>{"point", "materials.m.cohesive_stiffness", "seed", "engine", "status",
                                               "kappa_vol", "kappa_damage", "fragments", "cohesive_work", "reason"}));
  const std::vector<std::pair<std::string, std::string>> order{{"0", "5"}, {"0", "6"}, {"1", "5"}, {"1", "6"}};
  for (std::size_t k = 1; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), 10U) << csv;
    EXPECT_EQ(rows[k][0], order[k - 1].first);
    EXPECT_EQ(rows[k][2], order[k - 1].second);
    EXPECT_EQ(rows[k][3], "inhouse");
    EXPECT_EQ(rows[k][4], "ok");
    const double kappa = std::stod(rows[k][5]);
    EXPECT_GT(kappa, 0.0);
    EXPECT_LE(kappa, 1.0);
    // Cohesive work ½ k_c k_e Δ²/(k_e − k_c) grows tenfold with k_c (Δ = 2(r̂ − r), mean radius).
    EXPECT_GT(std::stod(rows[k][8]), 0.0);
  }
  EXPECT_NEAR(std::stod(rows[3][8]) / std::stod(rows[1][8]), 10.0 * (1e5 - 30.0) / (1e5 - 300.0), 1e-6);
  // The two seeds form different agglomerates, so their rows differ.
  EXPECT_NE(rows[1], rows[2]);
  const std::string report = support::read_file(two / "report.md");
  EXPECT_NE(report.find("(n = 2)"), std::string::npos) << report;
  EXPECT_NE(report.find("(plots/kappa_vol_vs_cohesive_stiffness.png)"), std::string::npos) << report;
  EXPECT_TRUE(fs::exists(two / "plots" / "kappa_damage_vs_cohesive_work.png"));
  // The fingerprint names the exact inputs and output.
  const auto fingerprint = nlohmann::json::parse(support::read_file(two / "sweep.json"));
  EXPECT_EQ(fingerprint.at("case_sha256"), support::sha256_hex(support::read_file(dir / "small.toml")));
  EXPECT_EQ(fingerprint.at("sweep_sha256"), support::sha256_hex(support::read_file(dir / "tiny.toml")));
  EXPECT_EQ(fingerprint.at("sweep_csv_sha256"), support::sha256_hex(csv));
  EXPECT_EQ(fingerprint.at("rows"), 4);
  EXPECT_NE(fingerprint.at("engines").at("inhouse").get<std::string>().find("dem-workbench"), std::string::npos);
}

TEST(DemwbSweep, AMissingKeyIsAnErrorRowNeverADroppedOne) {
  const fs::path dir = scratch("sweep_bad_key");
  support::write_file(dir / "small.toml", test_support::small_agglomerate(8, 1));
  support::write_file(dir / "bad.toml", R"(
[sweep]
name = "bad"
case = "small.toml"
seeds = [1]
[[parameters]]
key = "materials.m.cohesive_stifness"
values = [30.0]
)");
  const fs::path out = scratch("sweep_bad_out");
  const auto r = demwb({"sweep", (dir / "bad.toml").string(), "-o", out.string(), "--no-cache"});
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto rows = csv_rows(support::read_file(out / "sweep.csv"));
  ASSERT_EQ(rows.size(), 2U);
  EXPECT_EQ(rows[1][4], "error");
  EXPECT_NE(support::read_file(out / "sweep.csv").find("the case has no 'materials.m.cohesive_stifness' to sweep"),
            std::string::npos);
}

}  // namespace
