// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

namespace reference::lammps {

/// Lowest e_in the driver gives `damping tsuji`: α_L(−1) ≈ 89.3, far above any factor the core
/// asks for (the core's Tsuji factor tends to √5 as ε → 0).
inline constexpr double kTsujiInputLowest = -1.0;

/// The e_in ≈ 1.00065 just above 1 where LAMMPS' Tsuji polynomial α_L crosses zero (α_L(1) is
/// 3e-4, not 0: the fit does not vanish at e = 1).
double tsuji_input_zero();

/// The nominal restitution e_in to give LAMMPS `damping tsuji` so that its dashpot factor
/// α_L(e_in) (Tsuji's polynomial, dem::laws::lammps_tsuji_factor) equals `factor`: LAMMPS then
/// computes η = factor·√(m* · 4/3 E* a), the same dashpot as the core's `tsuji` (factor = α(ε) =
/// √5 β(ε)) or `restitution` on Hertz (factor = √1.5 β(ε), tangent stiffness 2E*a)
/// (measured with LAMMPS 29 Sep 2021: e_in = 0.3666513616 rebounds at 0.49996 for ε = 0.5).
/// e_in is an input of the polynomial, not a restitution: LAMMPS 29 Sep 2021 takes any real
/// value. α_L falls monotonically from α_L(−1) ≈ 89.3 through 1.2728 at 0 and 3e-4 at 1 to 0 at
/// tsuji_input_zero(), so every factor in [0, 89.3] has one e_in there (e_in < 0 for factors
/// above 1.2728, i.e. ε below about 0.12; e_in > 1 for factors below 3e-4, ε above about
/// 0.9996); solved by bisection to the last bit. Empty for factors outside that range.
std::optional<double> tsuji_input_for_factor(double factor);

}  // namespace reference::lammps
