// SPDX-License-Identifier: MIT
#include "reference/liggghts/primitive_walls.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace reference::liggghts {
namespace {

constexpr const char* kAxes[] = {"x", "y", "z"};

std::string exact(double v) { return fmt::format("{:.17g}", v); }

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

std::optional<WallCylinder> wall_cylinder(const cases::WallSpec& wall) {
  if (wall.shape != dem::WallShape::frustum || wall.size_u != wall.size_v) return std::nullopt;
  for (int k = 0; k < 3; ++k) {
    const double ak = wall.normal[static_cast<std::size_t>(k)];
    if (ak != 1.0 && ak != -1.0) continue;
    bool others_zero = true;
    for (int j = 0; j < 3; ++j) {
      if (j != k && wall.normal[static_cast<std::size_t>(j)] != 0.0) others_zero = false;
    }
    if (!others_zero) continue;
    const double base = wall.point[static_cast<std::size_t>(k)];
    const double end = base + ak * wall.length;
    return WallCylinder{k, wall.size_u, wall.point[static_cast<std::size_t>((k + 1) % 3)],
                        wall.point[static_cast<std::size_t>((k + 2) % 3)], std::min(base, end), std::max(base, end)};
  }
  return std::nullopt;
}

std::string primitive_arguments(const cases::WallSpec& wall) {
  if (const auto plane = wall_plane(wall)) return plane_arguments(*plane);
  if (const auto cylinder = wall_cylinder(wall)) return cylinder_arguments(*cylinder);
  return {};
}

std::vector<std::string> cylinder_end_reasons(const cases::Scene& scene, std::size_t index) {
  std::vector<std::string> reasons;
  const auto c = wall_cylinder(scene.walls.at(index));
  if (!c || !wall_in_run(scene.walls.at(index))) return reasons;
  const auto a = static_cast<std::size_t>(c->axis);
  for (std::size_t p = 0; p < scene.particles.size(); ++p) {
    const cases::ParticleSpec& s = scene.particles[p];
    if (s.fixed) continue;
    const double along = s.position[a];
    if (along >= c->low && along <= c->high) continue;
    const double d1 = s.position[(a + 1) % 3] - c->first;
    const double d2 = s.position[(a + 2) % 3] - c->second;
    const double gap = std::abs(std::sqrt(d1 * d1 + d2 * d2) - c->radius) - s.radius;
    if (gap < 0.0) {
      reasons.push_back(fmt::format("LIGGGHTS driver: particle {} starts beyond an end of cylinder wall {} ('{}') "
                                    "but touching its surface extended: LIGGGHTS' primitive cylinder is unbounded",
                                    p, index, scene.walls[index].name));
    }
  }
  return reasons;
}

std::vector<std::string> unmapped_wall(const cases::WallSpec& wall, std::size_t index) {
  std::vector<std::string> reasons;
  if (!wall_in_run(wall)) return reasons;
  const std::string who = fmt::format("LIGGGHTS driver: wall {} ('{}')", index, wall.name);
  const std::string_view shape = cases::wall_shape_name(wall);
  if (shape == "cylinder") {
    if (!wall_cylinder(wall)) {
      reasons.push_back(who + " is tilted: a primitive cylinder is xcylinder, ycylinder or zcylinder");
    }
  } else if (wall.shape != dem::WallShape::plane) {
    reasons.push_back(fmt::format("{} is a {}: only plane and cylinder walls are mapped yet (LIGGGHTS' STL meshes "
                                  "would take the others)",
                                  who, shape));
  } else if (!wall_plane(wall)) {
    reasons.push_back(who + " is tilted: a primitive plane is xplane, yplane or zplane");
  }
  if (wall_moves(wall)) {
    reasons.push_back(who + " moves: a primitive wall only has `shear`, a velocity without motion");
  }
  if (wall.removed_at) reasons.push_back(who + " is removed during the run: a LIGGGHTS fix stays");  // > 0 here
  return reasons;
}

std::string plane_arguments(const WallPlane& plane) {
  return fmt::format("{}plane {}", kAxes[plane.axis], exact(plane.position));
}

std::string cylinder_arguments(const WallCylinder& c) {
  return fmt::format("{}cylinder {} {} {}", kAxes[c.axis], exact(c.radius), exact(c.first), exact(c.second));
}

std::string distance_formula(const WallPlane& plane, std::size_t id) {
  if (plane.sign > 0.0) return fmt::format("({}[{}]-{})", kAxes[plane.axis], id, exact(plane.position));
  return fmt::format("({}-{}[{}])", exact(plane.position), kAxes[plane.axis], id);
}

}  // namespace reference::liggghts
