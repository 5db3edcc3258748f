// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

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

  /// What a lookup found: a hit, nothing, or an entry that failed its checks (`problem` says
  /// how; the caller runs the engine again, which overwrites it).
  struct Lookup {
    std::optional<cases::RunResult> hit;  ///< source set to "cache"
    std::string problem;                  ///< non-empty when an entry exists but cannot be trusted
  };
  /// The stored result of `engine` at `version` for `scene`. An entry is used only when its
  /// SHA-256 matches its content, its key matches the scene and version, and its status is ok.
  [[nodiscard]] Lookup find(const cases::Scene& scene, std::string_view engine, const std::string& version) const;
  /// Stores a successful result under `version` (the engine's version and its driver's revision;
  /// others are ignored), with the SHA-256 of the entry, atomically. Throws on I/O failure.
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
  /// engine → SHA-256 of the input its driver fed it (reference::Engine::input_fingerprint):
  /// a result is stale once the driver would write another deck or script for the case.
  std::map<std::string, std::string> inputs;
  std::map<std::string, double> inhouse_metrics;
};

/// Reads a baseline file; throws std::runtime_error naming the file when it cannot be read or
/// fails its SHA-256 check (an edited or damaged baseline is never used).
Baseline read_baseline(const std::filesystem::path& file);
/// Writes a baseline file with the SHA-256 of its content (scratch directories left out).
void write_baseline(const std::filesystem::path& file, const Baseline& baseline);

/// `document` with a "sha256" member: the SHA-256 of the document's compact JSON text without
/// that member (docs/security.md, "Cache and baselines").
nlohmann::ordered_json with_checksum(nlohmann::ordered_json document);
/// Empty when `document`'s "sha256" member matches its content; otherwise what is wrong.
std::string checksum_problem(const nlohmann::ordered_json& document);

}  // namespace store
