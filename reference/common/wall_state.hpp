// SPDX-License-Identifier: MIT
#pragma once

#include "cases/scene.hpp"

namespace reference {

/// False for a wall removed at t ≤ 0: it stood only through the preparation (a shutter closed
/// while the bed settled), and a reference code's input leaves it out.
[[nodiscard]] inline bool wall_in_run(const cases::WallSpec& wall) noexcept {
  return !wall.removed_at || *wall.removed_at > 0.0;
}

/// True when the wall (or the mesh a facet belongs to) translates.
[[nodiscard]] inline bool wall_moves(const cases::WallSpec& wall) noexcept {
  return wall.velocity[0] != 0.0 || wall.velocity[1] != 0.0 || wall.velocity[2] != 0.0;
}

}  // namespace reference
