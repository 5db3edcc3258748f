// SPDX-License-Identifier: MIT
#pragma once
// What a reference code's driver tells the rest of the workbench about its numerics, so that the
// matched engine can reproduce them without including the driver (docs/architecture.md, "Layers").

#include <string_view>

#include "cases/scene.hpp"
#include "reference/common/prepared_scene.hpp"

namespace reference {

/// A reference code's numerics as the in-house core can adopt them: the driver exports one of
/// these, the registry hands it to the matched engine ("inhouse@<code>").
struct CodeConventions {
  std::string_view code;  ///< the code's engine name: "lammps", "yade"
  /// A copy of the prepared scene that the core runs to reproduce the code's integrator, velocity convention
  /// and force formulas (docs/engines.md, "Native and matched comparisons"). Throws
  /// std::invalid_argument with the reason when the code's numerics cannot be matched.
  cases::Scene (*matched_scene)(const PreparedScene& prepared);
};

}  // namespace reference
