// SPDX-License-Identifier: MIT
#pragma once
// What a suite run produced, typed: one CaseResults per case, the stored cross-code ensembles,
// built either from the run itself (comparison::CaseOutcome) or read back from its results.json
// (docs/architecture.md, "Results"). The gate judges these, never untyped JSON.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "cases/run_result.hpp"
#include "cases/tier.hpp"
#include "compare/case_outcome.hpp"

namespace results {

/// One engine's run of a case, as far as the gate needs it.
struct EngineResults {
  std::string name;                 ///< "inhouse", "lammps", "inhouse@yade", …
  cases::RunStatus status = cases::RunStatus::error;
  std::string source = "run";       ///< "run", "cache" or "baseline"
  /// Every metric the case lists, in the case's order; empty when the engine has no value.
  std::vector<std::pair<std::string, std::optional<double>>> metrics;
};

/// One case of a suite: its comparison rows, engines and tolerances, or why it has none.
struct CaseResults {
  std::string name;                  ///< the case's name, or its file when it did not load
  std::optional<cases::Tier> tier;   ///< empty when the case did not load
  std::string failure;               ///< why the case produced no results (load or run error); else empty
  std::vector<comparison::Comparison> comparisons;
  std::vector<EngineResults> engines;  ///< in the order they ran
  /// The tolerance of every metric the case lists (the one-engine cases' baseline check uses it).
  std::vector<std::pair<std::string, cases::Tolerance>> tolerances;
};

/// A stored cross-code ensemble beside the suite (cases/baselines/sweeps).
struct EnsembleResults {
  std::string sweep;
  bool current = false;  ///< false: it no longer fits its sweep and case files
  std::string problem;   ///< why it is not current
};

/// A whole suite run.
struct SuiteResults {
  std::string suite;
  cases::Tier tier = cases::Tier::full;  ///< the tier the results were made in
  std::vector<CaseResults> cases;
  std::vector<EnsembleResults> ensembles;
};

/// The typed results of one case the suite ran.
[[nodiscard]] CaseResults case_results(const comparison::CaseOutcome& outcome);

/// A case that did not load or run: `file` and the reason.
[[nodiscard]] CaseResults failed_case(std::string file, std::string reason);

/// Reads the results.json a `demwb suite` (cases under "cases") or `demwb run` (one case)
/// wrote. Throws std::runtime_error naming `where` and the key when the document lacks a field
/// the gate needs or holds one of the wrong type.
[[nodiscard]] SuiteResults read_suite_results(const nlohmann::ordered_json& document, const std::string& where);

}  // namespace results
