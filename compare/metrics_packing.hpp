// SPDX-License-Identifier: MIT
#pragma once
// The packing metrics of one engine's run (docs/metrics.md, "Packing"): measured on the run's last
// snapshot in the scene's compare.packing region, with one implementation for every engine.

#include <optional>
#include <string>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"
#include "compare/metrics_cohesion.hpp"

namespace comparison {

/// The metric `name` (packing_fraction, packing_fraction_interior, orf, dose_remaining,
/// coordination_number) of `run`
/// at its last snapshot (its first with compare.packing.at = "start"), counting the mobile spheres only; empty when `name` is not a packing
/// metric. A value is missing, with the reason, when the scene has no packing region or the run
/// no snapshot of every sphere.
std::optional<CohesionMetric> packing_metric(const std::string& name, const cases::Scene& scene,
                                             const cases::RunResult& run);

}  // namespace comparison
