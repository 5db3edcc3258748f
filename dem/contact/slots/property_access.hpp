// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "dem/core/model_error.hpp"
#include "dem/materials/material_properties.hpp"

namespace dem {

/// Value of a pair property a sub-model needs; throws ModelError naming the key when unset.
inline double required_property(const PairProperties& pair,
                                 std::optional<double> PairProperties::*field,
                                 std::string_view key, std::string_view who) {
  const auto& value = pair.*field;
  if (!value) {
    throw ModelError(std::string(key), std::string(who) + " needs '" + std::string(key) +
                                           "' for every material pair");
  }
  return *value;
}

}  // namespace dem
