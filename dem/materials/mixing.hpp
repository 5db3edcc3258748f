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

/// Mixed pair properties of materials a and b: a property is set when both materials set it.
PairProperties mix_properties(const MaterialProperties& a, const MaterialProperties& b,
                              const MixingRules& rules);

/// Copies every property set in `overrides` onto `base` (per-pair values from a case file).
void apply_overrides(PairProperties& base, const PairProperties& overrides) noexcept;

}  // namespace dem
