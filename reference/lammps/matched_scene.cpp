// SPDX-License-Identifier: MIT
#include "reference/lammps/matched_scene.hpp"

#include "reference/inhouse/scene_to_core.hpp"

namespace reference::lammps {

/// LAMMPS 29 Sep 2021: `fix nve/sphere` (or `fix nve` without rotation) is velocity Verlet.
cases::Scene matched_scene(const cases::Scene& scene) {
  cases::Scene matched = scene;
  matched.integration.timestep = core_setup(scene).simulation.timestep;
  matched.integration.scheme = dem::SchemeId::velocity_verlet;
  return matched;
}

}  // namespace reference::lammps
