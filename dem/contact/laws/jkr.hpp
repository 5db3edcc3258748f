// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <numbers>

#include "dem/core/cube_root.hpp"

// The JKR adhesive contact (Johnson, Kendall & Roberts 1971; thesis eq 3.34–3.35;
// docs/physics-cohesion.md) as pure functions of the contact radius a. γ is the surface energy *per
// surface*; the work of adhesion is Γ = 2γ. Overlap δ > 0 means the bodies interpenetrate; force
// positive = repulsive. Every closed form below follows from the two defining equations; with a_c
// the critical radius and y = √(a/a_c) they read δ = (a_c²/R*)(y⁴ − 4y) and F = πγR*(y⁶/3 − 2y³).
namespace dem::laws {

/// The three constants of one JKR contact.
struct JkrParameters {
  double effective_modulus;  ///< E* [Pa] (eq 3.13)
  double reduced_radius;     ///< R* [m]
  double surface_energy;     ///< γ [J/m²], per surface
};

/// Overlap at contact radius a, eq 3.35: δ = a²/R* − √(4πγa/E*) [m].
[[nodiscard]] inline double jkr_overlap(double radius, const JkrParameters& p) noexcept {
  return radius * radius / p.reduced_radius -
         std::sqrt(4.0 * std::numbers::pi * p.surface_energy * radius / p.effective_modulus);
}

/// Normal force at contact radius a, eq 3.34: F = 4πa² (a E*/(3πR*) − √(γE*/(πa))) [N],
/// repulsive positive (negative in tension).
[[nodiscard]] inline double jkr_force(double radius, const JkrParameters& p) noexcept {
  const double a = radius;
  return 4.0 * std::numbers::pi * a * a *
         (a * p.effective_modulus / (3.0 * std::numbers::pi * p.reduced_radius) -
          std::sqrt(p.surface_energy * p.effective_modulus / (std::numbers::pi * a)));
}

/// Energy of the contact at radius a, elastic plus surface, relative to separated surfaces [J]:
/// U = 8E*a⁵/(15R*²) − 8√(πγE*) a^{7/2}/(3R*) + 2πγa², the integral of F dδ along eq 3.34–3.35
/// from a = 0, so dU/dδ = F on the curve. It is −1.2πγa² at first touch (δ = 0): the energy
/// released when the neck snaps in; 0.8πγa_c² at the displacement-controlled rupture.
[[nodiscard]] inline double jkr_energy(double radius, const JkrParameters& p) noexcept {
  const double a = radius;
  const double r = p.reduced_radius;
  const double root = std::sqrt(std::numbers::pi * p.surface_energy * p.effective_modulus);
  return 8.0 * p.effective_modulus * std::pow(a, 5) / (15.0 * r * r) -
         8.0 * root * std::pow(a, 3.5) / (3.0 * r) +
         2.0 * std::numbers::pi * p.surface_energy * a * a;
}

/// Critical contact radius, where dδ/da = 0: a_c³ = πΓR*²/(8E*) = πγR*²/(4E*) [m].
[[nodiscard]] inline double jkr_critical_radius(const JkrParameters& p) noexcept {
  return cube_root(std::numbers::pi * p.surface_energy * p.reduced_radius * p.reduced_radius /
                   (4.0 * p.effective_modulus));
}

/// Overlap of the displacement-controlled rupture, the smallest δ with a solution:
/// δ_c = −¾ (π²Γ²R*/E*²)^{1/3} = −3a_c²/R* [m] (negative: the surfaces are apart).
[[nodiscard]] inline double jkr_rupture_overlap(const JkrParameters& p) noexcept {
  const double work = 2.0 * p.surface_energy;
  return -0.75 * std::cbrt(std::numbers::pi * std::numbers::pi * work * work * p.reduced_radius /
                           (p.effective_modulus * p.effective_modulus));
}

/// Pull-off force under load control, the largest tension: F_po = 3πγR* = 1.5πΓR* [N] (> 0).
[[nodiscard]] inline double jkr_pulloff_force(const JkrParameters& p) noexcept {
  return 3.0 * std::numbers::pi * p.surface_energy * p.reduced_radius;
}

/// Contact radius at the load-controlled pull-off point (dF/da = 0):
/// a_f³ = 9πγR*²/(4E*) = 9 a_c³ [m].
[[nodiscard]] inline double jkr_pulloff_radius(const JkrParameters& p) noexcept {
  return std::cbrt(9.0) * jkr_critical_radius(p);
}

/// Overlap at the load-controlled pull-off point, δ_f = δ(a_f) = (9^{2/3} − 4·9^{1/6}) a_c²/R*
/// ≈ 0.4807 δ_c [m]; LAMMPS breaks JKR contacts here.
[[nodiscard]] inline double jkr_pulloff_overlap(const JkrParameters& p) noexcept {
  return jkr_overlap(jkr_pulloff_radius(p), p);
}

/// Contact radius at zero load: a_0³ = 9πγR*²/E* [m].
[[nodiscard]] inline double jkr_zero_load_radius(const JkrParameters& p) noexcept {
  return std::cbrt(9.0 * std::numbers::pi * p.surface_energy * p.reduced_radius *
                   p.reduced_radius / p.effective_modulus);
}

/// Contact radius at first touch, δ = 0 on the stable branch: a³ = 4πγR*²/E* [m]; the force
/// there is −8/9 F_po.
[[nodiscard]] inline double jkr_touch_radius(const JkrParameters& p) noexcept {
  return std::cbrt(4.0 * std::numbers::pi * p.surface_energy * p.reduced_radius *
                   p.reduced_radius / p.effective_modulus);
}

/// δ_c from a known critical radius: −3a_c²/R* (the same value as jkr_rupture_overlap, without
/// its cube root; what the contact loop uses, having a_c already) [m].
[[nodiscard]] inline double jkr_rupture_overlap_at(double critical_radius, const JkrParameters& p) noexcept {
  return -3.0 * critical_radius * critical_radius / p.reduced_radius;
}

/// δ_f from a known critical radius: at y_f = 9^{1/6}, y_f⁴ = 3y_f, so δ_f = −9^{1/6} a_c²/R*
/// (the same value as jkr_pulloff_overlap, without its cube roots) [m].
[[nodiscard]] inline double jkr_pulloff_overlap_at(double critical_radius, const JkrParameters& p) noexcept {
  constexpr double kSixthRootOfNine = 1.4422495703074083;  // 9^{1/6}
  return -kSixthRootOfNine * critical_radius * critical_radius / p.reduced_radius;
}

/// Contact radius a(δ) on the stable branch a ≥ a_c (the larger root of eq 3.35, dF/dδ > 0),
/// by Newton's method from a tabulated start, to rounding (docs/physics-cohesion.md). δ at or
/// below δ_c gives a_c.
[[nodiscard]] double jkr_contact_radius(double overlap, const JkrParameters& p) noexcept;

/// y = √(a/a_c) on the stable branch (y ≥ 1) for overlap δ, given a_c = jkr_critical_radius(p):
/// what jkr_contact_radius solves for; the contact loop, having a_c already, calls it directly, and
/// the force and energy below read it without a square root or a division.
[[nodiscard]] double jkr_radius_ratio(double overlap, const JkrParameters& p,
                                      double critical_radius) noexcept;

/// Normal force at y = √(a/a_c), eq 3.34 with a = a_c y²: F = πγR* (y⁶/3 − 2y³) [N], repulsive
/// positive (−5/3 πγR* at the rupture point y = 1, the largest tension −3πγR* at y³ = 3).
[[nodiscard]] inline double jkr_force_at_ratio(double ratio, const JkrParameters& p) noexcept {
  const double y3 = ratio * ratio * ratio;
  return std::numbers::pi * p.surface_energy * p.reduced_radius * (y3 * y3 / 3.0 - 2.0 * y3);
}

/// Contact energy at y = √(a/a_c) (jkr_energy with a = a_c y²):
/// U = πγa_c² (2y¹⁰/15 − 4y⁷/3 + 2y⁴) [J] (0.8πγa_c² at the rupture point).
[[nodiscard]] inline double jkr_energy_at_ratio(double ratio, double critical_radius,
                                                const JkrParameters& p) noexcept {
  const double y2 = ratio * ratio;
  const double y3 = y2 * ratio;
  const double y4 = y2 * y2;
  return std::numbers::pi * p.surface_energy * critical_radius * critical_radius * y4 *
         (2.0 * y4 * y2 / 15.0 - 4.0 * y3 / 3.0 + 2.0);
}

}  // namespace dem::laws
