// SPDX-License-Identifier: MIT
#include "reference/matching.hpp"

#include <stdexcept>
#include <string>

#include "reference/inhouse/scene_to_core.hpp"

namespace reference {
namespace {

/// LAMMPS 29 Sep 2021: `fix nve/sphere` (or `fix nve` without rotation) is velocity Verlet.
cases::Scene matched_to_lammps(const cases::Scene& scene) {
  cases::Scene matched = scene;
  matched.integration.timestep = core_setup(scene).simulation.timestep;
  matched.integration.scheme = dem::SchemeId::velocity_verlet;
  return matched;
}

/// YADE 2023.02a: NewtonIntegrator is leapfrog with half-step velocities, and the velocity a
/// script gives is taken as v(−Δt/2). The YADE driver leaves the velocities of such a scene
/// unchanged, so both engines start from the same v(−Δt/2).
cases::Scene matched_to_yade(const cases::Scene& scene) {
  cases::Scene matched = scene;
  matched.integration.timestep = core_setup(scene).simulation.timestep;
  matched.integration.scheme = dem::SchemeId::leapfrog;
  matched.integration.leapfrog_start = dem::LeapfrogStart::given_is_half_step;
  return matched;
}

}  // namespace

cases::Scene matched_scene(const cases::Scene& scene, std::string_view engine) {
  if (engine == "lammps") return matched_to_lammps(scene);
  if (engine == "yade") return matched_to_yade(scene);
  throw std::invalid_argument("no matched-numerics variant for engine '" + std::string(engine) +
                              "' (known: lammps, yade)");
}

}  // namespace reference
