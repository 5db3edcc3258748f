// SPDX-License-Identifier: MIT
#pragma once

#include "cases/scene.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/timestep/timestep_control.hpp"

namespace cases {

/// The core's time-step limits for the scene (dem::timestep_limits over its spheres, plane walls,
/// gravity and contact model `table`), exactly as the in-house engine computes them before a run
/// (reference/inhouse/scene_to_core.cpp). The limits read only extremes (per material the lightest
/// mobile sphere, the smallest radius, whether it has two mobile or one fixed sphere; the fastest
/// and the largest sphere), so they are computed from those few spheres: O(N) time, O(1) memory.
[[nodiscard]] dem::TimestepLimits scene_timestep_limits(const Scene& scene, const dem::PairTable& table);

/// The time step a run of the scene takes [s]: integration.timestep, or for "auto" the core's
/// automatic step (+∞ when no contact can occur: the run then stops with an error). `table` is
/// the scene's pair table.
[[nodiscard]] double run_timestep(const Scene& scene, const dem::PairTable& table);

/// As run_timestep, building the scene's pair table. Throws dem::ModelError when it cannot be
/// built (never for a scene the loader returned).
[[nodiscard]] double run_timestep(const Scene& scene);

/// The time step of the formation stage `stage` of the scene [s]: integration.timestep, or the
/// automatic step of the scene as the stage runs it (every material's restitution replaced by the
/// stage's, no friction unless it keeps it, its own gravity, walls only when it keeps them; see
/// prepare/formation.cpp). +∞ when no contact can occur.
[[nodiscard]] double formation_timestep(const Scene& scene, const FormationStageSpec& stage);

/// The simulated time of a run of the scene [s]: integration.duration, or, when a launch stage
/// sets it ("launch"), eq 5.1's t_max = 4 L_A / (u sin θ) with L_A taken from the mobile spheres
/// as listed, before any formation gathers them (an upper estimate: formation only brings them
/// closer).
[[nodiscard]] double run_duration(const Scene& scene);

}  // namespace cases
