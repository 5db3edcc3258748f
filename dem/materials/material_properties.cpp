// SPDX-License-Identifier: MIT
#include "dem/materials/material_properties.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace dem {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

const std::array kSpecs{
    PropertySpec{"normal_stiffness", "N/m", "linear normal stiffness k_e (eq 3.10)",
                 ValueRange{0.0, kInf, true, true}, &MaterialProperties::normal_stiffness, &PairProperties::normal_stiffness, MixingRule::harmonic},
    PropertySpec{"restitution", "-", "normal coefficient of restitution ε (eq 3.11)",
                 ValueRange{0.0, 1.0, true, false}, &MaterialProperties::restitution, &PairProperties::restitution, MixingRule::geometric},
    PropertySpec{"youngs_modulus", "Pa", "Young's modulus E (eq 3.13)",
                 ValueRange{0.0, kInf, true, true}, &MaterialProperties::youngs_modulus, nullptr, MixingRule::derived},
    PropertySpec{"poisson_ratio", "-", "Poisson's ratio ν (eq 3.13)",
                 ValueRange{-1.0, 0.5, true, true}, &MaterialProperties::poisson_ratio, nullptr, MixingRule::derived},
    PropertySpec{"effective_modulus", "Pa", "reduced modulus E* = [(1−ν_p²)/E_p + (1−ν_q²)/E_q]⁻¹ (eq 3.13)",
                 ValueRange{0.0, kInf, true, true}, nullptr, &PairProperties::effective_modulus, MixingRule::derived},
    PropertySpec{"effective_shear_modulus", "Pa", "G* = [(2−ν_p)/G_p + (2−ν_q)/G_q]⁻¹, G = E/(2(1+ν)) (eq 3.25)",
                 ValueRange{0.0, kInf, true, true}, nullptr, &PairProperties::effective_shear_modulus, MixingRule::derived},
    PropertySpec{"tangential_stiffness", "N/m", "tangential spring stiffness k_f (eq 3.24)",
                 ValueRange{0.0, kInf, true, true}, &MaterialProperties::tangential_stiffness, &PairProperties::tangential_stiffness, MixingRule::harmonic},
    PropertySpec{"tangential_damping_ratio", "-", "tangential dashpot as a fraction of the normal one, η_t/η_n (eq 3.26)",
                 ValueRange{0.0, kInf, false, true}, &MaterialProperties::tangential_damping_ratio, &PairProperties::tangential_damping_ratio, MixingRule::arithmetic},
    PropertySpec{"friction", "-", "Coulomb friction coefficient μ (eq 3.23)",
                 ValueRange{0.0, kInf, false, true}, &MaterialProperties::friction, &PairProperties::friction, MixingRule::min},
    PropertySpec{"rolling_friction", "-", "rolling friction coefficient μ_r",
                 ValueRange{0.0, kInf, false, true}, &MaterialProperties::rolling_friction, &PairProperties::rolling_friction, MixingRule::min},
    PropertySpec{"rolling_stiffness", "N/m", "rolling spring stiffness k_r (spring–dashpot–slider)",
                 ValueRange{0.0, kInf, false, true}, &MaterialProperties::rolling_stiffness, &PairProperties::rolling_stiffness, MixingRule::harmonic},
    PropertySpec{"rolling_damping", "kg/s", "rolling dashpot γ_r (spring–dashpot–slider)",
                 ValueRange{0.0, kInf, false, true}, &MaterialProperties::rolling_damping, &PairProperties::rolling_damping, MixingRule::arithmetic},
    PropertySpec{"cohesive_stiffness", "N/m", "linear cohesion stiffness k_c (eq 3.33)",
                 ValueRange{0.0, kInf, false, true}, &MaterialProperties::cohesive_stiffness, &PairProperties::cohesive_stiffness, MixingRule::harmonic},
    PropertySpec{"surface_energy", "J/m²", "surface energy γ per surface; work of adhesion Γ = 2γ (eq 3.34)",
                 ValueRange{0.0, kInf, false, true}, &MaterialProperties::surface_energy, &PairProperties::surface_energy, MixingRule::geometric},
    PropertySpec{"interaction_ratio", "-", "effect radius over body radius λ = r̂/r (eq 3.33); default effect radius",
                 ValueRange{1.0, kInf, false, true}, &MaterialProperties::interaction_ratio, nullptr, MixingRule::max},
    PropertySpec{"damping_coefficient", "kg/s", "normal dashpot coefficient η given directly",
                 ValueRange{0.0, kInf, false, true}, &MaterialProperties::damping_coefficient, &PairProperties::damping_coefficient, MixingRule::arithmetic},
    PropertySpec{"viscous_modulus", "Pa·s", "dissipative modulus E' of the Kuwabara–Kono dashpot η = 2 E' √(R* δ) (eq 3.14)",
                 ValueRange{0.0, kInf, false, true}, &MaterialProperties::viscous_modulus, &PairProperties::viscous_modulus, MixingRule::arithmetic},
    PropertySpec{"damping_rate", "1/s", "mass-scaled normal dashpot η/m*",
                 ValueRange{0.0, kInf, false, true}, &MaterialProperties::damping_rate, &PairProperties::damping_rate, MixingRule::arithmetic},
    PropertySpec{"viscoelastic_damping", "1/(m·s)", "η_0 of the viscoelastic dashpot η = η_0 a m*",
                 ValueRange{0.0, kInf, false, true}, &MaterialProperties::viscoelastic_damping, &PairProperties::viscoelastic_damping, MixingRule::arithmetic},
    PropertySpec{"relative_permittivity", "-", "relative permittivity ε_r of the medium (eq 3.36)",
                 ValueRange{0.0, kInf, true, true}, &MaterialProperties::relative_permittivity, &PairProperties::relative_permittivity, MixingRule::geometric},
    PropertySpec{"coulomb_cutoff", "m", "centre distance beyond which the Coulomb force is zero",
                 ValueRange{0.0, kInf, true, true}, &MaterialProperties::coulomb_cutoff, &PairProperties::coulomb_cutoff, MixingRule::max},
    PropertySpec{"potential_exponent", "-", "exponent a of the Langston potential (eq 3.17)",
                 ValueRange{0.0, kInf, true, true}, &MaterialProperties::potential_exponent, &PairProperties::potential_exponent, MixingRule::arithmetic},
    PropertySpec{"potential_critical_ratio", "-", "d_crit/d of the Langston potential (eq 3.17)",
                 ValueRange{1.0, kInf, true, true}, &MaterialProperties::potential_critical_ratio, &PairProperties::potential_critical_ratio, MixingRule::arithmetic},
    PropertySpec{"potential_gravity", "m/s²", "g in ε_p = d m* g / a (eq 3.19)",
                 ValueRange{0.0, kInf, true, true}, &MaterialProperties::potential_gravity, &PairProperties::potential_gravity, MixingRule::arithmetic},
};

std::string format_bound(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

std::string ValueRange::describe() const {
  return std::string(min_open ? "(" : "[") + format_bound(min) + ", " + format_bound(max) +
         (max_open ? ")" : "]");
}

std::span<const PropertySpec> property_specs() noexcept { return kSpecs; }

const PropertySpec* find_property_spec(std::string_view key) noexcept {
  for (const auto& spec : kSpecs) {
    if (spec.key == key) return &spec;
  }
  return nullptr;
}

ValueRange density_range() noexcept { return ValueRange{0.0, kInf, true, true}; }

}  // namespace dem
