// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "dem/materials/material_properties.hpp"

namespace dem {

/// Mixing rule per property key; keys absent here use the property's default rule.
using MixingRules = std::map<std::string, MixingRule, std::less<>>;

/// Per-pair values a case file sets directly, replacing the mixed ones.
struct PairOverride {
  std::size_t material_a;
  std::size_t material_b;
  PairProperties values;
};

/// Combines two material values of one property with `rule`.
double mix_values(MixingRule rule, double a, double b) noexcept;

/// Case-file keyword of a mixing rule ("harmonic", …).
std::string_view to_string(MixingRule rule) noexcept;

/// Mixing rule named `keyword`, or empty.
std::optional<MixingRule> parse_mixing_rule(std::string_view keyword) noexcept;

/// Rule used for the property `key` under `rules` (the case's choice or the default).
MixingRule rule_for(const MixingRules& rules, const PropertySpec& spec) noexcept;

/// Reduced Young's modulus E* = [(1 − ν_p²)/E_p + (1 − ν_q²)/E_q]⁻¹ [Pa] (thesis eq 3.13).
[[nodiscard]] double effective_modulus(double e_p, double nu_p, double e_q, double nu_q) noexcept;

/// Reduced shear modulus G* = [(2 − ν_p)/G_p + (2 − ν_q)/G_q]⁻¹ with G = E/(2(1 + ν)) [Pa]; the
/// factor of thesis eq 3.25 and of Mindlin's k_t = 8 G* a (docs/physics-tangential.md).
[[nodiscard]] double effective_shear_modulus(double e_p, double nu_p, double e_q,
                                             double nu_q) noexcept;

/// Mixed pair properties of materials a and b: a property is set when both materials set it;
/// E* and G* are derived when both materials set E and ν.
PairProperties mix_properties(const MaterialProperties& a, const MaterialProperties& b,
                              const MixingRules& rules);

/// Copies every property set in `overrides` onto `base` (per-pair values from a case file).
void apply_overrides(PairProperties& base, const PairProperties& overrides) noexcept;

}  // namespace dem
