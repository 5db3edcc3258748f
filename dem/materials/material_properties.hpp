// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace dem {

/// How a pair value is formed from the two materials' values of one property.
enum class MixingRule {
  harmonic,    ///< 2ab/(a+b): two half-contacts in series (equals a when a = b)
  arithmetic,  ///< (a+b)/2
  geometric,   ///< √(ab)
  min,         ///< min(a, b)
  max,         ///< max(a, b)
  derived,     ///< computed from several material properties (E*, G*), not mixed value by value
};

/// Raw properties of one material as a case file gives them (SI units). A property a material
/// does not set stays empty; the contact model says which ones it needs.
struct MaterialProperties {
  std::string name;
  double density = 0.0;                          ///< ρ [kg/m³] (thesis eq 3.1)
  std::optional<double> normal_stiffness;        ///< k_e [N/m], linear repulsion (eq 3.10)
  std::optional<double> restitution;             ///< ε [-], normal restitution (eq 3.11)
  std::optional<double> youngs_modulus;          ///< E [Pa] (eq 3.13)
  std::optional<double> poisson_ratio;           ///< ν [-] (eq 3.13)
  std::optional<double> tangential_stiffness;    ///< k_f [N/m] (eq 3.24)
  std::optional<double> tangential_damping_ratio;///< η_t / η_n [-] (eq 3.26)
  std::optional<double> friction;                ///< μ [-] (eq 3.23)
  std::optional<double> rolling_friction;        ///< μ_r [-], rolling resistance
  std::optional<double> rolling_stiffness;       ///< k_r [N/m], spring–dashpot–slider rolling
  std::optional<double> rolling_damping;         ///< γ_r [kg/s], spring–dashpot–slider rolling
  std::optional<double> cohesive_stiffness;      ///< k_c [N/m] (eq 3.33)
  std::optional<double> surface_energy;          ///< γ [J/m²], per surface (eq 3.34)
  std::optional<double> interaction_ratio;       ///< λ = r̂/r [-], effect radius default
  std::optional<double> damping_coefficient;     ///< η [kg/s], dashpot given directly
  std::optional<double> viscous_modulus;         ///< E' [Pa·s], Kuwabara–Kono dissipative modulus (eq 3.14)
  std::optional<double> damping_rate;            ///< η/m* [1/s], mass-scaled dashpot
  std::optional<double> viscoelastic_damping;    ///< η_0 [1/(m·s)], η = η_0 a m*
  std::optional<double> relative_permittivity;   ///< ε_r [-] of the medium (eq 3.36)
  std::optional<double> coulomb_cutoff;          ///< [m] centre distance beyond which no Coulomb force
  std::optional<double> potential_exponent;      ///< a [-] (eq 3.17)
  std::optional<double> potential_critical_ratio;///< d_crit / d [-] (eq 3.17)
  std::optional<double> potential_gravity;       ///< g [m/s²] in ε_p = d m* g / a (eq 3.19)
  /// The material of a rigid body (a wall with `rigid = true`): it adds no compliance, so E*, G*
  /// and the linear stiffnesses of its contacts come from the other body alone (mixing.hpp).
  bool rigid = false;
};

/// Mixed properties of one material pair, the input of every contact sub-model. A case file can
/// override any of them per pair; reports print the whole table.
struct PairProperties {
  std::optional<double> normal_stiffness;
  std::optional<double> restitution;
  std::optional<double> effective_modulus;       ///< E* [Pa] (eq 3.13), from E and ν
  std::optional<double> effective_shear_modulus; ///< G* [Pa] (eq 3.25), from E and ν
  std::optional<double> tangential_stiffness;
  std::optional<double> tangential_damping_ratio;
  std::optional<double> friction;
  std::optional<double> rolling_friction;
  std::optional<double> rolling_stiffness;
  std::optional<double> rolling_damping;
  std::optional<double> cohesive_stiffness;
  std::optional<double> surface_energy;
  std::optional<double> damping_coefficient;
  std::optional<double> viscous_modulus;
  std::optional<double> damping_rate;
  std::optional<double> viscoelastic_damping;
  std::optional<double> relative_permittivity;
  std::optional<double> coulomb_cutoff;
  std::optional<double> potential_exponent;
  std::optional<double> potential_critical_ratio;
  std::optional<double> potential_gravity;
};

/// Admissible interval of a physical value; `open` ends exclude the bound.
struct ValueRange {
  double min;
  double max;
  bool min_open;
  bool max_open;

  /// True when v lies in the interval (NaN never does).
  [[nodiscard]] bool contains(double v) const noexcept {
    const bool above = min_open ? v > min : v >= min;
    const bool below = max_open ? v < max : v <= max;
    return above && below;
  }
  /// Interval in mathematical notation, e.g. "(0, 1]".
  [[nodiscard]] std::string describe() const;
};

/// Description of one named property: case-file key, unit, meaning and valid range.
struct PropertySpec {
  std::string_view key;
  std::string_view unit;
  std::string_view meaning;
  ValueRange range;
  std::optional<double> MaterialProperties::*material_field;   ///< null for pair-only keys
  std::optional<double> PairProperties::*pair_field;            ///< null for material-only keys
  MixingRule default_mixing;                                    ///< rule unless the case names one
};

/// Every optional material/pair property the core knows, in documentation order.
std::span<const PropertySpec> property_specs() noexcept;

/// Spec of the property named `key`, or nullptr.
const PropertySpec* find_property_spec(std::string_view key) noexcept;

/// Valid range of density [kg/m³]: (0, ∞).
ValueRange density_range() noexcept;

}  // namespace dem
