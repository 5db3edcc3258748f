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

/// E* against a rigid body: eq 3.13 without the rigid body's compliance term, E/(1 − ν²) [Pa].
[[nodiscard]] double rigid_effective_modulus(double e, double nu) noexcept;

/// G* against a rigid body: eq 3.25 without the rigid body's term, G/(2 − ν) with G = E/(2(1 + ν)) [Pa].
[[nodiscard]] double rigid_effective_shear_modulus(double e, double nu) noexcept;

/// The properties a rigid partner changes (docs/physics.md, "Walls"): the body's elastic springs
/// (normal, tangential and rolling stiffness) are the compliant body's half-contact alone, 2k
/// (the harmonic rule 2ab/(a + b) with b infinitely stiff); E* and G* drop the rigid term.
[[nodiscard]] bool is_compliance_property(std::string_view key) noexcept;

/// Mixed pair properties of materials a and b: a property is set when both materials set it;
/// E* and G* are derived when both materials set E and ν. When one material is rigid, E*, G*
/// and the compliance properties come from the other alone (set when it sets them); two rigid
/// materials get none of them (two rigid bodies never touch: walls act on particles only).
PairProperties mix_properties(const MaterialProperties& a, const MaterialProperties& b,
                              const MixingRules& rules);

/// Copies every property set in `overrides` onto `base` (per-pair values from a case file).
void apply_overrides(PairProperties& base, const PairProperties& overrides) noexcept;

}  // namespace dem
