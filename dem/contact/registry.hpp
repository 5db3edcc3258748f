// SPDX-License-Identifier: MIT
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dem/materials/material_properties.hpp"

namespace dem {

/// The five slots of a contact model.
enum class Slot { normal, damping, tangential, cohesion, rolling };

/// All slots in evaluation order.
std::span<const Slot> all_slots() noexcept;

/// Case-file name of a slot ("normal", "damping", …).
std::string_view to_string(Slot slot) noexcept;

/// One registry row: what a sub-model is called, what it needs, and how the reference codes
/// express it. `reference/` reads its mappings from here so they cannot drift from the core.
struct SubModelInfo {
  std::string_view keyword;
  std::string_view description;
  std::vector<std::string_view> properties;  ///< pair properties it needs
  std::string_view lammps;                   ///< LAMMPS mapping, or why there is none
  std::string_view yade;                     ///< YADE mapping, or why there is none
  std::string_view liggghts;                 ///< LIGGGHTS mapping, or why there is none
};

/// Registry rows of a slot.
std::span<const SubModelInfo> sub_models(Slot slot);

/// Row of `keyword` in `slot`, or nullptr.
const SubModelInfo* find_sub_model(Slot slot, std::string_view keyword);

/// Keywords of a slot joined with ", " (for error messages).
std::string sub_model_keywords(Slot slot);

}  // namespace dem
