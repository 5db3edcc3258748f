// SPDX-License-Identifier: MIT
#pragma once
// The nearest point of a triangle, in the triangle's own plane frame, and which of its parts
// (face, edge, corner) holds it: the geometry of mesh walls (docs/walls.md, "Meshes").

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace dem {

/// The part of a triangle that holds a nearest point. Edge k joins corners k and k + 1 (mod 3).
enum class TrianglePart : std::uint8_t { face, edge, corner };

/// A triangle in its plane frame: corner 0 at the origin, corner 1 at (length, 0) on the u axis,
/// corner 2 at (cu, cv) with cv > 0 (the corners run anticlockwise seen from the normal's side).
struct PlaneTriangle {
  double length;  ///< corner 1's u [m]
  double cu;      ///< corner 2's u [m]
  double cv;      ///< corner 2's v [m], > 0
};

/// Where a point's projection (a, b) meets the triangle: the nearest point (u, v) of the closed
/// triangle, which part holds it, which edge or corner (`index`, 0 for the face), and whether the
/// projection lies in the closed triangle (then (u, v) = (a, b), whatever part is named).
struct TriangleNearest {
  double u;
  double v;
  TrianglePart part;
  std::uint8_t index;
  bool inside;
};

/// The nearest point of triangle `tri` to the in-plane point (a, b), with its part. A nearest
/// point closer than `snap` [m] to an edge is said to lie on that edge, and closer than `snap` to
/// a corner on that corner: neighbouring triangles then name a point on their common edge alike
/// although each computes it in its own frame. The point itself is never moved.
[[nodiscard]] inline TriangleNearest nearest_on_triangle(const PlaneTriangle& tri, double a, double b,
                                                         double snap) noexcept {
  const std::array<double, 3> cu{0.0, tri.length, tri.cu};
  const std::array<double, 3> cv{0.0, 0.0, tri.cv};
  // Signed distance of (a, b) to each edge line, positive inside (the interior lies to the left
  // of every edge), and the position along each edge.
  std::array<double, 3> inside{};
  std::array<double, 3> along{};
  std::array<double, 3> edge_length{};
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t j = (k + 1) % 3;
    const double eu = cu[j] - cu[k];
    const double ev = cv[j] - cv[k];
    edge_length[k] = std::hypot(eu, ev);
    inside[k] = (eu * (b - cv[k]) - ev * (a - cu[k])) / edge_length[k];
    along[k] = ((a - cu[k]) * eu + (b - cv[k]) * ev) / edge_length[k];
  }
  // The corner shared by edges k and k + 2 is corner k.
  const auto name = [&](double u, double v, std::size_t edge, double s, bool in) {
    if (s <= snap) return TriangleNearest{u, v, TrianglePart::corner, static_cast<std::uint8_t>(edge), in};
    if (s >= edge_length[edge] - snap) {
      return TriangleNearest{u, v, TrianglePart::corner, static_cast<std::uint8_t>((edge + 1) % 3), in};
    }
    return TriangleNearest{u, v, TrianglePart::edge, static_cast<std::uint8_t>(edge), in};
  };
  if (inside[0] >= 0.0 && inside[1] >= 0.0 && inside[2] >= 0.0) {
    std::size_t nearest_edge = 0;
    for (std::size_t k = 1; k < 3; ++k) {
      if (inside[k] < inside[nearest_edge]) nearest_edge = k;
    }
    if (inside[nearest_edge] > snap) return {a, b, TrianglePart::face, 0, true};
    return name(a, b, nearest_edge, std::clamp(along[nearest_edge], 0.0, edge_length[nearest_edge]), true);
  }
  // Outside: the nearest point lies on the boundary; the nearest of the three clamped edge points.
  std::size_t best = 0;
  double best_d2 = INFINITY;
  double best_s = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    const double s = std::clamp(along[k], 0.0, edge_length[k]);
    const std::size_t j = (k + 1) % 3;
    const double pu = cu[k] + (cu[j] - cu[k]) * (s / edge_length[k]);
    const double pv = cv[k] + (cv[j] - cv[k]) * (s / edge_length[k]);
    const double d2 = (a - pu) * (a - pu) + (b - pv) * (b - pv);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = k;
      best_s = s;
    }
  }
  const std::size_t j = (best + 1) % 3;
  const double f = best_s / edge_length[best];
  return name(cu[best] + (cu[j] - cu[best]) * f, cv[best] + (cv[j] - cv[best]) * f, best, best_s, false);
}

}  // namespace dem
