// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"
#include "compare/metrics.hpp"
#include "compare/status.hpp"

namespace comparison {

/// One row of a discrepancy table: an engine's metric against the reference engine's.
struct Comparison {
  std::string metric;
  std::string engine;
  std::string reference;
  std::optional<double> value;
  std::optional<double> reference_value;
  std::optional<double> abs_diff;
  std::optional<double> rel_diff;   ///< empty when the reference value is 0
  cases::Tolerance tolerance;
  Status status = Status::error;
  std::string note;                 ///< reason for error / missing / n/a
  /// A native reference-code row: the estimated discretisation error of `value` (its code's own
  /// time-stepping error, from halving Δt) and the Δt `value` was computed at.
  std::optional<double> error_estimate;
  std::optional<double> timestep;
};

/// Tolerance used when the case gives none for `metric` (documented in docs/metrics.md).
cases::Tolerance default_tolerance(std::string_view metric) noexcept;

/// Tolerance of `metric` in `scene` (the case's own, else the default).
cases::Tolerance tolerance_for(const cases::Scene& scene, const std::string& metric);

/// Tolerance of `metric` when the core run with a code's numerics is compared with that code
/// (the case's compare.matched_tolerances, else 1e-8: agreement to round-off is the claim).
cases::Tolerance matched_tolerance_for(const cases::Scene& scene, const std::string& metric);

/// pass when |value − reference| ≤ abs + rel·|reference|, else fail.
[[nodiscard]] Status judge(double value, double reference, const cases::Tolerance& tol) noexcept;

/// Every (metric, engine) comparison against the scene's reference engine, in the order of
/// scene.compare.metrics and `runs`. The reference engine is not compared with itself.
/// `metrics` maps engine name → its metric values. amplitude_error is compared with 0.
/// A matched run "inhouse@<code>" is also compared with <code> itself, metric by metric and on
/// `trace_deviation` (the position traces), at matched tolerances.
std::vector<Comparison> compare_runs(const cases::Scene& scene,
                                     const std::vector<cases::RunResult>& runs,
                                     const std::map<std::string, MetricSet>& metrics);

}  // namespace comparison
