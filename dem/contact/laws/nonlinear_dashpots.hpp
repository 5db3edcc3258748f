// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace dem::laws {

// Normal dashpots whose coefficient η [kg/s] depends on the contact; the dashpot force is
// −η (u_c·n) (repulsive while approaching), as for the linear dashpot (laws/linear_dashpot.hpp).

/// Secant stiffness F_el/δ [N/m] of a normal law in contact (elastic force F_el [N], overlap
/// δ [m]). Where it is undefined (δ ≤ 0 or F_el ≤ 0, e.g. the time-step estimate, which passes
/// only a stiffness) the tangent stiffness [N/m] stands in for it.
[[nodiscard]] constexpr double secant_stiffness(double elastic_force, double overlap,
                                                double tangent_stiffness) noexcept {
  return overlap > 0.0 && elastic_force > 0.0 ? elastic_force / overlap : tangent_stiffness;
}

/// Tsuji's Hertz dashpot η = α √(m* k_n) δ^{1/4} [kg/s] (Tsuji, Tanaka & Ishida 1992), written
/// with the secant stiffness F_el/δ of the normal law: for Hertz F_el/δ = k_n δ^{1/2},
/// k_n = 4/3 E* √R*, so η = α √(m* F_el/δ). This is also how LAMMPS `damping tsuji` evaluates it
/// (`sqrt(meff*knfac)`, knfac = 4/3 E* a for hertz/material, k for hooke). α [-], m* [kg],
/// secant stiffness [N/m] ≥ 0.
[[nodiscard]] inline double tsuji_damping_coefficient(double factor, double reduced_mass,
                                                      double secant_stiffness) noexcept {
  return factor * std::sqrt(reduced_mass * std::max(secant_stiffness, 0.0));
}

/// Tsuji's polynomial fit α(e) of LAMMPS `damping tsuji` (pair_granular.cpp, 2021):
/// α = 1.2728 − 4.2783e + 11.087e² − 22.348e³ + 27.467e⁴ − 18.022e⁵ + 4.8218e⁶. It is *not*
/// restitution-exact: with Hertz and no clamp it gives e = 0.6161 for a nominal e = 0.5
/// (measured with LAMMPS 29 Sep 2021: 0.616090 at 1 m/s). e ∈ [0, 1].
[[nodiscard]] constexpr double lammps_tsuji_factor(double e) noexcept {
  constexpr std::array<double, 7> c{1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218};
  double sum = 0.0;
  for (auto it = c.rbegin(); it != c.rend(); ++it) sum = sum * e + *it;
  return sum;
}

/// Kuwabara–Kono / Brilliantov viscoelastic dashpot η = 2 E' √(R* δ) = 2 E' a [kg/s] (thesis
/// eq 3.14: F = −2 E' √(R* δ) u_n). E' [Pa·s] is a dissipative (viscous) modulus, R* [m],
/// δ [m]. With Hertz the restitution depends on the impact speed: 1 − e ∝ v^{1/5} for small E'.
[[nodiscard]] inline double kuwabara_kono_damping_coefficient(double viscous_modulus,
                                                              double reduced_radius,
                                                              double overlap) noexcept {
  return overlap > 0.0 ? 2.0 * viscous_modulus * std::sqrt(reduced_radius * overlap) : 0.0;
}

/// LAMMPS `damping viscoelastic`: η = η₀ a m* [kg/s] with the contact radius a = √(R* δ) [m],
/// η₀ [1/(m·s)] the pair_coeff damping value, m* [kg]. The same form as Kuwabara–Kono with
/// 2 E' = η₀ m*.
[[nodiscard]] inline double lammps_viscoelastic_damping_coefficient(double rate_per_length,
                                                                    double reduced_radius,
                                                                    double overlap,
                                                                    double reduced_mass) noexcept {
  return overlap > 0.0 ? rate_per_length * std::sqrt(reduced_radius * overlap) * reduced_mass : 0.0;
}

/// LAMMPS `damping viscoelastic` at a given contact radius a [m] (under JKR, the JKR radius):
/// η = η₀ a m* [kg/s] (pair_granular.cpp, 2021).
[[nodiscard]] inline double lammps_viscoelastic_damping_at_radius(double rate_per_length, double contact_radius,
                                                                  double reduced_mass) noexcept {
  return rate_per_length * contact_radius * reduced_mass;
}

/// YADE Hertz–Mindlin damping ratio β_n(e) from Thornton, Cummins & Cleary 2013, eqs B6–B7 (as
/// `Ip2_FrictMat_FrictMat_MindlinPhys(en=e)` of YADE 2023.02a computes it):
/// β_n = √(1/(1 − (1+e)² exp(A(e))) − 1), A(e) = Σ_{i=1..10} h_i e^i. A fit for the *clipped*
/// Hertz dashpot η = 2 β_n √(m* k_tangent); measured e within 1e-4 for e ∈ [0.1, 0.9]. At
/// e = 1 the fit gives β_n = 0.0045, not 0 (YADE does the same).
[[nodiscard]] inline double thornton_damping_ratio(double e) noexcept {
  constexpr std::array<double, 10> h{-6.918798, -16.41105, 146.8049, -796.4559, 2928.711,
                                     -7206.864, 11494.29,  -11342.18, 6276.757, -1489.915};
  double a = 0.0;
  for (auto it = h.rbegin(); it != h.rend(); ++it) a = (a + *it) * e;
  return std::sqrt(1.0 / (1.0 - (1.0 + e) * (1.0 + e) * std::exp(a)) - 1.0);
}

/// YADE Hertz–Mindlin normal dashpot c_n = 2 β_n √(m* k_n) [kg/s] with the tangent stiffness
/// k_n = dF/dδ = 1.5 k_no √δ [N/m] (Law2_ScGeom_MindlinPhys_Mindlin), m* [kg].
[[nodiscard]] inline double yade_mindlin_damping_coefficient(double damping_ratio,
                                                             double reduced_mass,
                                                             double tangent_stiffness) noexcept {
  return 2.0 * damping_ratio * std::sqrt(reduced_mass * std::max(tangent_stiffness, 0.0));
}

}  // namespace dem::laws
