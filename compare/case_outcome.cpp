// SPDX-License-Identifier: MIT
#include "compare/case_outcome.hpp"

namespace comparison {
namespace {

/// Severity order used to find the worst status. `n/a` ranks below `pass`: a case whose rows
/// pass except those an engine cannot express is a passing case; only a case with nothing but
/// n/a rows is n/a.
int severity(Status s) noexcept {
  switch (s) {
    case Status::not_applicable: return 0;
    case Status::pass: return 1;
    case Status::missing: return 2;
    case Status::fail: return 3;
    case Status::error: return 4;
  }
  return 4;
}

}  // namespace

Status worse(Status a, Status b) noexcept { return severity(b) > severity(a) ? b : a; }

Status worst_status(const CaseOutcome& outcome) noexcept {
  if (outcome.comparisons.empty()) return Status::pass;
  Status worst = Status::not_applicable;
  for (const auto& c : outcome.comparisons) worst = worse(worst, c.status);
  return worst;
}

CaseOutcome evaluate_runs(cases::Scene scene, std::vector<cases::RunResult> runs) {
  CaseOutcome out;
  out.scene = std::move(scene);
  out.runs = std::move(runs);
  const cases::RunResult* analytic = nullptr;
  for (const auto& r : out.runs) {
    if (r.engine == "analytic") analytic = &r;
  }
  for (const auto& r : out.runs) out.metrics[r.engine] = compute_metrics(out.scene, r, analytic);
  out.comparisons = compare_runs(out.scene, out.runs, out.metrics);
  return out;
}

}  // namespace comparison
