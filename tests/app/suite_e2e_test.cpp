// SPDX-License-Identifier: MIT
// End-to-end tests of `demwb suite`: reference results reused from the cache on a second run,
// byte-identical results.json, and a report that pandoc renders cleanly.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "demwb_process.hpp"
#include "support/process.hpp"
#include "support/text_file.hpp"

namespace suite_e2e_test {

using demwb_e2e::canonical;
using demwb_e2e::demwb;
using demwb_e2e::scratch;
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

/// True when `program` is found in PATH.
bool installed(const std::string& program) { return support::find_program(program).has_value(); }

/// A one-case suite: the canonical single collision on the in-house core, the closed form and
/// LAMMPS only (no matched runs), whatever engines the canonical file lists.
fs::path lammps_suite() {
  const std::string kept =
      demwb_e2e::canonical_text_unmatched("single_collision", R"(["inhouse", "analytic", "lammps"])");
  const fs::path dir = scratch("suite_cached_cases");
  support::write_file(dir / "single_collision.toml", kept);
  return dir;
}

TEST(DemwbSuite, ASecondRunReusesCachedReferenceResultsAndWritesIdenticalResults) {
  if (!installed("lmp")) GTEST_SKIP() << "lmp is not installed (scripts/setup.sh installs it)";
  const fs::path suite = lammps_suite();
  const fs::path cache = scratch("suite_cache");
  std::vector<fs::path> outs;
  for (const char* name : {"suite_first", "suite_second", "suite_third"}) {
    outs.push_back(scratch(name));
    const auto r = demwb({"suite", suite.string(), "-o", outs.back().string(), "--cache", cache.string(),
                          "--reproducible"});
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  }
  const Json first = Json::parse(support::read_file(outs[0] / "results.json"));
  const Json second = Json::parse(support::read_file(outs[1] / "results.json"));
  EXPECT_EQ(first["cases"][0]["engines"]["lammps"]["source"], "run");
  EXPECT_EQ(second["cases"][0]["engines"]["lammps"]["source"], "cache");
  // The in-house engine's entry is byte for byte the same, and so is every comparison row.
  EXPECT_EQ(first["cases"][0]["engines"]["inhouse"].dump(2), second["cases"][0]["engines"]["inhouse"].dump(2));
  EXPECT_EQ(first["cases"][0]["comparisons"].dump(2), second["cases"][0]["comparisons"].dump(2));
  // Once LAMMPS comes from the cache, the whole file is identical.
  EXPECT_EQ(support::read_file(outs[1] / "results.json"), support::read_file(outs[2] / "results.json"));
  EXPECT_EQ(support::read_file(outs[1] / "single_collision" / "trace_inhouse.csv"),
            support::read_file(outs[2] / "single_collision" / "trace_inhouse.csv"));
  // The report says where the LAMMPS result came from and how long the original run took.
  const std::string report = support::read_file(outs[1] / "report.md");
  EXPECT_NE(report.find("| lammps | ok |"), std::string::npos) << report;
  EXPECT_NE(report.find("cached"), std::string::npos) << report;
  EXPECT_NE(report.find("(ran in "), std::string::npos) << report;
}

TEST(DemwbSuite, WithoutReproducibleEveryEngineEntryRecordsItsWallTime) {
  const fs::path out = scratch("suite_wall_times");
  const auto r = demwb({"run", canonical("sandwich"), "-o", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const Json j = Json::parse(support::read_file(out / "results.json"));
  for (const auto& [engine, e] : j["engines"].items()) {
    EXPECT_TRUE(e.contains("wall_time_s")) << engine;
  }
  const fs::path quiet = scratch("suite_no_wall_times");
  ASSERT_EQ(demwb({"run", canonical("sandwich"), "-o", quiet.string(), "--reproducible"}).exit_code, 0);
  const Json k = Json::parse(support::read_file(quiet / "results.json"));
  for (const auto& [engine, e] : k["engines"].items()) {
    EXPECT_FALSE(e.contains("wall_time_s")) << engine;
  }
}

}  // namespace
