// SPDX-License-Identifier: MIT
// Every file in tests/data/bad_cases/ is a malformed case whose first line says what the loader
// must report: "# expect: KEY | FRAGMENT".
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../bad_case_files.hpp"
#include "cases/case_loader.hpp"

namespace bad_cases_test {

namespace fs = std::filesystem;

using bad_cases::Expectation;

/// Every malformed case file, sorted by name.
std::vector<fs::path> bad_case_files() { return bad_cases::files(); }

/// Parameterised over the malformed case files.
class BadCase : public ::testing::TestWithParam<fs::path> {};

TEST_P(BadCase, IsRejectedNamingFileKeyAndProblem) {
  const fs::path file = GetParam();
  const Expectation expected = bad_cases::expectation(file);
  ASSERT_FALSE(expected.key.empty()) << file << " lacks a '# expect: KEY | FRAGMENT' first line";
  ASSERT_FALSE(expected.fragment.empty()) << file << " has an empty expected fragment";
  try {
    static_cast<void>(cases::load_case(file));
    FAIL() << file << " loaded without error";
  } catch (const cases::CaseError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind(file.string() + ":", 0), 0u) << what;
    EXPECT_EQ(e.file(), file.string());
    EXPECT_EQ(e.key(), expected.key) << what;
    EXPECT_NE(what.find(": " + expected.key + ": "), std::string::npos) << what;
    EXPECT_NE(what.find(expected.fragment), std::string::npos) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(CaseLoader, BadCase, ::testing::ValuesIn(bad_case_files()),
                         [](const ::testing::TestParamInfo<fs::path>& param) {
                           return param.param.stem().string();
                         });

TEST(CaseLoader, BadCaseLibraryHasAtLeastThirtyFiles) { EXPECT_GE(bad_case_files().size(), 30u); }

TEST(CaseLoader, EveryBadCaseErrorPointsAtALineAndColumn) {
  for (const fs::path& file : bad_case_files()) {
    try {
      static_cast<void>(cases::load_case(file));
    } catch (const cases::CaseError& e) {
      const std::string rest = std::string(e.what()).substr(file.string().size());
      EXPECT_TRUE(rest.size() > 1 && rest[0] == ':' &&
                  std::isdigit(static_cast<unsigned char>(rest[1])))
          << e.what();
    }
  }
}

}  // namespace
