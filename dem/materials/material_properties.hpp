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
};

/// Raw properties of one material as a case file gives them (SI units). A property a material
/// does not set stays empty; the contact model says which ones it needs.
struct MaterialProperties {
  std::string name;
  double density = 0.0;                     ///< ρ [kg/m³] (thesis eq 3.1)
  std::optional<double> normal_stiffness;   ///< k_e [N/m], linear repulsion (eq 3.10)
  std::optional<double> restitution;        ///< ε [-], normal coefficient of restitution (eq 3.11)
};

/// Mixed properties of one material pair, the input of every contact sub-model. A case file can
/// override any of them per pair; reports print the whole table.
struct PairProperties {
  std::optional<double> normal_stiffness;   ///< k_e [N/m] of the pair
  std::optional<double> restitution;        ///< ε [-] of the pair
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
