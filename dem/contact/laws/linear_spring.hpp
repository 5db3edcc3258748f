// SPDX-License-Identifier: MIT
#pragma once

namespace dem::laws {

/// Elastic part of the linear normal law, thesis eq 3.10: F = k_e δ.
/// stiffness k_e [N/m], overlap δ [m] (> 0 in contact); returns the repulsive force [N].
[[nodiscard]] constexpr double linear_spring_force(double stiffness, double overlap) noexcept {
  return stiffness * overlap;
}

/// Elastic energy stored in a linear spring, ½ k_e δ² [J].
[[nodiscard]] constexpr double linear_spring_energy(double stiffness, double overlap) noexcept {
  return 0.5 * stiffness * overlap * overlap;
}

}  // namespace dem::laws
