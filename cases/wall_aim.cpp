// SPDX-License-Identifier: MIT
// Velocities aimed at a wall: the wall a value names, the in-plane heading of a direction, and a
// particle's initial velocity given as a speed and an incidence angle to a wall's normal.
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "cases/excerpt.hpp"
#include "cases/loader_sections.hpp"

namespace cases::loader {
namespace {

constexpr auto kAimedVelocityKeys = std::to_array<std::string_view>({"speed", "wall", "incidence", "direction"});

}  // namespace

void require_plane_wall(const Value& v, const WallSpec& wall, std::string_view use) {
  if (wall.shape == dem::WallShape::plane) return;
  v.fail(fmt::format("wall '{}' is a {}; {} needs a plane wall (one fixed normal)", excerpt(wall.name),
                     wall_shape_name(wall), use));
}

std::size_t wall_index(const Value& v, const Scene& scene) {
  if (scene.walls.empty()) v.fail("the case has no [[walls]] to aim at");
  std::size_t w = scene.walls.size();
  if (v.node().is_string()) {
    const std::string name = v.string();
    for (std::size_t k = 0; k < scene.walls.size() && w == scene.walls.size(); ++k) {
      if (scene.walls[k].name == name) w = k;
    }
    if (w == scene.walls.size()) {
      std::string known;
      for (const WallSpec& wall : scene.walls) known += (known.empty() ? "'" : ", '") + wall.name + "'";
      v.fail(fmt::format("no wall is named '{}' (walls: {})", excerpt(name), known));
    }
  } else {
    w = v.index(scene.walls.size(), "walls");
  }
  require_plane_wall(v, scene.walls[w], "aiming at a wall");
  return w;
}

Vector3 in_plane_direction(const Value& direction, const WallSpec& wall) {
  Vector3 d = direction.vector3();
  // A direction whose squares overflow or underflow is scaled to unit length first, so that the
  // projection below stays finite (ordinary ones keep their bits).
  if (const double squares = d[0] * d[0] + d[1] * d[1] + d[2] * d[2]; !std::isnormal(squares)) {
    const double n = length(d);
    if (n > 0.0) {
      for (double& c : d) c /= n;
    }
  }
  // The in-plane part of `direction`: its component along the wall normal is removed.
  const double along = d[0] * wall.normal[0] + d[1] * wall.normal[1] + d[2] * wall.normal[2];
  for (std::size_t k = 0; k < 3; ++k) d[k] -= along * wall.normal[k];
  const double norm = length(d);
  if (!(norm > 1e-9)) {
    direction.fail(fmt::format("has no component in the plane of wall '{}' (normal [{}, {}, {}]); give a "
                               "direction along the wall",
                               wall.name, wall.normal[0], wall.normal[1], wall.normal[2]));
  }
  for (double& c : d) c /= norm;
  return d;
}

Vector3 read_initial_velocity(const Value& value, const Scene& scene) {
  if (!value.node().is_table()) return read_velocity(value);
  const Table t = value.table();
  t.allow_only(kAimedVelocityKeys);
  const Value speed_value = t.require("speed");
  const double speed = speed_value.number(positive_range());
  check_speed(speed_value, speed, "speed");
  const WallSpec& wall = scene.walls[wall_index(t.require("wall"), scene)];
  const double incidence = t.require("incidence").number(dem::ValueRange{0.0, 90.0, false, true});
  Vector3 heading{0.0, 0.0, 0.0};
  if (const auto d = t.find("direction")) {
    heading = in_plane_direction(*d, wall);
  } else if (incidence > 0.0) {
    t.fail("direction", fmt::format("missing: an incidence of {} degrees needs a heading along the wall", incidence));
  }
  // u = speed (sin θ t̂ − cos θ n): θ from the normal, towards the wall (n points away from it).
  const double theta = incidence * std::numbers::pi / 180.0;
  const double along_plane = speed * std::sin(theta);
  const double into_wall = speed * std::cos(theta);
  Vector3 u{};
  for (std::size_t k = 0; k < 3; ++k) u[k] = along_plane * heading[k] - into_wall * wall.normal[k];
  return u;
}

}  // namespace cases::loader
