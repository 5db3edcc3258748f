// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>

#include "dem/core/vector.hpp"

namespace dem {

/// The centripetal pull that gathers loose spheres into an agglomerate (thesis §5.2.1, step iv):
/// every mobile sphere is accelerated towards `centre` with a magnitude that falls linearly from
/// `acceleration` at t = 0 to zero at t = `fade_time`, and is zero afterwards. The force is
/// m·a, so every sphere, light or heavy, drifts inwards at the same rate; a sphere within
/// `core_radius` of the centre feels a proportionally weaker pull (a = a(t)·|d|/core_radius), so
/// the field is continuous where the direction to the centre is not.
struct CentralPull {
  Vec3 centre = Vec3::Zero();  ///< point the spheres are pulled towards [m]
  double acceleration = 0.0;   ///< magnitude at t = 0 [m/s²], ≥ 0
  double fade_time = 0.0;      ///< time at which the pull has faded to zero [s], > 0
  double core_radius = 0.0;    ///< inside this distance the pull falls linearly to 0 [m], > 0

  /// Magnitude of the pull at time t, before the near-centre taper [m/s²].
  [[nodiscard]] double magnitude(double t) const noexcept {
    return acceleration * std::max(0.0, 1.0 - t / fade_time);
  }
  /// Acceleration of a sphere centred at x at time t [m/s²].
  [[nodiscard]] Vec3 at(const Vec3& x, double t) const noexcept {
    const double a = magnitude(t);
    if (a == 0.0) return Vec3::Zero();
    const Vec3 d = centre - x;
    const double distance = d.norm();
    return distance >= core_radius ? Vec3(a / distance * d) : Vec3(a / core_radius * d);
  }
};

}  // namespace dem
