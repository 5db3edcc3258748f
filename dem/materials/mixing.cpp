// SPDX-License-Identifier: MIT
#include "dem/materials/mixing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace dem {
namespace {

constexpr std::array<std::pair<MixingRule, std::string_view>, 5> kRuleNames{{
    {MixingRule::harmonic, "harmonic"},
    {MixingRule::arithmetic, "arithmetic"},
    {MixingRule::geometric, "geometric"},
    {MixingRule::min, "min"},
    {MixingRule::max, "max"},
}};

}  // namespace

double mix_values(MixingRule rule, double a, double b) noexcept {
  if (a == b) return a;  // every rule is idempotent; keeps identical materials bit-exact
  switch (rule) {
    case MixingRule::harmonic: return 2.0 * a * b / (a + b);
    case MixingRule::arithmetic: return 0.5 * (a + b);
    case MixingRule::geometric: return std::sqrt(a * b);
    case MixingRule::min: return std::min(a, b);
    case MixingRule::max: return std::max(a, b);
    case MixingRule::derived: break;
  }
  return a;
}

std::string_view to_string(MixingRule rule) noexcept {
  if (rule == MixingRule::derived) return "derived";
  for (const auto& [r, name] : kRuleNames) {
    if (r == rule) return name;
  }
  return "?";
}

std::optional<MixingRule> parse_mixing_rule(std::string_view keyword) noexcept {
  for (const auto& [r, name] : kRuleNames) {
    if (name == keyword) return r;
  }
  return std::nullopt;
}

MixingRule rule_for(const MixingRules& rules, const PropertySpec& spec) noexcept {
  const auto it = rules.find(spec.key);
  return it == rules.end() ? spec.default_mixing : it->second;
}

bool is_compliance_property(std::string_view key) noexcept {
  return key == "normal_stiffness" || key == "tangential_stiffness" || key == "rolling_stiffness";
}

PairProperties mix_properties(const MaterialProperties& a, const MaterialProperties& b,
                              const MixingRules& rules) {
  PairProperties pair;
  // Against a rigid body only the compliant one deforms; two rigid bodies get no elastic values.
  const bool any_rigid = a.rigid || b.rigid;
  const bool one_rigid = a.rigid != b.rigid;
  const MaterialProperties& soft = a.rigid ? b : a;
  if (!any_rigid && a.youngs_modulus && a.poisson_ratio && b.youngs_modulus && b.poisson_ratio) {
    pair.effective_modulus =
        effective_modulus(*a.youngs_modulus, *a.poisson_ratio, *b.youngs_modulus, *b.poisson_ratio);
    pair.effective_shear_modulus = effective_shear_modulus(*a.youngs_modulus, *a.poisson_ratio,
                                                           *b.youngs_modulus, *b.poisson_ratio);
  } else if (one_rigid && soft.youngs_modulus && soft.poisson_ratio) {
    pair.effective_modulus = rigid_effective_modulus(*soft.youngs_modulus, *soft.poisson_ratio);
    pair.effective_shear_modulus = rigid_effective_shear_modulus(*soft.youngs_modulus, *soft.poisson_ratio);
  }
  for (const auto& spec : property_specs()) {
    if (spec.material_field == nullptr || spec.pair_field == nullptr) continue;
    const auto& va = a.*spec.material_field;
    const auto& vb = b.*spec.material_field;
    if (any_rigid && is_compliance_property(spec.key)) {
      // The harmonic rule 2ab/(a + b) with the rigid side infinitely stiff: 2k of the soft side.
      if (one_rigid && soft.*spec.material_field) pair.*spec.pair_field = 2.0 * *(soft.*spec.material_field);
    } else if (va && vb) {
      pair.*spec.pair_field = mix_values(rule_for(rules, spec), *va, *vb);
    }
  }
  return pair;
}

double rigid_effective_modulus(double e, double nu) noexcept { return e / (1.0 - nu * nu); }

double rigid_effective_shear_modulus(double e, double nu) noexcept {
  const double g = e / (2.0 * (1.0 + nu));
  return g / (2.0 - nu);
}

double effective_modulus(double e_p, double nu_p, double e_q, double nu_q) noexcept {
  return 1.0 / ((1.0 - nu_p * nu_p) / e_p + (1.0 - nu_q * nu_q) / e_q);
}

double effective_shear_modulus(double e_p, double nu_p, double e_q, double nu_q) noexcept {
  const double g_p = e_p / (2.0 * (1.0 + nu_p));
  const double g_q = e_q / (2.0 * (1.0 + nu_q));
  return 1.0 / ((2.0 - nu_p) / g_p + (2.0 - nu_q) / g_q);
}

void apply_overrides(PairProperties& base, const PairProperties& overrides) noexcept {
  for (const auto& spec : property_specs()) {
    if (spec.pair_field == nullptr) continue;
    if (const auto& v = overrides.*spec.pair_field) base.*spec.pair_field = *v;
  }
}

}  // namespace dem
