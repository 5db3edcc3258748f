// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cases/scene.hpp"
#include "reference/common/wall_state.hpp"

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

/// One reason per property of wall `index` that the deck cannot express (a tilted plane: fix
/// wall/gran has only xplane/yplane/zplane; a moving wall: only `wiggle`/`shear` motions exist; a
/// cylinder or cone about a tilted axis; a disc or rectangle; a removal during the run). None for a
/// wall removed at t ≤ 0, which the run never meets (wall_in_run).
std::vector<std::string> unmapped_wall(const cases::WallSpec& wall, std::size_t index);

/// Why this LAMMPS cannot take a mesh wall (unmapped_wall leaves its facets to this one reason).
[[nodiscard]] std::string unmapped_mesh(const cases::MeshSpec& mesh);

/// The `region` arguments of a cylinder or cone wall about a coordinate axis, open at both ends
/// and two-sided, for fix wall/gran/region, e.g. "cone z 0 0 0.006 0.015 0 0.003 side in open 1
/// open 2 units box"; empty for any other wall.
[[nodiscard]] std::optional<std::string> wall_region_arguments(const cases::WallSpec& wall);

/// "zplane 0 NULL" (or "xplane NULL 0.5", …) for the plane.
std::string wall_plane_arguments(const WallPlane& plane);

/// The signed distance of atom `id`'s centre from the plane, as a LAMMPS formula, e.g.
/// "(z[1]-0)" for a lower z wall.
std::string wall_distance_formula(const WallPlane& plane, std::size_t id);

}  // namespace reference::lammps
