// SPDX-License-Identifier: MIT
#pragma once

#include "dem/core/vector.hpp"

namespace dem {

/// Kinematics of one sphere pair p–q at one instant (thesis eq 3.2–3.8, PHYSICS.md §2).
/// The normal points from q to p; a positive overlap means the bodies interpenetrate.
struct ContactGeometry {
  Vec3 normal;              ///< n = x_pq / |x_pq|
  double distance;          ///< |x_pq| [m]
  double overlap;           ///< body overlap δ = r_p + r_q − |x_pq| [m]
  double effect_overlap;    ///< effect overlap δ̂ = r̂_p + r̂_q − |x_pq| [m]
  Vec3 branch_p;            ///< a_p = −(r_p − δ/2) n, centre of p → contact point [m]
  Vec3 branch_q;            ///< a_q = +(r_q − δ/2) n, centre of q → contact point [m]
  Vec3 contact_velocity;    ///< u_c = (u_p + ω_p × a_p) − (u_q + ω_q × a_q) [m/s]
  double normal_speed;      ///< u_c · n [m/s], negative while approaching
  Vec3 tangential_velocity; ///< u_t = u_c − (u_c·n) n [m/s]
  double reduced_mass;      ///< m* [kg]; the mobile mass when the partner is fixed
  double reduced_radius;    ///< R* = r_p r_q / (r_p + r_q) [m]
};

/// Per-sphere inputs of `pair_geometry`. inverse_mass is 0 for a fixed sphere.
struct SphereState {
  Vec3 position;
  Vec3 velocity;
  Vec3 angular_velocity;
  double radius;
  double effect_radius;
  double inverse_mass;
};

/// Contact kinematics of p and q by the common-normal method (thesis §3.3.3). Coincident
/// centres (|x_pq| = 0) get the normal +x so the result stays finite.
[[nodiscard]] inline ContactGeometry pair_geometry(const SphereState& p,
                                                   const SphereState& q) noexcept {
  ContactGeometry g;
  const Vec3 x_pq = p.position - q.position;
  g.distance = x_pq.norm();
  g.normal = g.distance > 0.0 ? Vec3(x_pq / g.distance) : Vec3::UnitX();
  g.overlap = p.radius + q.radius - g.distance;
  g.effect_overlap = p.effect_radius + q.effect_radius - g.distance;
  g.branch_p = -(p.radius - 0.5 * g.overlap) * g.normal;
  g.branch_q = (q.radius - 0.5 * g.overlap) * g.normal;
  g.contact_velocity = (p.velocity + p.angular_velocity.cross(g.branch_p)) -
                       (q.velocity + q.angular_velocity.cross(g.branch_q));
  g.normal_speed = g.contact_velocity.dot(g.normal);
  g.tangential_velocity = g.contact_velocity - g.normal_speed * g.normal;
  g.reduced_mass = 1.0 / (p.inverse_mass + q.inverse_mass);
  g.reduced_radius = p.radius * q.radius / (p.radius + q.radius);
  return g;
}

}  // namespace dem
