// SPDX-License-Identifier: MIT
#pragma once

#include <numbers>

namespace dem::laws {

/// Vacuum permittivity ε_0 [F/m] (CODATA 2018).
inline constexpr double kVacuumPermittivity = 8.8541878128e-12;

/// Coulomb force between two point charges, thesis eq 3.36 with repulsion positive:
/// F = q_p q_q / (4π ε_r ε_0 |x_pq|²) [N]; charge product q_p q_q [C²], relative permittivity
/// ε_r [-], centre distance |x_pq| > 0 [m]. Like charges repel (F > 0). Eq 3.36 as printed
/// carries a minus sign for the thesis' attraction-positive convention.
[[nodiscard]] constexpr double coulomb_force(double charge_product, double relative_permittivity,
                                             double distance) noexcept {
  return charge_product / (4.0 * std::numbers::pi * relative_permittivity * kVacuumPermittivity *
                           distance * distance);
}

/// Coulomb energy shifted to vanish at the cut-off r_c [J]:
/// U = q_p q_q/(4π ε_r ε_0) (1/|x_pq| − 1/r_c), so the energy is continuous where the force is
/// cut off (the force jump there does no work).
[[nodiscard]] constexpr double coulomb_energy(double charge_product, double relative_permittivity,
                                              double distance, double cutoff) noexcept {
  return charge_product / (4.0 * std::numbers::pi * relative_permittivity * kVacuumPermittivity) *
         (1.0 / distance - 1.0 / cutoff);
}

}  // namespace dem::laws
