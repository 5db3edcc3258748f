// SPDX-License-Identifier: MIT
#include "reference/lammps/wall_mapping.hpp"

#include <fmt/format.h>

namespace reference::lammps {
namespace {

constexpr std::string_view kAxisNames[] = {"x", "y", "z"};

/// The coordinate axis ±e_k a unit vector is, or −1.
int coordinate_axis(const cases::Vector3& v) noexcept {
  for (int axis = 0; axis < 3; ++axis) {
    if (v[axis] != 1.0 && v[axis] != -1.0) continue;
    for (int k = 0; k < 3; ++k) {
      if (k != axis && v[k] != 0.0) return -1;
    }
    return axis;
  }
  return -1;
}

}  // namespace

std::optional<WallPlane> wall_plane(const cases::WallSpec& wall) {
  if (wall.shape != dem::WallShape::plane) return std::nullopt;
  const int axis = coordinate_axis(wall.normal);
  if (axis < 0) return std::nullopt;
  return WallPlane{axis, wall.normal[axis] > 0.0, wall.point[axis]};
}

std::vector<std::string> unmapped_wall(const cases::WallSpec& wall, std::size_t index) {
  std::vector<std::string> reasons;
  if (!wall_in_run(wall)) return reasons;
  switch (wall.shape) {
    case dem::WallShape::plane:
      if (!wall_plane(wall)) {
        reasons.push_back(fmt::format(
            "LAMMPS driver: wall {} ('{}') has normal ({}, {}, {}); fix wall/gran has only "
            "xplane/yplane/zplane walls",
            index, wall.name, wall.normal[0], wall.normal[1], wall.normal[2]));
      }
      break;
    case dem::WallShape::frustum:
      if (coordinate_axis(wall.normal) < 0) {
        reasons.push_back(fmt::format(
            "LAMMPS driver: wall {} ('{}') is a {} about the axis ({}, {}, {}); LAMMPS' cylinder and cone regions "
            "lie along x, y or z",
            index, wall.name, cases::wall_shape_name(wall), wall.normal[0], wall.normal[1], wall.normal[2]));
      }
      break;
    case dem::WallShape::annulus:
      reasons.push_back(fmt::format(
          "LAMMPS driver: wall {} ('{}') is a disc; fix wall/gran/region has no thin disc, and a floor with a hole "
          "built from region intersect or union misses the contacts on the hole's rim (a convex edge)",
          index, wall.name));
      break;
    case dem::WallShape::rectangle:
      reasons.push_back(fmt::format(
          "LAMMPS driver: wall {} ('{}') is a rectangle; fix wall/gran/region has no thin plate (a block region "
          "has a thickness and one side)",
          index, wall.name));
      break;
    case dem::WallShape::triangle:
      return reasons;  // a mesh's facets: one reason for the whole mesh (unmapped_mesh)
  }
  if (wall_moves(wall)) {
    reasons.push_back(fmt::format(
        "LAMMPS driver: wall {} ('{}') moves; fix wall/gran moves walls only by `wiggle` or "
        "`shear`, not at a constant normal velocity",
        index, wall.name));
  }
  if (wall.removed_at) {
    reasons.push_back(fmt::format(
        "LAMMPS driver: wall {} ('{}') is removed at {:.6g} s, during the run; that needs a second `run` after "
        "`unfix`, and fix wall/gran converts its Tsuji damping again at every `run` (the 29 Sep 2021 build)",
        index, wall.name, *wall.removed_at));
  }
  return reasons;
}

std::string unmapped_mesh(const cases::MeshSpec& mesh) {
  return fmt::format("LAMMPS driver: wall '{}' is a triangle mesh ({} facets from {}); this LAMMPS has no mesh wall "
                     "(fix wall/gran takes planes and fix wall/gran/region its region styles: block, cone, "
                     "cylinder, plane, prism, sphere and their unions)",
                     mesh.name, mesh.facets, mesh.file);
}

std::optional<std::string> wall_region_arguments(const cases::WallSpec& wall) {
  if (wall.shape != dem::WallShape::frustum) return std::nullopt;
  const int axis = coordinate_axis(wall.normal);
  if (axis < 0) return std::nullopt;
  // The axis runs from the base along ±e_axis; LAMMPS wants lo < hi with the radius at each.
  const double base = wall.point[axis];
  const double top = base + wall.normal[axis] * wall.length;
  const bool rising = top > base;
  const double lo = rising ? base : top;
  const double hi = rising ? top : base;
  const double r_lo = rising ? wall.size_u : wall.size_v;
  const double r_hi = rising ? wall.size_v : wall.size_u;
  // The two other coordinates of the axis, in LAMMPS' order (x: y z; y: x z; z: x y).
  const int c1 = axis == 0 ? 1 : 0;
  const int c2 = axis == 2 ? 1 : 2;
  const std::string where = fmt::format("{} {:.17g} {:.17g}", kAxisNames[axis], wall.point[c1], wall.point[c2]);
  const std::string shape = wall.size_u == wall.size_v
                                ? fmt::format("cylinder {} {:.17g} {:.17g} {:.17g}", where, wall.size_u, lo, hi)
                                : fmt::format("cone {} {:.17g} {:.17g} {:.17g} {:.17g}", where, r_lo, r_hi, lo, hi);
  return shape + " side in open 1 open 2 units box";
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
