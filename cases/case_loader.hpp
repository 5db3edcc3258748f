// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
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

/// Limits of one load beyond those fixed in cases/limits.hpp (docs/case-format.md, "Limits").
struct LoadOptions {
  /// Most bytes of output a run of the case may hold in memory (estimate_output_bytes); empty:
  /// the machine's physical memory (physical_memory_bytes).
  std::optional<std::uint64_t> max_output_bytes;
};

/// Loads and validates the case file at `path` into an explicit Scene. The file is untrusted: it
/// must be a regular file of at most kMaxCaseFileBytes (read_case_file). Throws CaseError on the
/// first problem (unreadable or oversized file, syntax, unknown key, missing key, wrong type,
/// unphysical value, inconsistent references, a derived quantity out of range, a run too long or
/// whose output would not fit `options.max_output_bytes`). Non-fatal findings go to
/// Scene::warnings.
Scene load_case(const std::filesystem::path& path, const LoadOptions& options = {});

/// As load_case, from text already in memory (at most kMaxCaseFileBytes); `path` names it in
/// messages.
Scene load_case_text(std::string_view text, const std::string& path, const LoadOptions& options = {});

}  // namespace cases
