// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "cases/scene.hpp"

namespace prepare {

/// A pour settled by the core (thesis §6.3), before any sphere is removed.
struct Settled {
  std::vector<cases::ParticleSpec> particles;  ///< the scene's particles at rest, in scene order
  double time = 0.0;            ///< simulated time the settling took [s]
  std::uint64_t steps = 0;      ///< steps taken
  double timestep = 0.0;        ///< Δt used [s]
  double kinetic_energy = 0.0;  ///< kinetic energy of the mobile spheres at the end, spins included [J]
};

/// The scene `scene` is turned into for the settle run: every material's restitution replaced by
/// the stage's when it sets one, no fluid, no stages and no output; walls, gravity and the contact
/// model are the case's.
cases::Scene settle_scene(const cases::Scene& scene, const cases::SettleStageSpec& stage);

/// Settles the pour: runs settle_scene(scene, stage) in the core until at least
/// stage.min_duration has passed and the kinetic energy of the mobile spheres (translation and
/// spin) is below stage.kinetic_energy, checked after every step. Deterministic for any
/// `threads`. Throws std::runtime_error when they have not settled by stage.max_duration (the
/// message gives the energy reached) or the run blows up.
Settled settle(const cases::Scene& scene, const cases::SettleStageSpec& stage, int threads);

/// Removes every mobile sphere whose centre (its top, z + r, when `by_top`) lies above `height` (z)
/// from `scene`, keeping the
/// order of the others and each population's first index; returns how many it removed. Throws
/// cases::CaseError naming `key` when an index the case refers to (a traced particle or pair, the
/// compared subject, pair or wall contact) would lose its sphere or change meaning.
std::size_t remove_above(cases::Scene& scene, double height, bool by_top, const std::string& key);

}  // namespace prepare
