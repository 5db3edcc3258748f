// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cases/scene.hpp"

namespace reference::liggghts {

/// A plane wall as `fix wall/gran … primitive type T xplane|yplane|zplane c` expresses it. LIGGGHTS'
/// primitive planes push from both sides; the core's from the side its normal points to.
struct WallPlane {
  int axis = 2;           ///< 0 = x, 1 = y, 2 = z
  double sign = 1.0;      ///< +1: the wall's normal is +axis, −1: −axis
  double position = 0.0;  ///< the plane's coordinate [m]
};

/// The primitive plane of `wall`, or empty when its normal is not ±(a unit axis) or it is no plane.
std::optional<WallPlane> wall_plane(const cases::WallSpec& wall);

/// False for a wall removed at t ≤ 0: it stood only through the preparation, and the deck leaves
/// it out.
[[nodiscard]] bool wall_in_run(const cases::WallSpec& wall) noexcept;

/// One reason per property of wall `index` the deck cannot express (any shape but an axis-aligned
/// plane, a moving wall, a removal during the run); none for a wall removed at t ≤ 0.
std::vector<std::string> unmapped_wall(const cases::WallSpec& wall, std::size_t index);

/// "zplane 0" for the plane.
std::string plane_arguments(const WallPlane& plane);

/// The signed distance of atom `id`'s centre from the plane along the wall's normal, as a
/// LIGGGHTS formula, e.g. "(z[1]-0)".
std::string distance_formula(const WallPlane& plane, std::size_t id);

}  // namespace reference::liggghts
