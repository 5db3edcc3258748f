// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>

namespace dem::laws {

/// Force, tangent stiffness and potential energy of the Langston continuous potential.
struct PotentialResponse {
  double force = 0.0;      ///< [N], repulsive positive
  double stiffness = 0.0;  ///< dF/dδ = −dF/d|x| [N/m]
  double energy = 0.0;     ///< φ(|x|) − φ(d_crit) [J], ≥ 0
};

/// Characteristic energy ε_p = d m* g / a [J] of the Langston potential (thesis eq 3.19): the
/// force at |x| = d then equals the weight m* g. d [m], m* [kg], g [m/s²], exponent a > 0.
[[nodiscard]] constexpr double langston_energy_scale(double length, double reduced_mass,
                                                     double gravity, double exponent) noexcept {
  return length * reduced_mass * gravity / exponent;
}

/// Langston et al.'s simplified potential (thesis eq 3.17–3.18): φ = ε_p (d/|x|)^a and
/// F = −dφ/d|x| = a ε_p / |x| · (d/|x|)^a for |x| < d_crit, nothing beyond. |x| = centre
/// distance [m] (> 0), d = characteristic length [m], d_crit [m], ε_p [J], a > 0 (Langston: 36).
/// The energy is shifted by φ(d_crit) so that it is continuous (zero) at the cut-off; the force
/// jumps there from a ε_p/d_crit (d/d_crit)^a to 0 (negligible for a = 36, d_crit = √2 d).
[[nodiscard]] inline PotentialResponse langston_potential(double exponent, double energy_scale,
                                                          double length, double critical_distance,
                                                          double distance) noexcept {
  if (!(distance > 0.0) || distance >= critical_distance) return {};
  const double power = std::pow(length / distance, exponent);
  const double force = exponent * energy_scale / distance * power;
  return {force, (exponent + 1.0) * force / distance,
          energy_scale * (power - std::pow(length / critical_distance, exponent))};
}

}  // namespace dem::laws
