// SPDX-License-Identifier: MIT
#include "reference/lammps/wall_mapping.hpp"

#include <fmt/format.h>

namespace reference::lammps {
namespace {

constexpr std::string_view kAxisNames[] = {"x", "y", "z"};

}  // namespace

std::optional<WallPlane> wall_plane(const cases::WallSpec& wall) {
  for (int axis = 0; axis < 3; ++axis) {
    const double n = wall.normal[axis];
    if (n != 1.0 && n != -1.0) continue;
    bool others_zero = true;
    for (int k = 0; k < 3; ++k) {
      if (k != axis && wall.normal[k] != 0.0) others_zero = false;
    }
    if (!others_zero) return std::nullopt;
    return WallPlane{axis, n > 0.0, wall.point[axis]};
  }
  return std::nullopt;
}

std::vector<std::string> unmapped_wall(const cases::WallSpec& wall, std::size_t index) {
  std::vector<std::string> reasons;
  if (!wall_plane(wall)) {
    reasons.push_back(fmt::format(
        "LAMMPS driver: wall {} ('{}') has normal ({}, {}, {}); fix wall/gran has only "
        "xplane/yplane/zplane walls (and wall/gran/region is not written by this driver)",
        index, wall.name, wall.normal[0], wall.normal[1], wall.normal[2]));
  }
  if (wall.velocity[0] != 0.0 || wall.velocity[1] != 0.0 || wall.velocity[2] != 0.0) {
    reasons.push_back(fmt::format(
        "LAMMPS driver: wall {} ('{}') moves; fix wall/gran moves walls only by `wiggle` or "
        "`shear`, not at a constant normal velocity",
        index, wall.name));
  }
  return reasons;
}

std::string wall_plane_arguments(const WallPlane& plane) {
  const std::string at = fmt::format("{:.17g}", plane.position);
  return fmt::format("{}plane {} {}", kAxisNames[plane.axis], plane.lower ? at : "NULL",
                     plane.lower ? "NULL" : at);
}

std::string wall_distance_formula(const WallPlane& plane, std::size_t id) {
  const std::string coordinate = fmt::format("{}[{}]", kAxisNames[plane.axis], id);
  return plane.lower ? fmt::format("({}-{:.17g})", coordinate, plane.position)
                     : fmt::format("({:.17g}-{})", plane.position, coordinate);
}

}  // namespace reference::lammps
