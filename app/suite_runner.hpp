// SPDX-License-Identifier: MIT
#pragma once
// Running a suite as a function: `demwb suite` and `demwb gate` both call run_suite and work on
// what it returns (docs/architecture.md, "Results").

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "app/cli.hpp"
#include "compare/case_outcome.hpp"
#include "results/suite_results.hpp"
#include "sweeps/stored_ensembles.hpp"

namespace app {

/// One case of a suite: its outcome, or the reason it could not be loaded.
struct SuiteEntry {
  std::filesystem::path file;
  std::optional<comparison::CaseOutcome> outcome;
  std::string load_error;
  double seconds = 0.0;
};

/// What one suite run produced, after it wrote report.md, results.json and junit.xml to `out`.
struct SuiteRun {
  std::string suite;               ///< as named on the command line
  std::filesystem::path out;       ///< where the reports are
  cases::Tier tier = cases::Tier::fast;
  std::vector<SuiteEntry> entries;  ///< one per case file, in the suite's order
  std::vector<sweeps::StoredEnsemble> ensembles;
  comparison::Status worst = comparison::Status::not_applicable;
};

/// Runs every case of suite `suite_name` (canonical, or a directory) with the run, tier and jobs
/// options of `vm` (add_run_options, add_tier_option and "jobs"), writes its reports to `out` and
/// returns the typed outcome. Throws std::runtime_error when the suite holds no case.
SuiteRun run_suite(const std::string& suite_name, const std::filesystem::path& out,
                   const boost::program_options::variables_map& vm, const Invocation& inv);

/// The summary table of a suite run (markdown: one row per case), as report.md opens with it.
[[nodiscard]] std::string suite_summary(const SuiteRun& run);

/// The suite run's typed results, as the gate judges them.
[[nodiscard]] results::SuiteResults suite_results(const SuiteRun& run);

}  // namespace app
