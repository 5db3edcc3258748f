// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/model_choice.hpp"
#include "dem/contact/wall.hpp"
#include "dem/core/vector.hpp"

namespace dem {

/// Kinematics of one sphere pair p–q at one instant (thesis eq 3.2–3.8; docs/physics.md).
/// The normal points from q to p; a positive overlap means the bodies interpenetrate.
struct ContactGeometry {
  Vec3 normal;              ///< n = x_pq / |x_pq|
  double distance;          ///< |x_pq| [m]
  double overlap;           ///< body overlap δ = r_p + r_q − |x_pq| [m]
  double effect_overlap;    ///< effect overlap δ̂ = r̂_p + r̂_q − |x_pq| [m]
  Vec3 branch_p;            ///< a_p = −(r_p − δ/2) n (or −r_p n), centre of p → contact point [m]
  Vec3 branch_q;            ///< a_q = +(r_q − δ/2) n (or +r_q n), centre of q → contact point [m]
  Vec3 contact_velocity;    ///< u_c = (u_p + ω_p × a_p) − (u_q + ω_q × a_q) [m/s]
  double normal_speed;      ///< u_c · n [m/s], negative while approaching
  Vec3 tangential_velocity; ///< u_t = u_c − (u_c·n) n [m/s]
  Vec3 relative_angular_velocity;  ///< ω_p − ω_q [rad/s]
  Vec3 angular_velocity_sum;       ///< ω_p + ω_q [rad/s] (ω_p against a wall)
  double reduced_mass;      ///< m* [kg]; the mobile mass when the partner is fixed
  double reduced_radius;    ///< R* = r_p r_q / (r_p + r_q) [m]; r against a plane wall
  double contact_distance;  ///< r_p + r_q [m] (r for a wall): centre distance at first touch
  double effect_distance;   ///< r̂_p + r̂_q [m] (r̂ for a wall)
  double charge_product;    ///< q_p q_q [C²] (0 for a wall)
  bool against_wall = false;  ///< q is a wall (wall_geometry), not a sphere
};

/// The extent of a pair that sets how far its law reaches (for neighbour search).
struct PairExtent {
  double contact_distance;  ///< r_p + r_q [m]
  double effect_distance;   ///< r̂_p + r̂_q [m]
  double reduced_radius;    ///< R* [m]
};

/// Per-sphere inputs of `pair_geometry`. inverse_mass is 0 for a fixed sphere.
struct SphereState {
  Vec3 position;
  Vec3 velocity;
  Vec3 angular_velocity;
  double radius;
  double effect_radius;
  double inverse_mass;
  double charge = 0.0;  ///< [C]
};

/// The tangential velocity YADE integrates into the shear (docs/physics-tangential.md): the
/// tangential part of α u_centres − (r_p ω_p + r_q ω_q) × n, given the unscaled one `unscaled`
/// (spins with the radii) and the centres' relative velocity `centres`.
[[nodiscard]] inline Vec3 yade_tangential_velocity(const Vec3& unscaled, const Vec3& centres, const Vec3& normal,
                                                   double alpha) noexcept {
  const Vec3 centres_t = centres - centres.dot(normal) * normal;
  return unscaled + (alpha - 1.0) * centres_t;
}

/// Contact kinematics of p and q by the common-normal method (thesis §3.3.3). Coincident
/// centres (|x_pq| = 0) get the normal +x so the result stays finite. The lever arms (the
/// branches, which the torque uses) are r − δ/2, or the radii r for PairLeverArm::radius (LAMMPS
/// gran/hooke/history); the contact-point velocity uses the same arms, except under
/// PairLeverArm::radius_velocity and yade_incident, where it uses r (LAMMPS pair granular, YADE),
/// and yade_incident scales the centres' part of the tangential velocity by α. q is passed at
/// its periodic image nearest p.
[[nodiscard]] inline ContactGeometry pair_geometry(const SphereState& p, const SphereState& q,
                                                   PairLeverArm arm = PairLeverArm::contact_point) noexcept {
  const bool lever_arm_is_radius = arm == PairLeverArm::radius;
  ContactGeometry g;
  const Vec3 x_pq = p.position - q.position;
  g.distance = x_pq.norm();
  g.normal = g.distance > 0.0 ? Vec3(x_pq / g.distance) : Vec3::UnitX();
  g.overlap = p.radius + q.radius - g.distance;
  g.effect_overlap = p.effect_radius + q.effect_radius - g.distance;
  g.branch_p = -(lever_arm_is_radius ? p.radius : p.radius - 0.5 * g.overlap) * g.normal;
  g.branch_q = (lever_arm_is_radius ? q.radius : q.radius - 0.5 * g.overlap) * g.normal;
  if (arm == PairLeverArm::radius_velocity || arm == PairLeverArm::yade_incident) {
    g.contact_velocity = (p.velocity - p.radius * p.angular_velocity.cross(g.normal)) -
                         (q.velocity + q.radius * q.angular_velocity.cross(g.normal));
  } else {
    g.contact_velocity = (p.velocity + p.angular_velocity.cross(g.branch_p)) -
                         (q.velocity + q.angular_velocity.cross(g.branch_q));
  }
  g.normal_speed = g.contact_velocity.dot(g.normal);
  g.tangential_velocity = g.contact_velocity - g.normal_speed * g.normal;
  if (arm == PairLeverArm::yade_incident) {
    g.tangential_velocity =
        yade_tangential_velocity(g.tangential_velocity, p.velocity - q.velocity, g.normal,
                                 laws::incident_velocity_scale(p.radius + q.radius, g.overlap));
  }
  g.relative_angular_velocity = p.angular_velocity - q.angular_velocity;
  g.angular_velocity_sum = p.angular_velocity + q.angular_velocity;
  g.reduced_mass = 1.0 / (p.inverse_mass + q.inverse_mass);
  g.reduced_radius = p.radius * q.radius / (p.radius + q.radius);
  g.contact_distance = p.radius + q.radius;
  g.effect_distance = p.effect_radius + q.effect_radius;
  g.charge_product = p.charge * q.charge;
  return g;
}

/// Kinematics of sphere p against a wall at time t (the wall acts as an infinite-mass
/// partner: m* = m, R* = r). The normal and distance are wall_frame's (a plane's own normal);
/// the lever arm is r − δ/2 (common normal,
/// and WallLeverArm::yade_incident) or r (WallLeverArm::radius, LAMMPS fix wall/gran); the
/// contact-point velocity uses the same arm, except under yade_incident against any wall but a
/// mesh facet (see WallLeverArm).
[[nodiscard]] inline ContactGeometry wall_geometry(const SphereState& p, const Wall& w,
                                                   double t, WallLeverArm arm) noexcept {
  // YADE's facet functor (Ig2_Facet_Sphere_ScGeom) takes the velocity of the contact point at
  // r − δ/2 without α, which is the common-normal rule; only its plane wall scales by α.
  if (arm == WallLeverArm::yade_incident && w.shape == WallShape::triangle) arm = WallLeverArm::contact_point;
  const bool lever_arm_is_radius = arm == WallLeverArm::radius;
  ContactGeometry g;
  const WallFrame frame = wall_frame(w, p.position, t);
  g.normal = frame.normal;
  g.distance = frame.distance;
  g.overlap = p.radius - frame.distance;
  g.effect_overlap = p.effect_radius - frame.distance;
  g.branch_p = -(lever_arm_is_radius ? p.radius : p.radius - 0.5 * g.overlap) * g.normal;
  g.branch_q = Vec3::Zero();
  if (arm == WallLeverArm::yade_incident) {
    g.contact_velocity = p.velocity - p.radius * p.angular_velocity.cross(g.normal) - w.velocity;
  } else {
    g.contact_velocity = p.velocity + p.angular_velocity.cross(g.branch_p) - w.velocity;
  }
  g.normal_speed = g.contact_velocity.dot(g.normal);
  g.tangential_velocity = g.contact_velocity - g.normal_speed * g.normal;
  if (arm == WallLeverArm::yade_incident) {
    g.tangential_velocity = yade_tangential_velocity(g.tangential_velocity, p.velocity - w.velocity, g.normal,
                                                     laws::incident_velocity_scale(2.0 * p.radius, g.overlap));
  }
  g.relative_angular_velocity = p.angular_velocity;
  g.angular_velocity_sum = p.angular_velocity;
  g.reduced_mass = 1.0 / p.inverse_mass;
  g.reduced_radius = p.radius;
  g.contact_distance = p.radius;
  g.effect_distance = p.effect_radius;
  g.charge_product = 0.0;
  g.against_wall = true;
  return g;
}

}  // namespace dem
