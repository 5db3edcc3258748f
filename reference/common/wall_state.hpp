// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

#include "cases/scene.hpp"

// What every driver asks of a case wall before it writes its code's input.
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

/// Where wall `k` stands among the walls in the run (walls removed at t ≤ 0 are left out of a
/// code's input, so the ones after them move up).
[[nodiscard]] inline std::size_t run_wall_index(const cases::Scene& scene, std::size_t k) noexcept {
  std::size_t index = 0;
  for (std::size_t j = 0; j < k && j < scene.walls.size(); ++j) index += wall_in_run(scene.walls[j]) ? 1 : 0;
  return index;
}

/// The first facet wall of mesh `mesh` (the facets share its motion, removal and material), or
/// null when it has none.
[[nodiscard]] inline const cases::WallSpec* first_facet(const cases::Scene& scene, std::size_t mesh) noexcept {
  for (const cases::WallSpec& w : scene.walls) {
    if (w.mesh == mesh) return &w;
  }
  return nullptr;
}

}  // namespace reference
