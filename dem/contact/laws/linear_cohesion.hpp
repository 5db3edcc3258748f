// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>

namespace dem::laws {

/// Linear cohesion, thesis eq 3.33 (appendix E eq E.5): F = −k_c max(δ̂, 0) while the effect
/// spheres overlap. cohesive stiffness k_c [N/m], effect overlap δ̂ [m]; returns the normal
/// force [N], attractive negative. Acts whether or not the bodies touch.
[[nodiscard]] constexpr double linear_cohesion_force(double cohesive_stiffness,
                                                     double effect_overlap) noexcept {
  return -cohesive_stiffness * std::max(effect_overlap, 0.0);
}

/// Potential of the linear cohesion, U = −½ k_c max(δ̂, 0)² [J] (zero once the effect spheres
/// separate), so that F = dU/dδ̂.
[[nodiscard]] constexpr double linear_cohesion_energy(double cohesive_stiffness,
                                                      double effect_overlap) noexcept {
  const double d = std::max(effect_overlap, 0.0);
  return -0.5 * cohesive_stiffness * d * d;
}

/// Overlap at which linear repulsion and linear cohesion balance, k_e δ = k_c (δ + Δ) with
/// Δ = δ̂ − δ = (r̂_p + r̂_q) − (r_p + r_q): δ_eq = k_c Δ / (k_e − k_c) [m]; needs k_e > k_c.
[[nodiscard]] constexpr double linear_cohesion_equilibrium_overlap(double normal_stiffness,
                                                                   double cohesive_stiffness,
                                                                   double effect_gap) noexcept {
  return cohesive_stiffness * effect_gap / (normal_stiffness - cohesive_stiffness);
}

}  // namespace dem::laws
