// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <numbers>

#include "dem/core/vector.hpp"

namespace dem::laws {

/// Particle Reynolds number Re_p = ρ_f |u_f − u_p| d_p / η_f (thesis eq 3.47).
[[nodiscard]] inline double particle_reynolds(double fluid_density, double slip_speed,
                                              double diameter, double viscosity) noexcept {
  return fluid_density * slip_speed * diameter / viscosity;
}

/// Drag coefficient of a single sphere, the piecewise correlation of thesis eq 3.48 (Brenn et
/// al.): Stokes below Re 0.2, four Schiller–Naumann-type corrections up to Re 1000, Newton's
/// 0.44 to 2e5, 0.1 beyond (drag crisis). Re_p > 0.
[[nodiscard]] inline double brenn_drag_coefficient(double re) noexcept {
  if (re <= 0.2) return 24.0 / re;
  if (re <= 2.0) return 24.0 / re * (1.0 + 0.1 * std::pow(re, 0.99));
  if (re <= 21.0) return 24.0 / re * (1.0 + 0.11 * std::pow(re, 0.81));
  if (re <= 200.0) return 24.0 / re * (1.0 + 0.189 * std::pow(re, 0.632));
  if (re <= 1000.0) return 24.0 / re * (1.0 + 0.15 * std::pow(re, 0.687));
  if (re <= 2.0e5) return 0.44;
  return 0.1;
}

/// Drag force on a sphere, F = ½ ρ_f (u_f − u_p)|u_f − u_p| C_D π r² (thesis eq 3.45–3.46),
/// with C_D from eq 3.48. Zero when the slip velocity is zero.
[[nodiscard]] inline Vec3 sphere_drag(const Vec3& slip, double radius, double fluid_density,
                                      double viscosity) noexcept {
  const double speed = slip.norm();
  if (!(speed > 0.0)) return Vec3::Zero();
  const double re = particle_reynolds(fluid_density, speed, 2.0 * radius, viscosity);
  return 0.5 * fluid_density * speed * brenn_drag_coefficient(re) * std::numbers::pi * radius *
         radius * slip;
}

/// Pressure-gradient force on a sphere, F = −(4/3) π r³ ∇P (thesis eq 3.49).
[[nodiscard]] inline Vec3 pressure_gradient_force(const Vec3& gradient, double radius) noexcept {
  return -4.0 / 3.0 * std::numbers::pi * radius * radius * radius * gradient;
}

}  // namespace dem::laws
