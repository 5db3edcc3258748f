// SPDX-License-Identifier: MIT
#include "cases/case_library.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "support/build_info.hpp"

namespace cases {

std::filesystem::path resolve_suite(const std::string& name_or_dir) {
  const std::filesystem::path given(name_or_dir);
  if (std::filesystem::is_directory(given)) return given;
  std::vector<std::filesystem::path> roots;
  if (const char* env = std::getenv("DEMWB_CASES_DIR")) roots.emplace_back(env);
  roots.emplace_back(support::kSourceCasesDir);
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) roots.push_back(exe.parent_path().parent_path() / "share" / "demwb" / "cases");
  roots.emplace_back(support::kInstalledCasesDir);
  std::string looked;
  for (const auto& root : roots) {
    const auto dir = root / name_or_dir;
    if (std::filesystem::is_directory(dir)) return dir;
    looked += " " + dir.string();
  }
  throw std::runtime_error("no suite '" + name_or_dir + "': not a directory, and not found in" +
                           looked);
}

std::filesystem::path suite_case(const std::string& suite, const std::string& case_name) {
  const std::filesystem::path file = resolve_suite(suite) / (case_name + ".toml");
  if (!std::filesystem::is_regular_file(file)) {
    throw std::runtime_error("suite '" + suite + "' has no case " + file.string());
  }
  return file;
}

std::vector<std::filesystem::path> case_files(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".toml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace cases
