// SPDX-License-Identifier: MIT
// `demwb fuzz-matched`: what it writes for a few scenes against the real LAMMPS, and its usage
// errors. Whether the scenes agree is the study's finding (docs/engines.md), not asserted here;
// that every scene is accounted for, and every scene that neither agrees nor is n/a is kept as a
// replayable case file, is.
#include <filesystem>
#include <set>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "demwb_process.hpp"
#include "support/text_file.hpp"

namespace fuzz_matched_e2e_test {

using demwb_e2e::demwb;
using demwb_e2e::scratch;
namespace fs = std::filesystem;

TEST(DemwbFuzzMatched, AccountsForEveryScene) {
  const fs::path out = scratch("fuzz_matched");
  const auto r = demwb({"fuzz-matched", "--code", "lammps", "--count", "4", "--seed", "1", "-j", "2", "-o", out.string()});
  const auto j = nlohmann::json::parse(support::read_file(out / "fuzz.json"));
  ASSERT_EQ(j["scenes"].size(), 4U) << r.out << r.err;
  const std::set<std::string> known{"agree", "disagree", "n/a", "error", "missing", "invalid"};
  bool clean = true;
  for (const auto& scene : j["scenes"]) {
    const std::string status = scene["status"];
    EXPECT_TRUE(known.contains(status)) << status;
    EXPECT_NE(status, "invalid") << scene["reason"];  // the generator writes only loadable cases
    const fs::path kept = out / "failing" / (scene["name"].get<std::string>() + ".toml");
    const bool judged = status == "agree" || status == "n/a";
    EXPECT_EQ(fs::exists(kept), !judged) << scene["name"];
    EXPECT_TRUE(fs::exists(out / "cases" / (scene["name"].get<std::string>() + ".toml")));
    if (status == "n/a") {
      EXPECT_FALSE(scene["reason"].get<std::string>().empty());
    }
    if (status == "agree") {
      EXPECT_LE(scene["trace_deviation"].get<double>(), 1e-8);
    }
    clean = clean && judged;
  }
  EXPECT_EQ(r.exit_code, clean ? 0 : 1) << r.out << r.err;
  EXPECT_NE(support::read_file(out / "report.md").find("| status | scenes |"), std::string::npos);
}

TEST(DemwbFuzzMatched, AnUnknownCodeIsAUsageError) {
  const auto r = demwb({"fuzz-matched", "--code", "gromacs"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("gromacs"), std::string::npos) << r.err;
}

}  // namespace fuzz_matched_e2e_test
