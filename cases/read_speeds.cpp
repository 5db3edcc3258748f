// SPDX-License-Identifier: MIT
// Readers of speeds, bounded by the speed of light (docs/case-format.md, "Limits").
#include <cmath>

#include <fmt/format.h>

#include "cases/limits.hpp"
#include "cases/loader_sections.hpp"

namespace cases::loader {

double length(const Vector3& v) noexcept {
  const double squares = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  return std::isnormal(squares) ? std::sqrt(squares) : std::hypot(v[0], v[1], v[2]);
}

void check_speed(const Value& value, double speed, std::string_view what) {
  if (speed < kSpeedOfLight) return;
  value.fail(fmt::format("the {} = {:.6g} m/s is not below the speed of light ({} m/s)", what, speed, kSpeedOfLight));
}

Vector3 read_velocity(const Value& value) {
  const Vector3 v = value.vector3();
  check_speed(value, length(v), "speed |v|");
  return v;
}

void check_surface_speed(const Value& value, const Vector3& angular_velocity, double radius) {
  check_speed(value, length(angular_velocity) * radius, "surface speed |ω| r");
}

}  // namespace cases::loader
