// SPDX-License-Identifier: MIT
#pragma once
// The corpus of malformed case files (tests/data/bad_cases/): each file's first line says what
// the loader must report, "# expect: KEY | FRAGMENT".
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace bad_cases {

/// What a bad case file promises about its error.
struct Expectation {
  std::string key;
  std::string fragment;
};

/// Folder of the malformed case files.
inline std::filesystem::path directory() { return std::filesystem::path(DEMWB_TEST_DATA_DIR) / "bad_cases"; }

/// Every malformed case file, sorted by name.
inline std::vector<std::filesystem::path> files() {
  std::vector<std::filesystem::path> out;
  for (const auto& entry : std::filesystem::directory_iterator(directory())) {
    if (entry.path().extension() == ".toml") out.push_back(entry.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Parses "# expect: KEY | FRAGMENT" from the first line of `file` (empty when absent).
inline Expectation expectation(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  const std::string prefix = "# expect: ";
  const auto bar = line.find(" | ");
  if (line.rfind(prefix, 0) != 0 || bar == std::string::npos) return {};
  return {line.substr(prefix.size(), bar - prefix.size()), line.substr(bar + 3)};
}

}  // namespace bad_cases
