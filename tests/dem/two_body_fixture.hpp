// SPDX-License-Identifier: MIT
#pragma once

#include <numbers>

#include "dem/simulation/simulation.hpp"

namespace test_support {

/// Thesis table 4.2 in core terms: sphere p (r = 0.01 m, ρ = 1000) moving at `speed` towards a
/// fixed sphere q (r = 0.1 m) whose surface is `gap` away, linear stiffness 1e5 N/m.
inline dem::SimulationSetup head_on_collision(dem::SchemeId scheme, double dt, double restitution,
                                              double speed = 4.0, double gap = 1e-4) {
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "sphere";
  m.density = 1000.0;
  m.normal_stiffness = 1e5;
  if (restitution < 1.0) m.restitution = restitution;
  s.materials = {m};
  s.model.damping = restitution < 1.0 ? "restitution" : "none";
  s.particles = {
      dem::ParticleInit{0.01, 0.01, 1000.0, 0, dem::Vec3(0, 0, 0), dem::Vec3(speed, 0, 0), dem::Vec3::Zero(), false},
      dem::ParticleInit{0.1, 0.1, 1000.0, 0, dem::Vec3(0.11 + gap, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), true}};
  s.scheme = scheme;
  s.scheme_settings.rotation = false;
  s.scheme_settings.length_scale = 0.01;
  s.timestep = dt;
  return s;
}

/// Mass of the moving sphere of head_on_collision.
inline double mover_mass() { return 4.0 / 3.0 * std::numbers::pi * 1000.0 * 1e-6; }

}  // namespace test_support
