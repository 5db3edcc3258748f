// SPDX-License-Identifier: MIT
#include "reference/analytic/analytic_engine.hpp"

#include <stdexcept>

#include "reference/analytic/collinear_solver.hpp"
#include "reference/analytic/solver.hpp"

namespace reference {

std::optional<std::string> AnalyticEngine::version() const { return "closed-form 1"; }

Support AnalyticEngine::supports(const PreparedScene& prepared) const {
  const cases::Scene& scene = prepared.scene();
  Support support;
  if (scene.domain.any_periodic()) {
    support.reasons.emplace_back(
        "analytic: the closed-form solutions are for bodies in open space; a periodic box is not one");
    return support;
  }
  if (!scene.output.trace_aggregates.empty()) {
    support.reasons.emplace_back(
        "analytic: the solvers trace particles and contacts, not whole-scene aggregates "
        "(output.trace_aggregates)");
    return support;
  }
  for (const auto& solver : analytic::all_solvers()) {
    auto reasons = solver->unsupported_reasons(prepared);
    if (reasons.empty()) return {};
    support.reasons.insert(support.reasons.end(), reasons.begin(), reasons.end());
  }
  return support;
}

cases::RunResult AnalyticEngine::run(const PreparedScene& prepared, const RunOptions&) const {
  const cases::Scene& scene = prepared.scene();
  if (const Support s = supports(prepared); scene.domain.any_periodic() || !scene.output.trace_aggregates.empty()) {
    throw std::invalid_argument(s.reasons.front());
  }
  for (const auto& solver : analytic::all_solvers()) {
    if (!solver->unsupported_reasons(prepared).empty()) continue;
    cases::RunResult result = solver->run(prepared);
    result.conventions["solver"] = std::string(solver->name());
    return result;
  }
  throw std::invalid_argument("no analytic solver supports this scene");
}

std::vector<cases::Snapshot> exact_states(const PreparedScene& prepared,
                                          const std::vector<double>& times) {
  const auto reasons = analytic::CollinearSolver().unsupported_reasons(prepared);
  if (!reasons.empty()) {
    std::string joined;
    for (const auto& r : reasons) joined += (joined.empty() ? "" : "; ") + r;
    throw std::invalid_argument(joined);
  }
  return analytic::collinear_exact_states(prepared, times);
}

}  // namespace reference
