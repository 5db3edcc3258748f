// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace cases {

/// Directory of a named suite ("canonical") or the path itself when it is a directory. Named
/// suites are looked up in $DEMWB_CASES_DIR, the source tree, <program dir>/../share/demwb/cases,
/// then the configured install prefix; throws
/// std::runtime_error listing where it looked.
std::filesystem::path resolve_suite(const std::string& name_or_dir);

/// Path of one case of a named suite, e.g. canonical_case("canonical", "sandwich").
std::filesystem::path suite_case(const std::string& suite, const std::string& case_name);

/// Every *.toml in a directory, sorted by name.
std::vector<std::filesystem::path> case_files(const std::filesystem::path& dir);

}  // namespace cases
