// SPDX-License-Identifier: MIT
#pragma once

#include "dem/particles/particles.hpp"

namespace dem {

/// Time derivative of a KinematicState: dx/dt, du/dt, dω/dt, and the angular velocity that
/// turns the orientation. Schemes combine these linearly.
struct Derivative {
  Vec3Array velocity;
  Vec3Array acceleration;
  Vec3Array angular_velocity;
  Vec3Array angular_acceleration;
};

/// The derivative at a state whose accelerations are `acc`.
[[nodiscard]] Derivative derivative_of(const KinematicState& state, const Accelerations& acc);

/// y += c·x, field by field.
void add_scaled(Derivative& y, double c, const Derivative& x);

/// c·x.
[[nodiscard]] Derivative scaled(double c, const Derivative& x);

/// out = base advanced by h along d: x += h·dx/dt, u += h·du/dt, …; the orientation turns by
/// the rotation vector h·ω_eff. With `rotation` false, ω and orientation keep base's values.
void advance(const KinematicState& base, double h, const Derivative& d, bool rotation,
             KinematicState& out);

/// Largest absolute component of a − b (∞-norm), 0 for empty arrays.
[[nodiscard]] double max_abs_difference(const Vec3Array& a, const Vec3Array& b) noexcept;

/// Rotation vector θ with exp(θ) ⊗ from = to, per sphere, divided by h (an angular velocity).
[[nodiscard]] Vec3Array orientation_rate(const std::vector<Quat>& from,
                                         const std::vector<Quat>& to, double h);

}  // namespace dem
