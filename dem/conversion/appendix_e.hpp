// SPDX-License-Identifier: MIT
#pragma once

#include "dem/contact/laws/jkr.hpp"
#include "dem/contact/model_choice.hpp"

// Thesis appendix E: relating the linear elastic–cohesive model (k_e, k_c, effect radius) to
// the JKR model (E, γ) for two identical spheres by equal work. The elastic stiffness follows
// from equal elastic work up to δ_max (eq E.3–E.4); the cohesion from equal work of the whole
// force–separation curve (eq E.8, listing E.1). "Work" here is the work W the contact force
// does on the pair while it is separated quasi-statically (displacement control) from the
// deepest overlap δ_max until the force vanishes: W = ∫ F dℓ over the centre distance ℓ, i.e.
// the area under the force–separation curve, counted positive for repulsion:
//   linear:  W = ½ k_e δ_max² − ½ k_c δ̂_max²,  δ̂_max = 2(r̂ − r) + δ_max  (eq E.8, sign of the
//            cohesive term as in listing E.1; the printed E.8 has "+")
//   JKR:     W = U(a(δ_max)) − U(a_rupture), U the closed-form JKR energy (laws::jkr_energy), so
//            no quadrature is needed; the curve ends at the rupture point δ_c (or δ_f).
namespace dem::conversion {

/// Which radius and modulus the appendix-E formulas (E.2, E.4, E.6, E.7) receive.
enum class Convention {
  workbench,  ///< as the core evaluates a pair: R* = r/2 and E* = E/(2(1 − ν²))
  thesis,     ///< as listing E.1 was run: the particle radius r and the tabulated E unreduced
};

/// The pair appendix E relates: two identical spheres pressed together to δ_max.
struct PairGeometry {
  double radius;         ///< body radius r [m]
  double effect_radius;  ///< effect (interaction) radius r̂ ≥ r [m]
  double max_overlap;    ///< δ_max [m] > 0, the deepest overlap of a typical collision
};

/// Parameters of the linear elastic–cohesive model (eq E.5).
struct LinearModel {
  double normal_stiffness;    ///< k_e [N/m]
  double cohesive_stiffness;  ///< k_c [N/m]
};

/// Parameters of the JKR model as its formulas use them (eq E.6–E.7).
struct JkrModel {
  double modulus;         ///< the modulus in eq E.2/E.6–E.7: E* (workbench) or E (thesis) [Pa]
  double surface_energy;  ///< γ per surface [J/m²]
};

/// Radius the formulas use: R* = r/2 (workbench) or r (thesis) [m].
[[nodiscard]] double formula_radius(const PairGeometry& pair, Convention convention) noexcept;

/// Modulus the formulas use from a material's E and ν: E* = E/(2(1 − ν²)) for two identical
/// spheres (workbench), or E itself (thesis) [Pa].
[[nodiscard]] double formula_modulus(double youngs_modulus, double poisson_ratio,
                                     Convention convention) noexcept;

/// Young's modulus E of the material from the modulus the formulas use (inverse of
/// formula_modulus) [Pa].
[[nodiscard]] double youngs_modulus(double modulus, double poisson_ratio,
                                    Convention convention) noexcept;

/// Eq E.4: linear stiffness with the same elastic work up to δ_max as Hertz,
/// k_e = 16/15 E √(R δ_max) [N/m].
[[nodiscard]] double stiffness_from_modulus(double modulus, double radius,
                                            double max_overlap) noexcept;

/// Eq E.4 solved for the modulus: E = 15 k_e / (16 √(R δ_max)) [Pa].
[[nodiscard]] double modulus_from_stiffness(double stiffness, double radius,
                                            double max_overlap) noexcept;

/// Effect overlap at δ_max: δ̂_max = 2(r̂ − r) + δ_max [m].
[[nodiscard]] double max_effect_overlap(const PairGeometry& pair) noexcept;

/// Work of the linear model from δ_max to full separation, ½ k_e δ_max² − ½ k_c δ̂_max² [J].
[[nodiscard]] double linear_separation_work(const LinearModel& model,
                                            const PairGeometry& pair) noexcept;

/// Work of the Hertz repulsion alone from δ_max to touch, 8/15 E √R δ_max^{5/2} [J]; the JKR
/// work tends to it as γ → 0.
[[nodiscard]] double hertz_separation_work(double modulus, double radius,
                                           double max_overlap) noexcept;

/// Work of the JKR curve from δ_max to its rupture (δ_c, or δ_f under `load`) [J].
[[nodiscard]] double jkr_separation_work(const laws::JkrParameters& p, double max_overlap,
                                         JkrRupture rupture) noexcept;

/// Cohesive work of the linear model (thesis fig. 5.15, for the linear law): the work that must
/// be done on two identical spheres to separate them quasi-statically from their force-free
/// equilibrium δ_eq = k_c Δ/(k_e − k_c) (Δ = 2(r̂ − r)) until cohesion stops acting (δ̂ = 0):
/// ½ k_c (δ_eq + Δ)² − ½ k_e δ_eq² [J]. Throws std::invalid_argument when k_e ≤ k_c (no
/// equilibrium) or r̂ < r.
[[nodiscard]] double linear_cohesive_work(const LinearModel& model, double radius, double effect_radius);

/// Cohesive work of JKR (thesis fig. 5.15, the shaded area): the work that must be done on the
/// pair to separate it quasi-statically from the zero-load contact (F = 0, radius a_0) to its
/// rupture (δ_c, or δ_f under `load`), U(a_end) − U(a_0) [J], U the closed-form JKR energy.
[[nodiscard]] double jkr_cohesive_work(const laws::JkrParameters& p, JkrRupture rupture) noexcept;

/// Surface energy γ whose JKR separation work from δ_max equals `work` [J/m²], by a bracketed
/// TOMS 748 solve in log γ (W decreases monotonically with γ). Throws std::domain_error when
/// no γ > 0 matches (work ≥ the Hertz work) and std::invalid_argument on bad input.
[[nodiscard]] double surface_energy_for_work(double work, double modulus, double radius,
                                             double max_overlap, JkrRupture rupture);

/// Linear → JKR: the modulus from eq E.4, γ by equal work (listing E.1). Throws
/// std::invalid_argument on non-physical input, std::domain_error when nothing matches.
[[nodiscard]] JkrModel linear_to_jkr(const LinearModel& model, const PairGeometry& pair,
                                     Convention convention,
                                     JkrRupture rupture = JkrRupture::displacement);

/// JKR → linear: k_e from eq E.4, k_c by equal work (closed form). Throws
/// std::invalid_argument on non-physical input, std::domain_error when k_c would be negative.
[[nodiscard]] LinearModel jkr_to_linear(const JkrModel& model, const PairGeometry& pair,
                                        Convention convention,
                                        JkrRupture rupture = JkrRupture::displacement);

}  // namespace dem::conversion
