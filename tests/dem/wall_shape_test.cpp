// SPDX-License-Identifier: MIT
// Bounded walls (rectangle, annulus, frustum): the nearest point of the surface against
// hand-computed configurations and against random samples of the surface, and spheres bouncing
// off faces, edges and curved surfaces.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "dem/contact/mesh_topology.hpp"
#include "dem/contact/wall.hpp"
#include "wall_builders.hpp"

namespace wall_shape_test {

using dem::Vec3;
using dem::Wall;
using dem::WallShape;

using test_support::annulus;
using test_support::frustum;
using test_support::rectangle;

void expect_frame(const dem::WallFrame& f, const Vec3& normal, double distance) {
  EXPECT_NEAR(f.distance, distance, 1e-15);
  EXPECT_LT((f.normal - normal).norm(), 1e-15) << f.normal.transpose() << " against " << normal.transpose();
}

TEST(WallFrame, PlaneIsSignedAlongItsNormal) {
  const Wall w{Vec3(0, 0, 1), Vec3(0, 0, 1)};
  expect_frame(dem::wall_frame(w, Vec3(5, -3, 1.25), 0.0), Vec3(0, 0, 1), 0.25);
  expect_frame(dem::wall_frame(w, Vec3(5, -3, 0.5), 0.0), Vec3(0, 0, 1), -0.5);
}

TEST(WallFrame, RectangleFaceEdgeAndCorner) {
  // 2 × 1 plate in z = 0, sides along x (half 1) and y (half 0.5).
  const Wall w = rectangle(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 1.0, 0.5);
  expect_frame(dem::wall_frame(w, Vec3(0.3, -0.2, 0.4), 0.0), Vec3::UnitZ(), 0.4);      // over the face
  expect_frame(dem::wall_frame(w, Vec3(0.3, -0.2, -0.4), 0.0), -Vec3::UnitZ(), 0.4);    // under it: two-sided
  expect_frame(dem::wall_frame(w, Vec3(1.3, 0.1, 0.4), 0.0), Vec3(0.6, 0, 0.8), 0.5);   // beside the x edge
  expect_frame(dem::wall_frame(w, Vec3(0.0, 0.8, 0.0), 0.0), Vec3::UnitY(), 0.3);       // in the plane, off the y edge
  const Vec3 off_corner(1.0 + 0.2, 0.5 + 0.2, 0.1);
  expect_frame(dem::wall_frame(w, off_corner, 0.0), Vec3(0.2, 0.2, 0.1) / 0.3, 0.3);    // beyond the corner
  // Moved by its velocity: at t = 2 the plate is 1 higher.
  Wall moving = w;
  moving.velocity = Vec3(0, 0, 0.5);
  expect_frame(dem::wall_frame(moving, Vec3(0.3, -0.2, 1.4), 2.0), Vec3::UnitZ(), 0.4);
}

TEST(WallFrame, AnnulusFaceRimAndHole) {
  // Ring in z = 0 from radius 1 to 3: a floor with a round orifice of radius 1.
  const Wall w = annulus(Vec3::Zero(), Vec3::UnitZ(), 1.0, 3.0);
  expect_frame(dem::wall_frame(w, Vec3(2, 0, 0.5), 0.0), Vec3::UnitZ(), 0.5);
  expect_frame(dem::wall_frame(w, Vec3(0, 0.6, 0.3), 0.0), Vec3(0, -0.8, 0.6), 0.5);   // over the hole: the rim
  expect_frame(dem::wall_frame(w, Vec3(0, 0.6, -0.3), 0.0), Vec3(0, -0.8, -0.6), 0.5); // under the hole
  expect_frame(dem::wall_frame(w, Vec3(3.3, 0, 0.4), 0.0), Vec3(0.6, 0, 0.8), 0.5);    // beyond the outer rim
  // A disc (no hole): the axis point lies over the face.
  expect_frame(dem::wall_frame(annulus(Vec3::Zero(), Vec3::UnitZ(), 0.0, 3.0), Vec3(0, 0, 0.7), 0.0),
               Vec3::UnitZ(), 0.7);
}

TEST(WallFrame, CylinderInsideOutsideAndBeyondItsEnds) {
  // Cylinder of radius 2 along z from z = 0 to z = 4.
  const Wall w = frustum(Vec3::Zero(), Vec3::UnitZ(), 4.0, 2.0, 2.0);
  expect_frame(dem::wall_frame(w, Vec3(1.5, 0, 1), 0.0), -Vec3::UnitX(), 0.5);   // inside: the normal points in
  expect_frame(dem::wall_frame(w, Vec3(0, 2.5, 3), 0.0), Vec3::UnitY(), 0.5);    // outside
  expect_frame(dem::wall_frame(w, Vec3(1.6, 0, 4.3), 0.0), Vec3(-0.8, 0, 0.6), 0.5);  // past the top rim
}

TEST(WallFrame, ConeGeneratorAndRims) {
  // A 45° funnel: radius 1 at z = 0 rising to radius 3 at z = 2 (the orifice is at the bottom).
  const Wall w = frustum(Vec3::Zero(), Vec3::UnitZ(), 2.0, 1.0, 3.0);
  const double s = std::sqrt(0.5);
  // A point inside the funnel, on the inward normal of the generator's midpoint (r = 2, z = 1).
  expect_frame(dem::wall_frame(w, Vec3(2.0 - 0.3 * s, 0, 1.0 + 0.3 * s), 0.0), Vec3(-s, 0, s), 0.3);
  // Below the orifice rim, in the axis plane y = 0.
  expect_frame(dem::wall_frame(w, Vec3(0.6, 0, -0.3), 0.0), Vec3(-0.8, 0, -0.6), 0.5);
}

/// Whether the point y lies on the surface of w (within tol).
bool on_surface(const Wall& w, const Vec3& y, double tol) {
  const Vec3 rel = y - w.point;
  switch (w.shape) {
    case WallShape::plane: return std::abs(rel.dot(w.normal)) < tol;
    case WallShape::rectangle: {
      const Vec3 v = w.normal.cross(w.axis_u);
      return std::abs(rel.dot(w.normal)) < tol && std::abs(rel.dot(w.axis_u)) < w.size_u + tol &&
             std::abs(rel.dot(v)) < w.size_v + tol;
    }
    case WallShape::annulus: {
      const double rho = (rel - rel.dot(w.normal) * w.normal).norm();
      return std::abs(rel.dot(w.normal)) < tol && rho > w.size_u - tol && rho < w.size_v + tol;
    }
    case WallShape::frustum: {
      const double s = rel.dot(w.normal);
      const double rho = (rel - s * w.normal).norm();
      const double expected = w.size_u + (w.size_v - w.size_u) * s / w.length;
      return s > -tol && s < w.length + tol && std::abs(rho - expected) < tol;
    }
    case WallShape::triangle: {
      const Vec3 v = w.normal.cross(w.axis_u);
      const double a = rel.dot(w.axis_u);
      const double b = rel.dot(v);
      // Inside the three edge lines (anticlockwise corners (0, 0), (L, 0), (cu, cv)).
      const double e1 = (w.size_u - w.length) * b - w.size_v * (a - w.length);
      const double e2 = w.size_v * a - w.size_u * b;
      const double scale = w.length + std::hypot(w.size_u, w.size_v);
      return std::abs(rel.dot(w.normal)) < tol && b > -tol && e1 > -tol * scale && e2 > -tol * scale;
    }
  }
  return false;
}

/// A uniformly random point of the surface of w.
Vec3 surface_sample(const Wall& w, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vec3 e1 = dem::any_orthogonal(w.normal);
  const Vec3 e2 = w.normal.cross(e1);
  const double phi = 2.0 * std::numbers::pi * unit(rng);
  switch (w.shape) {
    case WallShape::rectangle: {
      const Vec3 v = w.normal.cross(w.axis_u);
      return w.point + (2.0 * unit(rng) - 1.0) * w.size_u * w.axis_u + (2.0 * unit(rng) - 1.0) * w.size_v * v;
    }
    case WallShape::annulus: {
      const double rho = w.size_u + (w.size_v - w.size_u) * unit(rng);
      return w.point + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
    }
    case WallShape::frustum: {
      const double s = unit(rng);
      const double rho = w.size_u + (w.size_v - w.size_u) * s;
      return w.point + s * w.length * w.normal + rho * (std::cos(phi) * e1 + std::sin(phi) * e2);
    }
    case WallShape::triangle: {
      const Vec3 v = w.normal.cross(w.axis_u);
      const double r1 = std::sqrt(unit(rng));
      const double r2 = unit(rng);
      const Vec3 c1 = w.length * w.axis_u;
      const Vec3 c2 = w.size_u * w.axis_u + w.size_v * v;
      return w.point + r1 * (1.0 - r2) * c1 + r1 * r2 * c2;
    }
    case WallShape::plane: break;
  }
  return w.point;
}

/// A random unit vector.
Vec3 random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> gauss(0.0, 1.0);
  return Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
}

