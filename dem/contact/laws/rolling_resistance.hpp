// SPDX-License-Identifier: MIT
#pragma once

#include "dem/core/vector.hpp"

namespace dem::laws {

/// Rolling velocity of a contact, v_roll = R* (ω_p − ω_q) × n [m/s] (Wang et al., Particuology
/// 23 (2015) eq 31; LAMMPS pair granular). Only the part of ω_p − ω_q in the tangent plane
/// contributes (twisting about n does not). For a sphere rolling without slip on a plane wall
/// it points along the direction of travel with magnitude R* |ω|.
[[nodiscard]] inline Vec3 rolling_velocity(double reduced_radius, const Vec3& relative_angular_velocity,
                                           const Vec3& normal) noexcept {
  return reduced_radius * relative_angular_velocity.cross(normal);
}

/// Rolling-resistance torque on p from a rolling pseudo-force F_r acting at the contact:
/// τ_p = R* n × F_r [N·m]; q receives −τ_p (LAMMPS pair granular `rolling sds`).
[[nodiscard]] inline Vec3 rolling_torque(double reduced_radius, const Vec3& normal,
                                         const Vec3& pseudo_force) noexcept {
  return reduced_radius * normal.cross(pseudo_force);
}

/// Constant directional ("type A", Ai et al., Powder Technol. 206 (2011)) rolling torque on p:
/// τ_p = −μ_r R* F ω̂_r, ω_r the tangent-plane part of ω_p − ω_q, F ≥ 0 the friction-limit basis
/// [N], R* [m], μ_r [-]. Zero when ω_r = 0. Its sign follows ω_r, so once ω_r is about to
/// vanish it flips every step: a bounded chatter of |Δω| ≤ μ_r R* F Δt / I (see
/// docs/physics-tangential.md).
[[nodiscard]] inline Vec3 constant_rolling_torque(double rolling_friction, double reduced_radius,
                                                  double basis, const Vec3& relative_angular_velocity,
                                                  const Vec3& normal) noexcept {
  const Vec3 rolling = relative_angular_velocity - relative_angular_velocity.dot(normal) * normal;
  const double magnitude = rolling.norm();
  if (!(magnitude > 0.0)) return Vec3::Zero();
  return -(rolling_friction * reduced_radius * basis / magnitude) * rolling;
}

/// LIGGGHTS' constant directional rolling torque on p (`rolling_friction cdt`, LIGGGHTS-PUBLIC
/// 3.8.0 src/rolling_model_cdt.h): τ_p = −μ_r R* F_el (ω̂ − (ω̂·n) n), ω̂ the unit vector of the
/// whole relative spin ω_p − ω_q, F_el ≥ 0 the elastic normal force [N]. The twist part is dropped
/// after normalising, so the torque shrinks as ω_p − ω_q turns towards n (zero for pure twist);
/// it equals constant_rolling_torque when the spin lies in the tangent plane. Zero when
/// ω_p − ω_q = 0.
[[nodiscard]] inline Vec3 projected_rolling_torque(double rolling_friction, double reduced_radius,
                                                   double elastic_force, const Vec3& relative_angular_velocity,
                                                   const Vec3& normal) noexcept {
  const double magnitude = relative_angular_velocity.norm();
  if (!(magnitude > 0.0)) return Vec3::Zero();
  const Vec3 along = relative_angular_velocity * (rolling_friction * elastic_force * reduced_radius / magnitude);
  return -(along - along.dot(normal) * normal);
}

}  // namespace dem::laws
