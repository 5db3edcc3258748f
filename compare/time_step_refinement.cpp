// SPDX-License-Identifier: MIT
#include "compare/time_step_refinement.hpp"

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cases/time_step.hpp"
#include "compare/discrepancy.hpp"
#include "compare/metrics.hpp"

namespace comparison {
namespace {

/// The metrics of one run that have values (metric → value); the runs here carry no refinement.
std::map<std::string, double> values_of(const cases::Scene& scene, const cases::RunResult& run,
                                        const cases::RunResult* analytic) {
  std::map<std::string, double> out;
  for (const auto& [name, v] : compute_metrics(scene, run, analytic)) {
    if (v.value) out[name] = *v.value;
  }
  return out;
}

/// Richardson estimates of level k from levels k and k + 1: 2 |m_k − m_{k+1}| (order p = 1
/// assumed: |m_k − m_{k+1}| = (1 − 2^{−p}) |e_k| ≥ |e_k|/2 for every p ≥ 1).
std::map<std::string, double> estimates_of(const std::map<std::string, double>& coarse,
                                           const std::map<std::string, double>& fine) {
  std::map<std::string, double> out;
  for (const auto& [name, value] : coarse) {
    if (const auto f = fine.find(name); f != fine.end()) out[name] = 2.0 * std::abs(value - f->second);
  }
  return out;
}

/// True when every estimate is within `fraction` of its metric's tolerance at its value.
bool small_enough(const cases::Scene& scene, const std::map<std::string, double>& values,
                  const std::map<std::string, double>& estimates, double fraction) {
  for (const auto& [name, estimate] : estimates) {
    const cases::Tolerance tol = tolerance_for(scene, name);
    const double allowed = fraction * (tol.abs + tol.rel * std::abs(values.at(name)));
    if (!(estimate <= allowed)) return false;
  }
  return true;
}

}  // namespace

cases::Scene halved_time_step(const cases::Scene& scene, int halvings) {
  cases::Scene s = scene;
  const double factor = std::ldexp(1.0, halvings);
  // The duration becomes the case's whole number of steps times its Δt, so that the refined run
  // makes exactly 2^halvings times as many steps and ends on the case's last sample.
  const double dt = cases::run_timestep(scene);
  s.integration.duration = static_cast<double>(cases::step_count(scene.integration.duration, dt)) * dt;
  // An automatic step is t_c / steps_per_collision: halve it by doubling the steps.
  if (scene.integration.timestep) {
    s.integration.timestep = *scene.integration.timestep / factor;
  } else {
    s.integration.steps_per_collision = scene.integration.steps_per_collision * factor;
  }
  s.output.trace_every = scene.output.trace_every * (std::uint64_t{1} << halvings);
  return s;
}

cases::TimeStepRefinement refine_time_step(const cases::Scene& scene, const cases::RunResult& base,
                                           const SceneRunner& run, const cases::RunResult* analytic,
                                           const RefinementPolicy& policy) {
  cases::TimeStepRefinement out;
  out.limit = policy.max_halvings;
  const double dt = cases::run_timestep(scene);
  out.timestep = dt;
  std::map<std::string, double> level = values_of(scene, base, analytic);
  out.metrics = level;
  for (int k = 0; k < policy.max_halvings; ++k) {
    const cases::Scene finer = halved_time_step(scene, k + 1);
    const cases::RunResult r = run(finer);
    if (r.status != cases::RunStatus::ok) {
      out.problem = fmt::format("the run at Δt/{} ended {}: {}", 1 << (k + 1), cases::to_string(r.status), r.reason);
      return out;
    }
    const std::map<std::string, double> next = values_of(finer, r, analytic);
    out.halvings = k;
    out.timestep = std::ldexp(dt, -k);  // exactly what halved_time_step(scene, k) runs
    out.metrics = level;
    out.estimates = estimates_of(level, next);
    if (small_enough(scene, level, out.estimates, policy.fraction_of_tolerance)) return out;
    level = next;
  }
  out.limit_reached = true;
  return out;
}

}  // namespace comparison
