// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <string>
#include <vector>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"
#include "compare/discrepancy.hpp"
#include "compare/metrics.hpp"

namespace comparison {

/// A reference code the case does not list among its engines, with its driver's verdict on the
/// prepared scene (asked of the driver's mappings; the code does not run). Reports show it, so
/// that every case says what every reference code makes of it.
struct UnlistedCode {
  std::string engine;
  std::string reason;  ///< why the code cannot express the case (its driver's reasons, "; "-joined); empty: it can
};

/// Everything one comparison of one case produced: the scene, each engine's run, the metrics
/// computed from each run and the discrepancy rows (docs/architecture.md, "The flow of one
/// comparison", steps 1–4).
struct CaseOutcome {
  cases::Scene scene;
  std::vector<cases::RunResult> runs;
  std::map<std::string, MetricSet> metrics;  ///< engine name → metrics
  std::vector<Comparison> comparisons;
  std::vector<UnlistedCode> unlisted;  ///< reference codes not run, when the command asked (app::RunContext)
};

/// Worst status over the outcome's comparisons (pass when there are none).
Status worst_status(const CaseOutcome& outcome) noexcept;
/// The more severe of two statuses (n/a < pass < missing < fail < error).
Status worse(Status a, Status b) noexcept;

/// Computes metrics and comparisons for runs already made.
CaseOutcome evaluate_runs(cases::Scene scene, std::vector<cases::RunResult> runs);

}  // namespace comparison
