// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"
#include "compare/metrics_breakup.hpp"
#include "compare/metrics_cohesion.hpp"

// The breakup metrics of one engine's run of a scene (docs/metrics.md, "Agglomerate breakup"):
// the formed agglomerate is the scene's mobile spheres at t = 0 (every engine starts from it),
// the final state the run's last snapshot.
namespace comparison {

/// The bond rule of the scene's contact model at the end of an impact: two mobile spheres are one
/// body while their centres are within the distance at which the pair's law still acts
/// (dem::interaction_range: body contact for a law without cohesion, r̂_i + r̂_j for linear
/// cohesion, the rupture distance for JKR). `mobile` lists the scene's mobile spheres.
[[nodiscard]] breakup::BondRule scene_bond_rule(const cases::Scene& scene, const std::vector<std::size_t>& mobile);

/// The cohesive work of the scene's pair law for two mobile spheres of the mean size (thesis
/// fig. 5.15): the work needed to separate them quasi-statically from their force-free contact
/// until cohesion ends (dem::conversion::linear_cohesive_work, jkr_cohesive_work; R* = r/2,
/// E* = E/(2(1 − ν²))). A property of the case, the same for every engine; empty with the reason
/// for other laws, several materials or pair overrides.
CohesionMetric cohesive_work(const cases::Scene& scene);

/// The metric `name` (cohesive_work, kappa_vol, kappa_damage, fragments, coordination_before,
/// coordination_after) of `run`, or empty when `name` is not a breakup metric.
std::optional<CohesionMetric> breakup_metric(const std::string& name, const cases::Scene& scene,
                                             const cases::RunResult& run);

}  // namespace comparison
