// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "cases/scene.hpp"

namespace cases {

/// A case file that cannot be used. what() reads "FILE:LINE:COL: KEY: problem" (line and
/// column when known), so a user can jump to the spot.
class CaseError : public std::runtime_error {
 public:
  CaseError(std::string file, std::string key, std::string problem, int line = 0,
            int column = 0);
  [[nodiscard]] const std::string& file() const noexcept { return file_; }
  [[nodiscard]] const std::string& key() const noexcept { return key_; }
  [[nodiscard]] const std::string& problem() const noexcept { return problem_; }

 private:
  std::string file_;
  std::string key_;
  std::string problem_;
};

/// Loads and validates the case file at `path` into an explicit Scene. Throws CaseError on
/// the first problem (syntax, unknown key, missing key, wrong type, unphysical value,
/// inconsistent references). Non-fatal findings go to Scene::warnings.
Scene load_case(const std::filesystem::path& path);

/// As load_case, from text already in memory; `path` names it in messages.
Scene load_case_text(std::string_view text, const std::string& path);

}  // namespace cases
