// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <numbers>

namespace dem::laws {

// Closed-form restitution of the two dashpots that have one: the linear spring–dashpot and the
// Hertz contact with Tsuji's dashpot. Both are written with the damping ratio ζ of a linear
// oscillator, which is why Tsuji's α can be made restitution-exact without a numerical solve.

/// Restitution of the linear spring–dashpot m* δ'' + η δ' + k δ = 0 whose total force is
/// clipped at ≥ 0 (the contact ends when the force reaches 0, before δ does), as a function of
/// the damping ratio ζ = η / (2√(m* k)) ≥ 0 (Schwager & Pöschel, Granular Matter 9, 2007).
/// ζ < 1: e = exp(−ζ/√(1−ζ²) · (π − atan2(2ζ√(1−ζ²), 1 − 2ζ²))); ζ > 1 (overdamped, the force
/// still vanishes at the inflection of δ): e = ((ζ−s)/(ζ+s))^{ζ/s}, s = √(ζ²−1); e = e⁻² at
/// ζ = 1. Larger than the unclipped exp(−πζ/√(1−ζ²)). YADE's ViscElPhys law converges to it.
[[nodiscard]] inline double linear_clipped_restitution(double damping_ratio) noexcept {
  const double z = damping_ratio;
  if (z < 1.0) {
    const double w = std::sqrt(1.0 - z * z);
    return std::exp(-z / w * (std::numbers::pi - std::atan2(2.0 * z * w, 1.0 - 2.0 * z * z)));
  }
  if (z == 1.0) return std::exp(-2.0);
  const double s = std::sqrt(z * z - 1.0);
  return std::exp(-z / s * std::log((z + s) / (z - s)));
}

/// Restitution of a Hertz contact with Tsuji's dashpot,
/// m* δ'' = −k_n δ^{3/2} − α √(m* k_n) δ^{1/4} δ' (k_n = 4/3 E* √R*), for the factor α ≥ 0.
/// Exact: in units δ* = (m* v²/k_n)^{2/5}, δ*/v it reads x'' + α x^{1/4} x' + x^{3/2} = 0; the
/// time change dσ = x^{1/4} dτ and y = x^{5/4} turn it into the linear oscillator
/// ÿ + α ẏ + (5/4) y = 0 with x' = (4/5) ẏ, so the rebound is that of a linear dashpot with
/// damping ratio ζ = α/√5, independent of the impact speed. `clamp_tensile`: force clipped at
/// ≥ 0, which is the clipped linear oscillator (same ζ, any ζ). Unclipped, the contact never
/// ends for ζ ≥ 1 and 0 is returned.
[[nodiscard]] inline double hertz_tsuji_restitution(double factor, bool clamp_tensile) noexcept {
  const double zeta = factor / std::sqrt(5.0);
  if (clamp_tensile) return linear_clipped_restitution(zeta);
  if (zeta >= 1.0) return 0.0;
  return std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta));
}

/// Tsuji factor α(ε) that makes the unclipped Hertz–Tsuji contact rebound with restitution ε
/// exactly, ε ∈ (0, 1]: the inverse of hertz_tsuji_restitution, α = −√5 ln ε / √(π² + ln² ε)
/// (= √5 ζ(ε); 0.4817693 for ε = 0.5). The "α = √5 β" found numerically for
/// LAMMPS' Hertz dashpot (RK4 root-find; LAMMPS 29 Sep 2021 then rebounds at 0.49996 for 0.5).
[[nodiscard]] inline double tsuji_factor(double restitution) noexcept {
  const double ln_e = std::log(restitution);
  return -std::sqrt(5.0) * ln_e / std::sqrt(std::numbers::pi * std::numbers::pi + ln_e * ln_e);
}

}  // namespace dem::laws
