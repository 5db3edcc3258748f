// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "dem/contact/triangle.hpp"
#include "dem/core/vector.hpp"

namespace dem {

/// The surface a wall presents to the spheres (docs/walls.md).
enum class WallShape : std::uint8_t {
  plane,      ///< infinite half-space boundary: one-sided, spheres live on the normal's side
  rectangle,  ///< bounded thin plate: centre, normal, in-plane axis u and half sizes along u, v = n × u
  annulus,    ///< flat ring (a disc when the inner radius is 0): a floor with a round orifice
  frustum,    ///< open lateral surface of a cone frustum about an axis (a cylinder when both radii agree)
  triangle,   ///< one facet of a mesh wall: corner 0, unit normal, unit u along edge 0, corners 1 and 2 in (u, v)
};

/// Marks a wall that belongs to no mesh (Wall::mesh).
inline constexpr std::uint32_t kNoMesh = 0xffffffffU;

/// A rigid wall: its shape, where it is at t = 0, a constant velocity, its material and the
/// time it is removed (an orifice plate that opens). Bounded shapes are thin and two-sided:
/// a sphere touches the nearest point of the surface, edges and rims included.
struct Wall {
  Vec3 point;   ///< plane: a point on it; rectangle, annulus: centre; frustum: axis point of its first end; triangle: corner 0 [m]
  Vec3 normal;  ///< plane: unit normal into the domain; rectangle, annulus, triangle: unit normal; frustum: unit axis
  Vec3 velocity = Vec3::Zero();  ///< [m/s]
  std::uint32_t material = 0;
  WallShape shape = WallShape::plane;
  std::uint32_t mesh = kNoMesh;  ///< triangle: the mesh it belongs to (index into the force field's meshes)
  Vec3 axis_u = Vec3::Zero();  ///< rectangle, triangle: unit in-plane axis u, orthogonal to the normal
  double size_u = 0.0;         ///< rectangle: half size along u; annulus: inner radius; frustum: radius at the first end; triangle: corner 2's u [m]
  double size_v = 0.0;         ///< rectangle: half size along v; annulus: outer radius; frustum: radius at the second end; triangle: corner 2's v (> 0) [m]
  double length = 0.0;         ///< frustum: axial length; triangle: corner 1's u (the length of edge 0) [m]
  double removed_at = std::numeric_limits<double>::infinity();  ///< the wall is gone from this time on [s]

  /// Whether the wall exists at time t.
  [[nodiscard]] bool present(double t) const noexcept { return t < removed_at; }
};

/// The wall of the triangle with corners a, b, c: its plane frame (unit normal along
/// (b − a) × (c − a), u along b − a, corner c's in-plane coordinates). Throws
/// std::invalid_argument when the corners span no area.
[[nodiscard]] inline Wall triangle_wall(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a;
  const Vec3 e2 = c - a;
  const Vec3 n = e1.cross(e2);
  if (!(n.norm() > 0.0) || !std::isfinite(n.norm())) throw std::invalid_argument("the triangle has no area");
  Wall w{a, n.normalized()};
  w.shape = WallShape::triangle;
  w.length = e1.norm();
  w.axis_u = e1 / w.length;
  w.size_u = e2.dot(w.axis_u);
  w.size_v = e2.dot(w.normal.cross(w.axis_u));
  return w;
}

/// Where a sphere centre sees a wall: the unit contact normal from the wall towards the centre
/// and the centre's distance along it (signed for a plane; ≥ 0 for a bounded shape).
struct WallFrame {
  Vec3 normal;
  double distance;
};

/// A unit vector orthogonal to the unit vector a (a deterministic choice).
[[nodiscard]] inline Vec3 any_orthogonal(const Vec3& a) noexcept {
  const Vec3 seed = std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (seed - seed.dot(a) * a).normalized();
}

/// The frame of centre x against wall w at time t: for a plane, its normal and the signed
/// distance; for a bounded shape, the direction from the surface's nearest point to x and the
/// distance to it. A centre exactly on a bounded surface takes the surface normal.
[[nodiscard]] inline WallFrame wall_frame(const Wall& w, const Vec3& x, double t) noexcept {
  const Vec3 rel = x - (w.point + t * w.velocity);
  Vec3 nearest = Vec3::Zero();  // the surface's nearest point relative to w.point(t)
  Vec3 surface_normal = w.normal;
  switch (w.shape) {
    case WallShape::plane: return {w.normal, rel.dot(w.normal)};
    case WallShape::rectangle: {
      const Vec3 v = w.normal.cross(w.axis_u);
      nearest = std::clamp(rel.dot(w.axis_u), -w.size_u, w.size_u) * w.axis_u +
                std::clamp(rel.dot(v), -w.size_v, w.size_v) * v;
      break;
    }
    case WallShape::annulus: {
      const Vec3 in_plane = rel - rel.dot(w.normal) * w.normal;
      const double rho = in_plane.norm();
      const Vec3 radial = rho > 0.0 ? Vec3(in_plane / rho) : any_orthogonal(w.normal);
      nearest = std::clamp(rho, w.size_u, w.size_v) * radial;
      break;
    }
    case WallShape::frustum: {
      const double s = rel.dot(w.normal);
      const Vec3 off_axis = rel - s * w.normal;
      const double rho = off_axis.norm();
      const Vec3 radial = rho > 0.0 ? Vec3(off_axis / rho) : any_orthogonal(w.normal);
      // The generator runs from (0, r0) to (L, r1) in the (axial, radial) half-plane.
      const double dr = w.size_v - w.size_u;
      const double tau = std::clamp((s * w.length + (rho - w.size_u) * dr) / (w.length * w.length + dr * dr), 0.0, 1.0);
      nearest = tau * w.length * w.normal + (w.size_u + tau * dr) * radial;
      surface_normal = (w.length * radial - dr * w.normal).normalized();
      break;
    }
    case WallShape::triangle: {
      const Vec3 v = w.normal.cross(w.axis_u);
      const TriangleNearest p =
          nearest_on_triangle(PlaneTriangle{w.length, w.size_u, w.size_v}, rel.dot(w.axis_u), rel.dot(v), 0.0);
      nearest = p.u * w.axis_u + p.v * v;
      break;
    }
  }
  const Vec3 d = rel - nearest;
  const double distance = d.norm();
  return {distance > 0.0 ? Vec3(d / distance) : surface_normal, distance};
}

}  // namespace dem
