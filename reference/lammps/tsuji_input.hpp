// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

namespace reference::lammps {

/// The nominal restitution e_in to give LAMMPS `damping tsuji` so that its dashpot factor
/// α_L(e_in) (Tsuji's polynomial, dem::laws::lammps_tsuji_factor) equals `factor`: LAMMPS then
/// computes η = factor·√(m* · 4/3 E* a), the same dashpot as the core's `tsuji` (factor = α(ε) =
/// √5 β(ε)) or `restitution` on Hertz (factor = √1.5 β(ε), tangent stiffness 2E*a)
/// (measured with LAMMPS 29 Sep 2021: e_in = 0.3666513616 rebounds at 0.49996 for ε = 0.5).
/// α_L falls monotonically from 1.2728 at e = 0 to ≈ 0 at e = 1; solved by
/// bisection to the last bit. Empty when factor lies outside α_L's range [α_L(1), α_L(0)].
std::optional<double> tsuji_input_for_factor(double factor);

}  // namespace reference::lammps
