// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
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

/// How far a chaotic scene can be compared at round-off: the relative drift of a run's
/// round-off twin (the same run started one ulp away) past which later trace rows are no longer
/// compared (docs/metrics.md, "Round-off horizon"). A hundredth of the matched tolerance 1e-8.
inline constexpr double kRoundoffDrift = 1e-10;

/// How a matched trace_deviation row's note begins when the round-off horizon cut it short.
inline constexpr std::string_view kRoundoffHorizonNote = "round-off horizon at";

/// A matched trace deviation and the rows it covers.
struct TraceDeviation {
  double value = 0.0;    ///< the deviation over the rows before the round-off horizon
  double whole = 0.0;    ///< the deviation over every row
  std::size_t rows = 0;  ///< rows in the traces
  std::size_t horizon = 0;  ///< first row not compared (= rows when the twin never drifted past kRoundoffDrift)
  double horizon_time = 0.0;  ///< time of that row [s] (when horizon < rows)
};

/// Largest difference between two engines' traced positions, over every traced particle and
/// row, divided by the compared contact's largest overlap in `reference` (docs/metrics.md,
/// "Matched-numerics metric": the position trace relative to the max overlap). When `run` carries
/// a round-off twin, only the rows before the twin drifts past kRoundoffDrift count (the
/// round-off horizon). Empty with `problem` set when the traces are not sampled at the same times
/// or have nothing to compare.
std::optional<TraceDeviation> trace_deviation(const cases::Scene& scene, const cases::RunResult& run,
                                              const cases::RunResult& reference, std::string& problem);

}  // namespace comparison
