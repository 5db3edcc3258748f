// SPDX-License-Identifier: MIT
#pragma once
// The discharge metrics of one engine's run (docs/metrics.md, "Discharge"): the mobile mass that
// has passed the scene's compare.discharge outlet plane, followed over the run's snapshots.

#include <optional>
#include <span>
#include <string>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"
#include "compare/metrics_cohesion.hpp"
#include "support/line_fit.hpp"

namespace comparison {

/// The mass [kg] of the spheres (centres `centres`, masses `masses`) whose centres lie beyond
/// the outlet plane through `point` with outward unit normal `direction`.
[[nodiscard]] double mass_past(std::span<const cases::Vector3> centres, std::span<const double> masses,
                               const cases::Vector3& point, const cases::Vector3& direction) noexcept;

/// The least-squares line through the samples (t_k, m_k) whose m_k / total lies in [from, to]:
/// the steady mass flow rate of a discharge (slope, kg/s). Empty when fewer than `min_points`
/// samples lie in the window.
[[nodiscard]] std::optional<support::LineFit> fit_flow_rate(std::span<const double> times, std::span<const double> mass,
                                                   double total, double from, double to, std::size_t min_points);

/// The metric `name` (mass_flow_rate, discharged_fraction) of `run`; empty when `name` is not a
/// discharge metric. Missing, with the reason, when the scene has no compare.discharge, the run
/// no full snapshots, or too few snapshots fall in the fit window.
std::optional<CohesionMetric> discharge_metric(const std::string& name, const cases::Scene& scene,
                                               const cases::RunResult& run);

}  // namespace comparison
