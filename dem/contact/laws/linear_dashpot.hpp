// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <numbers>

namespace dem::laws {

/// Damping factor β(ε) = −2 ln ε / √(π² + ln² ε) of the linear spring–dashpot, so that the
/// dashpot coefficient is η = β √(m* k_e) (thesis eq 3.11). restitution ε ∈ (0, 1]; β ∈ [0, 2).
[[nodiscard]] inline double restitution_damping_factor(double restitution) noexcept {
  const double ln_e = std::log(restitution);
  return -2.0 * ln_e / std::sqrt(std::numbers::pi * std::numbers::pi + ln_e * ln_e);
}

/// Dashpot coefficient η [kg/s] giving restitution ε for reduced mass m* [kg] and stiffness
/// k_e [N/m] (thesis eq 3.11): η = −2 ln ε √(m* k_e / (π² + ln² ε)).
[[nodiscard]] inline double restitution_damping_coefficient(double restitution, double reduced_mass,
                                                           double stiffness) noexcept {
  return restitution_damping_factor(restitution) * std::sqrt(reduced_mass * stiffness);
}

/// Viscous normal force −η (u_c·n) [N] (thesis eq 3.10, damping part). normal_speed = u_c·n
/// [m/s] is negative on approach, so the force is repulsive while the particles approach.
[[nodiscard]] constexpr double dashpot_force(double damping_coefficient,
                                             double normal_speed) noexcept {
  return -damping_coefficient * normal_speed;
}

/// Contact duration of the linear spring–dashpot [s]: t_c = π / √(k_e/m* − (η/2m*)²)
/// (thesis eq 3.40 with its typo corrected; docs/physics.md). Requires η < 2√(m* k_e).
[[nodiscard]] inline double linear_contact_duration(double stiffness, double reduced_mass,
                                                    double damping_coefficient) noexcept {
  const double half_rate = damping_coefficient / (2.0 * reduced_mass);
  return std::numbers::pi / std::sqrt(stiffness / reduced_mass - half_rate * half_rate);
}

/// Restitution of the linear spring–dashpot (the inverse of eq 3.11):
/// ε = exp(−π ζ / √(1 − ζ²)) with ζ = η / (2√(m* k_e)).
[[nodiscard]] inline double linear_restitution(double stiffness, double reduced_mass,
                                               double damping_coefficient) noexcept {
  const double zeta = damping_coefficient / (2.0 * std::sqrt(reduced_mass * stiffness));
  return std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta));
}

/// YADE's ratcheting correction α = D/(D − δ) of the relative normal velocity (ScGeom::
/// getIncidentVel with avoidGranularRatcheting), for the reference length D and overlap δ.
[[nodiscard]] inline double incident_velocity_scale(double reference_length, double overlap) noexcept {
  return reference_length / (reference_length - overlap);
}

}  // namespace dem::laws
