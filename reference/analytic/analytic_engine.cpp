// SPDX-License-Identifier: MIT
#include "reference/analytic/analytic_engine.hpp"

#include <stdexcept>

#include "reference/analytic/collinear_solver.hpp"
#include "reference/analytic/solver.hpp"

namespace reference {

std::optional<std::string> AnalyticEngine::version() const { return "closed-form 1"; }

Support AnalyticEngine::supports(const cases::Scene& scene) const {
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
    auto reasons = solver->unsupported_reasons(scene);
    if (reasons.empty()) return {};
    support.reasons.insert(support.reasons.end(), reasons.begin(), reasons.end());
  }
  return support;
}

cases::RunResult AnalyticEngine::run(const cases::Scene& scene, const RunOptions&) const {
  if (const Support s = supports(scene); scene.domain.any_periodic() || !scene.output.trace_aggregates.empty()) {
    throw std::invalid_argument(s.reasons.front());
  }
  for (const auto& solver : analytic::all_solvers()) {
    if (!solver->unsupported_reasons(scene).empty()) continue;
    cases::RunResult result = solver->run(scene);
    result.conventions["solver"] = std::string(solver->name());
    return result;
  }
  throw std::invalid_argument("no analytic solver supports this scene");
}

std::vector<cases::Snapshot> exact_states(const cases::Scene& scene,
                                          const std::vector<double>& times) {
  const auto reasons = analytic::CollinearSolver().unsupported_reasons(scene);
  if (!reasons.empty()) {
    std::string joined;
    for (const auto& r : reasons) joined += (joined.empty() ? "" : "; ") + r;
    throw std::invalid_argument(joined);
  }
  return analytic::collinear_exact_states(scene, times);
}

}  // namespace reference
