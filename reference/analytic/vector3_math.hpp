// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>

#include "cases/core_vector.hpp"
#include "cases/scene.hpp"

// Small vector arithmetic on the case model's plain 3-vectors, and conversions to the core's.
namespace reference::analytic {

/// Relative tolerance of the solvers' collinearity checks (off_line against the vector's length).
inline constexpr double kCollinearTolerance = 1e-12;

using cases::case_vec;  // the core's 3-vector as the case model's
using cases::core_vec;  // the case model's 3-vector as the core's

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
