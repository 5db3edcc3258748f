// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"

namespace store {

/// Reference-code results kept on disk, keyed by the scene's fingerprint, the engine and its
/// version (docs/architecture.md, "The store module"). Only successful runs are kept. A
/// stored file that cannot be read is treated as absent.
class ResultCache {
 public:
  /// A cache rooted at `dir` (created on first store).
  explicit ResultCache(std::filesystem::path dir) : dir_(std::move(dir)) {}
  /// $DEMWB_CACHE_DIR, else $XDG_CACHE_HOME/demwb, else ~/.cache/demwb, else ./.demwb-cache.
  static std::filesystem::path default_dir();

  /// The stored result of `engine` at `version` for `scene`, if any (source set to "cache").
  [[nodiscard]] std::optional<cases::RunResult> find(const cases::Scene& scene, std::string_view engine,
                                                     const std::string& version) const;
  /// Stores a successful result under `version` (the engine's version and its driver's revision;
  /// others are ignored). Throws on I/O failure.
  void store(const cases::Scene& scene, const cases::RunResult& run, const std::string& version) const;
  /// Where the result of `engine` at `version` for `scene` lives.
  [[nodiscard]] std::filesystem::path path_of(const cases::Scene& scene, std::string_view engine,
                                              const std::string& version) const;
  /// The cache directory.
  [[nodiscard]] const std::filesystem::path& dir() const noexcept { return dir_; }

 private:
  std::filesystem::path dir_;
};

/// A committed baseline of one case (cases/baselines/<case>.json): the reference engines'
/// results, so the gate can compare where a reference code is not installed, and the in-house
/// metrics, so the gate can report drift.
struct Baseline {
  std::string case_name;
  std::string fingerprint;                            ///< of the scene it was made from
  std::map<std::string, cases::RunResult> references; ///< engine → result
  std::map<std::string, double> inhouse_metrics;
};

/// Reads a baseline file; throws std::runtime_error naming the file on failure.
Baseline read_baseline(const std::filesystem::path& file);
/// Writes a baseline file.
void write_baseline(const std::filesystem::path& file, const Baseline& baseline);

}  // namespace store
