// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "cases/scene.hpp"

namespace prepare {

/// An agglomerate formed by the core (thesis §5.2.1).
struct Formation {
  std::vector<cases::ParticleSpec> particles;  ///< the scene's particles, formed, in scene order
  double time = 0.0;            ///< simulated time the formation took [s]
  std::uint64_t steps = 0;      ///< steps taken
  double timestep = 0.0;        ///< Δt used [s]
  double kinetic_energy = 0.0;  ///< kinetic energy relative to the rigid motion at the end [J]
  double drift_speed = 0.0;     ///< speed of the centre of mass at the end, taken out [m/s]
  double turn_rate = 0.0;       ///< angular speed of the agglomerate as a whole at the end, taken out [rad/s]
};

/// The scene `scene` is turned into for the formation run: every material's restitution
/// replaced by the stage's, no friction (tangential and rolling laws off) unless the stage keeps
/// it, the stage's gravity, no fluid, and no walls unless the stage keeps them.
cases::Scene formation_scene(const cases::Scene& scene, const cases::FormationStageSpec& stage);

/// Forms the agglomerate: runs formation_scene(scene, stage) in the core, every mobile sphere
/// pulled towards the centre of the mobile spheres' bounding box (dem::CentralPull, taper radius
/// the mean radius), until the pull has faded and the kinetic energy relative to the
/// agglomerate's rigid motion (drift and turn as a whole: an uneven grid feels a net pull) is
/// below stage.kinetic_energy; that rigid motion is then taken out of every mobile sphere's
/// velocity. Deterministic for any `threads`. Throws std::runtime_error when the
/// spheres have not settled by stage.max_duration (the message gives the energy reached).
Formation form_agglomerate(const cases::Scene& scene, const cases::FormationStageSpec& stage, int threads);

}  // namespace prepare
