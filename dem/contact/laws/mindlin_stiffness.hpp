// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>

namespace dem::laws {

/// Contact radius a = √(R* δ) [m] the Mindlin stiffness uses (Hertz geometry); 0 for δ ≤ 0.
[[nodiscard]] inline double mindlin_contact_radius(double reduced_radius, double overlap) noexcept {
  return std::sqrt(reduced_radius * std::max(overlap, 0.0));
}

/// The thesis' Mindlin stiffness 16/3 G* a at a given contact radius a [m] (eq 3.25 with a
/// instead of √(R* δ): the JKR radius when the contact's cohesion law sets it) [N/m].
[[nodiscard]] inline double mindlin_thesis_stiffness_at_radius(double effective_shear_modulus, double a) noexcept {
  return 16.0 / 3.0 * effective_shear_modulus * a;
}

/// Mindlin's initial stiffness 8 G* a at a given contact radius a [m] (LAMMPS `tangential
/// mindlin` scales k_t by its normal model's a: √(R* δ), or the JKR radius under jkr) [N/m].
[[nodiscard]] inline double mindlin_stiffness_at_radius(double effective_shear_modulus, double a) noexcept {
  return 8.0 * effective_shear_modulus * a;
}

/// Tangential stiffness of the thesis' Mindlin form, eq 3.25: k_f = 16/3 G* √(R* δ) [N/m],
/// with G* = G_p G_q / (G_p(2 − ν_q) + G_q(2 − ν_p)) [Pa], R* [m], δ [m]. Valid for small
/// tangential load relative to μ F_n (no micro-slip softening). 0 out of contact.
[[nodiscard]] inline double mindlin_thesis_stiffness(double effective_shear_modulus,
                                                     double reduced_radius,
                                                     double overlap) noexcept {
  return mindlin_thesis_stiffness_at_radius(effective_shear_modulus, mindlin_contact_radius(reduced_radius, overlap));
}

/// Mindlin's initial tangential stiffness k_t = 8 G* a, a = √(R* δ) [N/m] (Mindlin 1949; the
/// form of LAMMPS `tangential mindlin` and YADE Ip2_FrictMat_FrictMat_MindlinPhys). 0 out of contact.
[[nodiscard]] inline double mindlin_stiffness(double effective_shear_modulus, double reduced_radius,
                                              double overlap) noexcept {
  return mindlin_stiffness_at_radius(effective_shear_modulus, mindlin_contact_radius(reduced_radius, overlap));
}

}  // namespace dem::laws
