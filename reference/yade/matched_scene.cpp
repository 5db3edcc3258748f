// SPDX-License-Identifier: MIT
#include "reference/yade/matched_scene.hpp"

#include "reference/inhouse/scene_to_core.hpp"

namespace reference::yade {

/// YADE 2023.02a: NewtonIntegrator is leapfrog with half-step velocities, and the velocity a
/// script gives is taken as v(−Δt/2). The YADE driver leaves the velocities of such a scene
/// unchanged, so both engines start from the same v(−Δt/2).
cases::Scene matched_scene(const cases::Scene& scene) {
  cases::Scene matched = scene;
  matched.integration.timestep = core_setup(scene).simulation.timestep;
  matched.integration.scheme = dem::SchemeId::leapfrog;
  matched.integration.leapfrog_start = dem::LeapfrogStart::given_is_half_step;
  return matched;
}

}  // namespace reference::yade
