// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>

#include "cases/scene.hpp"
#include "dem/core/vector.hpp"

// Small vector arithmetic on the case model's plain 3-vectors, and conversions to the core's.
namespace reference::analytic {

/// Relative tolerance of the solvers' collinearity checks (off_line against the vector's length).
inline constexpr double kCollinearTolerance = 1e-12;

/// The case model's 3-vector as the core's.
inline dem::Vec3 vec(const cases::Vector3& a) noexcept { return {a[0], a[1], a[2]}; }
/// The core's 3-vector as the case model's.
inline cases::Vector3 arr(const dem::Vec3& a) noexcept { return {a.x(), a.y(), a.z()}; }

/// a − b.
inline cases::Vector3 minus(const cases::Vector3& a, const cases::Vector3& b) noexcept {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
/// f a.
inline cases::Vector3 scaled(const cases::Vector3& a, double f) noexcept {
  return {a[0] * f, a[1] * f, a[2] * f};
}
/// a · b.
inline double dot(const cases::Vector3& a, const cases::Vector3& b) noexcept {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
/// |a|.
inline double norm(const cases::Vector3& a) noexcept { return std::sqrt(dot(a, a)); }
/// Length of the part of v perpendicular to the unit vector e.
inline double off_line(const cases::Vector3& v, const cases::Vector3& e) noexcept {
  return norm(minus(v, scaled(e, dot(v, e))));
}

}  // namespace reference::analytic
