// SPDX-License-Identifier: MIT
#pragma once
// Bounded walls for tests, built from their defining sizes.

#include "dem/contact/wall.hpp"

namespace test_support {

/// A rectangle centred at `centre` with normal n, first side along u, half sides half_u, half_v.
inline dem::Wall rectangle(const dem::Vec3& centre, const dem::Vec3& normal, const dem::Vec3& u, double half_u,
                           double half_v) {
  dem::Wall w{centre, normal};
  w.shape = dem::WallShape::rectangle;
  w.axis_u = u;
  w.size_u = half_u;
  w.size_v = half_v;
  return w;
}

/// A ring centred at `centre` with normal n from radius `inner` (0: a disc) to `outer`.
inline dem::Wall annulus(const dem::Vec3& centre, const dem::Vec3& normal, double inner, double outer) {
  dem::Wall w{centre, normal};
  w.shape = dem::WallShape::annulus;
  w.size_u = inner;
  w.size_v = outer;
  return w;
}

/// The open lateral surface of a cone frustum from `base` along the unit `axis`, `length` long,
/// radius r0 at the base and r1 at the other end (a cylinder when they agree).
inline dem::Wall frustum(const dem::Vec3& base, const dem::Vec3& axis, double length, double r0, double r1) {
  dem::Wall w{base, axis};
  w.shape = dem::WallShape::frustum;
  w.length = length;
  w.size_u = r0;
  w.size_v = r1;
  return w;
}

}  // namespace test_support