TEST(WallFrame, IsTheNearestPointOfTheSurfaceAtRandomPoints) {
  // For random shapes, sizes, orientations and query points: the foot x − d n lies on the
  // surface, and no sampled surface point is nearer than d.
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const Vec3 n = random_direction(rng);
    const Vec3 centre(unit(rng), unit(rng), unit(rng));
    Wall w;
    switch (trial % 5) {
      case 0: w = rectangle(centre, n, dem::any_orthogonal(n), 0.1 + unit(rng), 0.1 + unit(rng)); break;
      case 1: w = annulus(centre, n, 0.8 * unit(rng), 1.0 + unit(rng)); break;
      case 2: w = frustum(centre, n, 0.2 + 2.0 * unit(rng), 0.5 + unit(rng), 0.5 + unit(rng)); break;
      case 3: w = frustum(centre, n, 0.2 + 2.0 * unit(rng), 0.0, 0.5 + unit(rng)); break;  // a pointed cone
      default: {  // a triangle with random corners, obtuse ones among them
        const Vec3 a = centre + Vec3(unit(rng), unit(rng), unit(rng)) - Vec3::Constant(0.5);
        const Vec3 b = centre + Vec3(unit(rng), unit(rng), unit(rng)) - Vec3::Constant(0.5);
        w = dem::triangle_wall(centre, a, b);
        break;
      }
    }
    if (trial % 5 == 0) {  // turn the rectangle's first side by a random angle in its plane
      const double a = 2.0 * std::numbers::pi * unit(rng);
      w.axis_u = std::cos(a) * w.axis_u + std::sin(a) * n.cross(w.axis_u);
    }
    std::vector<Vec3> samples;
    for (int k = 0; k < 3000; ++k) samples.push_back(surface_sample(w, rng));
    for (int q = 0; q < 25; ++q) {
      const Vec3 x = centre + 3.0 * Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
      const dem::WallFrame f = dem::wall_frame(w, x, 0.0);
      ASSERT_GE(f.distance, 0.0);
      ASSERT_NEAR(f.normal.norm(), 1.0, 1e-12);
      const Vec3 foot = x - f.distance * f.normal;
      ASSERT_TRUE(on_surface(w, foot, 1e-12)) << "trial " << trial << " query " << q;
      for (const Vec3& y : samples) ASSERT_LE(f.distance, (x - y).norm() + 1e-12) << "trial " << trial;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 60 * 25);
}

TEST(WallFrame, ARemovedWallIsAbsentFromItsRemovalTimeOn) {
  Wall w = rectangle(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 1.0, 1.0);
  EXPECT_TRUE(w.present(1e9));
  w.removed_at = 0.5;
  EXPECT_TRUE(w.present(0.4999));
  EXPECT_FALSE(w.present(0.5));
  EXPECT_FALSE(w.present(0.6));
}

}  // namespace wall_shape_test
