// SPDX-License-Identifier: MIT
#pragma once

#include "dem/particles/particles.hpp"

namespace dem {

/// Time derivative of a KinematicState: dx/dt, du/dt, dω/dt, and the angular velocity that
/// turns the orientation. Schemes combine these linearly, in preallocated workspaces.
struct Derivative {
  Vec3Array velocity;
  Vec3Array acceleration;
  Vec3Array angular_velocity;
  Vec3Array angular_acceleration;
};

/// out = the derivative at a state whose accelerations are `acc` (reuses out's storage).
void derivative_of(const KinematicState& state, const Accelerations& acc, Derivative& out);

/// y += c·x, field by field.
void add_scaled(Derivative& y, double c, const Derivative& x);

/// out = c·x (reuses out's storage).
void scale(double c, const Derivative& x, Derivative& out);

/// out = base advanced by h along d: x += h·dx/dt, u += h·du/dt, …; the orientation turns by
/// the rotation vector h·ω_eff when `orientation`. With `rotation` false, ω and orientation keep
/// base's values. Reuses out's storage (no allocation once out has the right size).
void advance(const KinematicState& base, double h, const Derivative& d, bool rotation,
             KinematicState& out, bool orientation = true);

/// Turns each orientation q by the rotation vector h·ω: q ← exp(h ω) ⊗ q (unit quaternion).
void turn_orientations(std::vector<Quat>& orientation, double h, const Vec3Array& angular_velocity);

/// Largest absolute component of a − b (∞-norm), 0 for empty arrays.
[[nodiscard]] double max_abs_difference(const Vec3Array& a, const Vec3Array& b) noexcept;

/// out = rotation vector θ with exp(θ) ⊗ from = to, per sphere, divided by h (an angular
/// velocity).
void orientation_rate(const std::vector<Quat>& from, const std::vector<Quat>& to, double h,
                      Vec3Array& out);

}  // namespace dem
