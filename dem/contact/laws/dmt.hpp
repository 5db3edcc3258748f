// SPDX-License-Identifier: MIT
#pragma once

#include <numbers>

namespace dem::laws {

/// Adhesive part of the DMT contact (Derjaguin, Muller & Toporov 1975; docs/physics-cohesion.md):
/// F = F_Hertz − 4πγR* while δ ≥ 0; returns −4πγR* [N] (attractive), γ per surface [J/m²],
/// R* [m]. The force jumps from 0 to −4πγR* at δ = 0 (the simple DMT form of LAMMPS `dmt` and
/// YADE's Hertz–Mindlin `gamma`: no attraction outside contact).
[[nodiscard]] constexpr double dmt_adhesion_force(double surface_energy,
                                                  double reduced_radius) noexcept {
  return -4.0 * std::numbers::pi * surface_energy * reduced_radius;
}

/// Energy of the DMT adhesion at overlap δ ≥ 0: U = −4πγR* δ [J] (continuous at δ = 0).
[[nodiscard]] constexpr double dmt_adhesion_energy(double surface_energy, double reduced_radius,
                                                   double overlap) noexcept {
  return dmt_adhesion_force(surface_energy, reduced_radius) * overlap;
}

/// DMT pull-off force 4πγR* = 2πΓR* [N] (> 0), the tension just before the contact opens.
[[nodiscard]] constexpr double dmt_pulloff_force(double surface_energy,
                                                 double reduced_radius) noexcept {
  return 4.0 * std::numbers::pi * surface_energy * reduced_radius;
}

}  // namespace dem::laws
