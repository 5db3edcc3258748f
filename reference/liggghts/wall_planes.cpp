// SPDX-License-Identifier: MIT
#include "reference/liggghts/wall_planes.hpp"

#include <fmt/format.h>

namespace reference::liggghts {
namespace {

constexpr const char* kAxes[] = {"x", "y", "z"};

std::string num(double v) { return fmt::format("{:.17g}", v); }

}  // namespace

std::optional<WallPlane> wall_plane(const cases::WallSpec& wall) {
  if (wall.shape != dem::WallShape::plane) return std::nullopt;
  for (int k = 0; k < 3; ++k) {
    const double nk = wall.normal[static_cast<std::size_t>(k)];
    if (nk != 1.0 && nk != -1.0) continue;
    bool others_zero = true;
    for (int j = 0; j < 3; ++j) {
      if (j != k && wall.normal[static_cast<std::size_t>(j)] != 0.0) others_zero = false;
    }
    if (others_zero) return WallPlane{k, nk, wall.point[static_cast<std::size_t>(k)]};
  }
  return std::nullopt;
}

bool wall_in_run(const cases::WallSpec& wall) noexcept { return !wall.removed_at || *wall.removed_at > 0.0; }

std::vector<std::string> unmapped_wall(const cases::WallSpec& wall, std::size_t index) {
  std::vector<std::string> reasons;
  if (!wall_in_run(wall)) return reasons;
  const std::string who = fmt::format("LIGGGHTS driver: wall {} ('{}')", index, wall.name);
  if (wall.shape != dem::WallShape::plane) {
    reasons.push_back(fmt::format("{} is a {}: only plane walls are mapped yet (primitive cylinders and STL meshes "
                                  "are LIGGGHTS' too)",
                                  who, cases::wall_shape_name(wall)));
  } else if (!wall_plane(wall)) {
    reasons.push_back(who + " is tilted: a primitive plane is xplane, yplane or zplane");
  }
  if (wall.velocity[0] != 0.0 || wall.velocity[1] != 0.0 || wall.velocity[2] != 0.0) {
    reasons.push_back(who + " moves: a primitive wall only has `shear`, a velocity without motion");
  }
  if (wall.removed_at) reasons.push_back(who + " is removed during the run: a LIGGGHTS fix stays");  // > 0 here
  return reasons;
}

std::string plane_arguments(const WallPlane& plane) {
  return fmt::format("{}plane {}", kAxes[plane.axis], num(plane.position));
}

std::string distance_formula(const WallPlane& plane, std::size_t id) {
  if (plane.sign > 0.0) return fmt::format("({}[{}]-{})", kAxes[plane.axis], id, num(plane.position));
  return fmt::format("({}-{}[{}])", num(plane.position), kAxes[plane.axis], id);
}

}  // namespace reference::liggghts
