// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"

namespace comparison {

/// Value of one metric for one engine, or why there is none (never NaN).
struct MetricValue {
  std::optional<double> value;
  std::string source;   ///< "trace" (computed here) or "closed form" (given by the engine)
  std::string problem;  ///< set when value is empty
  bool not_applicable = false;  ///< the engine cannot express this metric here (by design)
};

/// Metric name → value for one engine.
using MetricSet = std::map<std::string, MetricValue>;

/// Computes every metric the scene lists (scene.compare.metrics) from one engine's result,
/// with one implementation shared by all engines (docs/metrics.md). Closed-form values an
/// engine supplies in exact_metrics take precedence, then the values of a time-step refinement
/// (the run's metrics at the Δt its error estimate asked for). `analytic` (may be null) is the analytic
/// engine's result, needed by amplitude_error. A run that is not ok yields no values.
MetricSet compute_metrics(const cases::Scene& scene, const cases::RunResult& run,
                          const cases::RunResult* analytic);

/// Displacement of the subject along the collision axis at every trace row (the observable of
/// max_position and amplitude_error), or empty when the trace cannot give it.
std::optional<std::vector<double>> axis_displacement(const cases::Scene& scene,
                                                     const cases::Trace& trace);

/// Largest difference between two engines' traced positions, over every traced particle and
/// row, divided by the compared contact's largest overlap in `reference` (docs/metrics.md,
/// "Matched-numerics metric": the position trace relative to the max overlap). Empty with `problem`
/// set when the traces are not sampled at the same times or have nothing to compare.
std::optional<double> trace_deviation(const cases::Scene& scene, const cases::RunResult& run,
                                      const cases::RunResult& reference, std::string& problem);

}  // namespace comparison
