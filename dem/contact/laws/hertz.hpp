// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>

namespace dem::laws {

// Elastic Hertz contact of two spheres (thesis eq 3.12–3.13; docs/physics-normal.md). Inputs:
// reduced modulus E* = [(1−ν_p²)/E_p + (1−ν_q²)/E_q]⁻¹ [Pa], reduced radius R* [m] (r against a
// plane wall), body overlap δ [m]. Valid for small strains, δ ≪ R*, frictionless elastic spheres;
// every function returns 0 for δ ≤ 0 (no contact).

/// Hertz repulsion F = 4/3 E* √R* δ^{3/2} [N], repulsive positive (eq 3.12).
[[nodiscard]] inline double hertz_force(double effective_modulus, double reduced_radius,
                                        double overlap) noexcept {
  if (overlap <= 0.0) return 0.0;
  return 4.0 / 3.0 * effective_modulus * std::sqrt(reduced_radius) * overlap * std::sqrt(overlap);
}

/// Tangent stiffness dF/dδ = 2 E* √(R* δ) = 2 E* a [N/m], a the contact radius.
[[nodiscard]] inline double hertz_stiffness(double effective_modulus, double reduced_radius,
                                            double overlap) noexcept {
  if (overlap <= 0.0) return 0.0;
  return 2.0 * effective_modulus * std::sqrt(reduced_radius * overlap);
}

/// Secant stiffness F/δ = 4/3 E* a [N/m] of a Hertz contact of contact radius a [m] (a = √(R*δ));
/// LAMMPS' `knfac`, which its tsuji dashpot reads (under JKR with the JKR radius).
[[nodiscard]] inline double hertz_secant_stiffness_at_radius(double effective_modulus, double contact_radius) noexcept {
  return 4.0 / 3.0 * effective_modulus * contact_radius;
}

/// Elastic energy ∫F dδ = 8/15 E* √R* δ^{5/2} [J].
[[nodiscard]] inline double hertz_energy(double effective_modulus, double reduced_radius,
                                         double overlap) noexcept {
  if (overlap <= 0.0) return 0.0;
  return 8.0 / 15.0 * effective_modulus * std::sqrt(reduced_radius) * overlap * overlap *
         std::sqrt(overlap);
}

/// Largest overlap of an elastic head-on impact at normal speed v [m/s] with reduced mass m*
/// [kg]: kinetic energy ½ m* v² = hertz_energy(δ_max), δ_max = (15 m* v² / (16 E* √R*))^{2/5} [m].
[[nodiscard]] inline double hertz_max_overlap(double reduced_mass, double effective_modulus,
                                              double reduced_radius, double speed) noexcept {
  return std::pow(15.0 * reduced_mass * speed * speed /
                      (16.0 * effective_modulus * std::sqrt(reduced_radius)),
                  0.4);
}

/// Dimensionless duration of an elastic Hertz impact, C = t_c v / δ_max. From the energy
/// integral t_c = 2 ∫₀^δmax dδ / (v √(1 − (δ/δ_max)^{5/2})) with w = (δ/δ_max)^{5/2}:
/// C = (4/5) B(2/5, 1/2) = (4/5) Γ(2/5) Γ(1/2) / Γ(9/10) = 2.943275184…; equivalently
/// t_c = 3.218065… (m*/k_n)^{2/5} v^{−1/5} with k_n = 4/3 E* √R*, or
/// t_c = 2.868266… (m*² / (R* E*² v))^{1/5} (the "2.868" of the literature).
[[nodiscard]] inline double hertz_duration_constant() noexcept {
  return 0.8 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
}

/// Contact duration of an elastic head-on Hertz impact at normal speed v [s]:
/// t_c = C δ_max / v (see hertz_duration_constant). Independent of any damping.
[[nodiscard]] inline double hertz_contact_duration(double reduced_mass, double effective_modulus,
                                                   double reduced_radius, double speed) noexcept {
  return hertz_duration_constant() *
         hertz_max_overlap(reduced_mass, effective_modulus, reduced_radius, speed) / speed;
}

}  // namespace dem::laws
