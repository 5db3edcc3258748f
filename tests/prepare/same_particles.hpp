// SPDX-License-Identifier: MIT
#pragma once
// The comparison of prepared scenes the preparation tests share.
#include "cases/scene.hpp"

namespace test_support {

/// True when two scenes have the same particles at bit-identical positions, velocities and spins.
inline bool same_particles(const cases::Scene& a, const cases::Scene& b) {
  if (a.particles.size() != b.particles.size()) return false;
  for (std::size_t i = 0; i < a.particles.size(); ++i) {
    if (a.particles[i].position != b.particles[i].position || a.particles[i].velocity != b.particles[i].velocity ||
        a.particles[i].angular_velocity != b.particles[i].angular_velocity) {
      return false;
    }
  }
  return true;
}

}  // namespace test_support
