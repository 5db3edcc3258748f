// SPDX-License-Identifier: MIT
#pragma once

#include <functional>

#include "cases/run_result.hpp"
#include "cases/scene.hpp"

// A reference code's own discretisation error, measured by halving its time step (docs/metrics.md,
// "Reference discretisation error").
namespace comparison {

/// How far a native reference run is refined.
struct RefinementPolicy {
  int max_halvings = 6;                ///< the finest run is at Δt/2^6 = Δt/64
  double fraction_of_tolerance = 0.1;  ///< an estimate above this share of the tolerance refines
};

/// `scene` with its time step divided by 2^halvings (an automatic step through
/// steps_per_collision), output.trace_every multiplied by 2^halvings and the duration set to the
/// case's whole number of steps, so that the refined run is sampled at the same instants (the
/// same trace rows and snapshots) and ends where the case's run ends.
[[nodiscard]] cases::Scene halved_time_step(const cases::Scene& scene, int halvings);

/// Runs one engine on a scene (the caller's runner: cache, scratch directories, timeouts).
using SceneRunner = std::function<cases::RunResult(const cases::Scene&)>;

/// Checks the time step of `base`, an ok native run of `scene` by a reference code: runs the
/// code at Δt/2, Δt/4, … (`run`), computes the case's metrics at each level (`analytic` may be
/// null; it serves amplitude_error) and keeps the first level k whose every metric m_k has the
/// estimate 2 |m_k − m_{k+1}| within policy.fraction_of_tolerance of the metric's tolerance
/// (rel·|m_k| + abs). At the limit it keeps the finest level with an estimate, marked
/// limit_reached. A failed refined run stops the refinement with `problem` set; metrics that
/// have no value at two consecutive levels get no estimate.
[[nodiscard]] cases::TimeStepRefinement refine_time_step(const cases::Scene& scene, const cases::RunResult& base,
                                                         const SceneRunner& run, const cases::RunResult* analytic,
                                                         const RefinementPolicy& policy = {});

}  // namespace comparison
