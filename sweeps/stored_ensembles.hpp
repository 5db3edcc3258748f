// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "cases/scene.hpp"

namespace sweeps {

/// A committed sweep run on two or more engines: a cross-code ensemble comparison whose results
/// are stored under cases/baselines/sweeps/<name>/ (run outside CI, docs/sweeps.md).
struct StoredEnsemble {
  std::string name;                  ///< the sweep's name
  std::string description;           ///< its description
  std::filesystem::path sweep_file;  ///< cases/sweeps/<name>.toml
  std::filesystem::path stored_dir;  ///< cases/baselines/sweeps/<name>/
  std::vector<std::string> engines;  ///< as the sweep names them
  bool current = false;              ///< the stored fingerprint matches the sweep and case files
  std::string problem;               ///< why it is not current (stale, missing, unreadable)
  std::string comparison_table;      ///< the stored report's engines-compared table (markdown)
  std::size_t beyond_two = 0;        ///< cells of that table above 2 combined standard errors
};

/// The SHA-256 of every mesh file a case reads, by the file as the case names it: stored with a
/// sweep's results (sweep.json `mesh_sha256`) so that an edited STL makes them stale.
[[nodiscard]] std::map<std::string, std::string> mesh_sha256(const cases::Scene& scene);

/// The stored cross-code ensembles of a suite: every sweep file in `sweeps_dir` naming two or
/// more engines, with its results in `stored_root`/<name>/. A sweep file that does not load, or
/// results that are missing or no longer fingerprinted by the current sweep and case files,
/// give an entry with `problem` set (never an exception).
std::vector<StoredEnsemble> stored_ensembles(const std::filesystem::path& sweeps_dir,
                                             const std::filesystem::path& stored_root);

/// The suite report's section on them: per ensemble the difference of the engines' means in
/// combined standard errors, per metric and point, and whether the results are current. `ran_now`:
/// the results are this run's (full tier), not the committed ones. Empty when there are none.
/// Links are written relative to `report_dir`.
std::string stored_ensembles_section(const std::vector<StoredEnsemble>& ensembles,
                                     const std::filesystem::path& report_dir, bool ran_now = false);

}  // namespace sweeps
