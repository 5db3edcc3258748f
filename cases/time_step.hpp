// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "cases/scene.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/timestep/timestep_control.hpp"

namespace cases {

/// What the core's time-step control reads from a scene's spheres: per material the census
/// (dem::MaterialCensus) and the expected impact speed under `gravity`, with the core's arithmetic
/// (masses as dem::build_particles makes them, speeds as Eigen norms), so that limits computed from
/// it equal the in-house engine's bit for bit. O(N) time, O(materials) memory.
struct SphereCensus {
  std::vector<dem::MaterialCensus> materials;
  double impact_speed = 0.0;  ///< dem::expected_impact_speed of the spheres [m/s]
};

/// The census of `particles` of `materials` under `gravity`.
[[nodiscard]] SphereCensus sphere_census(const std::vector<ParticleSpec>& particles,
                                         const std::vector<dem::MaterialProperties>& materials, const Vector3& gravity);

/// The plane walls' materials, in wall order, as the time-step control takes them.
[[nodiscard]] std::vector<std::uint32_t> wall_materials(const std::vector<WallSpec>& walls);

/// The core's time-step limits for the scene (dem::timestep_limits over its spheres, plane walls,
/// gravity and contact model `table`), exactly as the in-house engine computes them before a run
/// (reference/common/core_setup.cpp).
[[nodiscard]] dem::TimestepLimits scene_timestep_limits(const Scene& scene, const dem::PairTable& table);

/// The time step a run of the scene takes [s]: integration.timestep, or for "auto" the core's
/// automatic step (+∞ when no contact can occur: the run then stops with an error). `table` is
/// the scene's pair table.
[[nodiscard]] double run_timestep(const Scene& scene, const dem::PairTable& table);

/// As run_timestep, building the scene's pair table. Throws dem::ModelError when it cannot be
/// built (never for a scene the loader returned).
[[nodiscard]] double run_timestep(const Scene& scene);

/// The time step of the formation stage `stage` of the scene [s]: integration.timestep, or the
/// automatic step of the scene as the stage runs it (formation_materials, formation_model, its own
/// gravity, walls only when it keeps them; see prepare/formation.cpp). +∞ when no contact can occur.
[[nodiscard]] double formation_timestep(const Scene& scene, const FormationStageSpec& stage);
/// Δt of a settle stage's run: the case's, or the automatic one with the stage's materials.
[[nodiscard]] double settle_timestep(const Scene& scene, const SettleStageSpec& stage);

/// The simulated time of a run of the scene [s]: integration.duration, or, when a launch stage
/// sets it ("launch"), eq 5.1's t_max = 4 L_A / (u sin θ) with L_A taken from the mobile spheres
/// as listed, before any formation gathers them (an upper estimate: formation only brings them
/// closer).
[[nodiscard]] double run_duration(const Scene& scene);

/// Steps of a run of `duration` at `dt`: ⌈duration / Δt⌉ with a 1e-12 relative allowance for
/// round-off, at least one; a ratio that is not a finite count saturates (NaN: one step).
[[nodiscard]] std::uint64_t step_count(double duration, double dt) noexcept;

/// The step at which each requested snapshot time is taken, the one rule every engine follows
/// (docs/case-format.md, [output]): the first step n in [0, steps] with n·Δt ≥ t − Δt/2, for the
/// times in ascending order (repeats kept). A time whose step would lie past the last one, or
/// that is not a number, gets none.
[[nodiscard]] std::vector<std::uint64_t> snapshot_steps(std::vector<double> times, double dt, std::uint64_t steps);

}  // namespace cases
