// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cases/scene.hpp"

namespace reference::lammps {

/// A plane wall as `fix wall/gran … xplane|yplane|zplane lo hi` expresses it: a coordinate
/// plane that bounds the domain from below (normal +axis, `lo`) or above (normal −axis, `hi`).
struct WallPlane {
  int axis = 2;           ///< 0 = x, 1 = y, 2 = z
  bool lower = true;      ///< normal points along +axis (the wall is the domain's `lo`)
  double position = 0.0;  ///< the plane's coordinate [m]
};

/// The fix wall/gran plane of `wall`, or empty when its normal is not ±(a unit axis).
std::optional<WallPlane> wall_plane(const cases::WallSpec& wall);

/// One reason per property of wall `index` that fix wall/gran cannot express (a tilted normal:
/// only xplane/yplane/zplane exist; a moving wall: only `wiggle`/`shear` motions exist).
std::vector<std::string> unmapped_wall(const cases::WallSpec& wall, std::size_t index);

/// "zplane 0 NULL" (or "xplane NULL 0.5", …) for the plane.
std::string wall_plane_arguments(const WallPlane& plane);

/// The signed distance of atom `id`'s centre from the plane, as a LAMMPS formula, e.g.
/// "(z[1]-0)" for a lower z wall.
std::string wall_distance_formula(const WallPlane& plane, std::size_t id);

}  // namespace reference::lammps
