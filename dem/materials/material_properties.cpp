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
                 ValueRange{0.0, kInf, true, true}, &MaterialProperties::normal_stiffness,
                 &PairProperties::normal_stiffness, MixingRule::harmonic},
    PropertySpec{"restitution", "-", "normal coefficient of restitution ε (eq 3.11)",
                 ValueRange{0.0, 1.0, true, false}, &MaterialProperties::restitution,
                 &PairProperties::restitution, MixingRule::geometric},
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
