// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "cases/scene.hpp"
#include "dem/simulation/simulation.hpp"

namespace prepare {

/// `scene` as a preparation stage runs it in the core: no fluid, no stages of its own, no output
/// (the stage reads the simulation's state, not a trace), every wall standing (remove_at counts in
/// the run's time) except those placed when the run starts (in_preparation = false).
cases::Scene stage_run_scene(cases::Scene scene);

/// When a preparation run counts as settled: not before `first_step`, at the first step whose
/// energy is below `threshold`, failing at `max_steps`.
struct SettleCriterion {
  std::uint64_t first_step = 0;  ///< no check before this step
  std::uint64_t max_steps = 0;   ///< the run fails when not settled by then
  double threshold = 0.0;        ///< settled below this energy [J]
  double max_duration = 0.0;     ///< max_steps as a time, for the message [s]
  bool count_spin = true;        ///< the energy counts spin: the message ranks spheres the same way
};

/// Kinetic energy of one sphere (index `i` in the simulation's order) [J]: translation ½ m u² and
/// spin ½ I ω².
struct SphereKineticEnergy {
  double translation = 0.0;
  double spin = 0.0;
};
[[nodiscard]] SphereKineticEnergy sphere_kinetic_energy(const dem::Simulation& sim, Eigen::Index i) noexcept;

/// Steps `sim` until `energy(sim)` (checked after every step from `criterion.first_step`) falls
/// below the threshold; returns that energy. Throws std::runtime_error, naming `run` ("formation",
/// "settle"), when the energy is not finite (the run blew up) or the threshold is not reached by
/// `criterion.max_steps`.
double run_until_settled(dem::Simulation& sim, const SettleCriterion& criterion,
                         const std::function<double(const dem::Simulation&)>& energy, std::string_view run);

/// `particles` (the scene's, in scene order) with the positions, velocities and spins `sim` has
/// reached.
std::vector<cases::ParticleSpec> particles_at(const dem::Simulation& sim, std::vector<cases::ParticleSpec> particles);

}  // namespace prepare
