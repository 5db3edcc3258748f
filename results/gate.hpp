// SPDX-License-Identifier: MIT
#pragma once
// The gate's verdict on a suite's typed results (docs/user-guide.md, "The gate").

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "results/suite_results.hpp"

namespace results {

/// How strict the gate is.
struct GateOptions {
  bool allow_missing = false;  ///< comparisons with an engine that is not installed count as green
  /// Committed baselines (a directory of <case>.json, or one file) for the in-house drift check;
  /// empty: no drift check.
  std::optional<std::filesystem::path> baselines;
};

/// What the gate found: it passes when `failures` is empty.
struct GateFindings {
  std::vector<std::string> failures;
  std::vector<std::string> notes;
  std::size_t cases = 0;
  std::size_t comparisons = 0;
  std::map<std::string, std::size_t> by_status;  ///< comparison status → rows
  [[nodiscard]] bool passed() const noexcept { return failures.empty(); }
};

/// Judges `results`: every comparison must be pass or n/a (or missing, when allowed); a case that
/// did not load or run fails; a stored ensemble that no longer fits its sweep fails; an in-house
/// metric that moved beyond its tolerance from the committed baseline fails. Notes say which
/// results came from baselines and which cases have nothing to compare.
[[nodiscard]] GateFindings gate(const SuiteResults& results, const GateOptions& options);

/// The gate's closing line: "gate: N case(s), M comparison(s) (…) — PASS|FAIL".
[[nodiscard]] std::string gate_summary(const GateFindings& findings, const GateOptions& options);

}  // namespace results
