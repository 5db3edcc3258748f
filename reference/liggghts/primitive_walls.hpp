// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cases/scene.hpp"
#include "reference/common/wall_state.hpp"

namespace reference::liggghts {

// The case's walls as LIGGGHTS 3.8 primitive walls (`fix wall/gran … primitive type T …`,
// primitive_wall_definitions.h): axis-aligned planes and cylinders.

/// A plane wall as `fix wall/gran … primitive type T xplane|yplane|zplane c` expresses it. LIGGGHTS'
/// primitive planes push from both sides; the core's from the side its normal points to.
struct WallPlane {
  int axis = 2;           ///< 0 = x, 1 = y, 2 = z
  double sign = 1.0;      ///< +1: the wall's normal is +axis, −1: −axis
  double position = 0.0;  ///< the plane's coordinate [m]
};

/// The primitive plane of `wall`, or empty when its normal is not ±(a unit axis) or it is no plane.
std::optional<WallPlane> wall_plane(const cases::WallSpec& wall);

/// A cylinder wall as `… primitive type T xcylinder|ycylinder|zcylinder R c1 c2` expresses it.
/// LIGGGHTS' primitive cylinders are unbounded and push from both sides (primitive_wall_definitions.h
/// 159–197); the core's is the lateral surface between its ends, so the two agree while every
/// sphere stays between the ends.
struct WallCylinder {
  int axis = 2;           ///< 0 = x, 1 = y, 2 = z
  double radius = 0.0;    ///< R [m]
  double first = 0.0;     ///< the axis' coordinate along (axis + 1) mod 3 [m] (LIGGGHTS' order)
  double second = 0.0;    ///< along (axis + 2) mod 3 [m]
  double low = 0.0;       ///< the ends along the axis [m]
  double high = 0.0;
};

/// The primitive cylinder of `wall`, or empty when it is no cylinder or its axis is not ±(a unit axis).
std::optional<WallCylinder> wall_cylinder(const cases::WallSpec& wall);

/// "zplane 0" or "zcylinder 0.01 0 0": the primitive's words for a plane or cylinder wall, empty
/// for any other.
std::string primitive_arguments(const cases::WallSpec& wall);

/// One reason per mobile sphere of `scene` that starts beyond an end of cylinder wall `index`
/// yet within reach of its unbounded surface: LIGGGHTS would push it, the core not.
std::vector<std::string> cylinder_end_reasons(const cases::Scene& scene, std::size_t index);

/// One reason per property of wall `index` the deck cannot express (any shape but an axis-aligned
/// plane or cylinder, a moving wall, a removal during the run); none for a wall removed at t ≤ 0.
std::vector<std::string> unmapped_wall(const cases::WallSpec& wall, std::size_t index);

/// "zplane 0" for the plane.
std::string plane_arguments(const WallPlane& plane);
/// "zcylinder 0.01 0 0" for the cylinder.
std::string cylinder_arguments(const WallCylinder& cylinder);

/// The signed distance of atom `id`'s centre from the plane along the wall's normal, as a
/// LIGGGHTS formula, e.g. "(z[1]-0)".
std::string distance_formula(const WallPlane& plane, std::size_t id);

}  // namespace reference::liggghts
