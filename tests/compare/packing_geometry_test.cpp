// SPDX-License-Identifier: MIT
// Packing geometry against closed forms: the disk–rectangle area, the volume of a sphere inside a
// box (whole, halved, quartered, an eighth, a spherical cap, and boxes that tile space), the
// packing fraction, the interior region, and the obscured reservoir fraction of thesis appendix G
// on configurations counted by hand.
#include "compare/packing_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace {

using comparison::Box;
using cases::Vector3;

constexpr double kPi = std::numbers::pi;

double sphere_volume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

/// Volume of a spherical cap of height h (thesis-independent closed form πh²(3r − h)/3).
double cap_volume(double r, double h) { return kPi * h * h * (3.0 * r - h) / 3.0; }

Box cube(double half) { return Box{{-half, -half, -half}, {half, half, half}}; }

TEST(DiskRectangleArea, MatchesTheWholeDiskHalvesQuartersAndASegment) {
  const double r = 1.5;
  EXPECT_NEAR(comparison::disk_rectangle_area(r, -2, 2, -2, 2), kPi * r * r, 1e-14);
  EXPECT_NEAR(comparison::disk_rectangle_area(r, 0, 2, -2, 2), 0.5 * kPi * r * r, 1e-14);
  EXPECT_NEAR(comparison::disk_rectangle_area(r, -2, 0, -2, 0), 0.25 * kPi * r * r, 1e-14);
  EXPECT_NEAR(comparison::disk_rectangle_area(r, 0, 2, 0, 2), 0.25 * kPi * r * r, 1e-14);
  // A circular segment beyond x = a: r² acos(a/r) − a√(r² − a²).
  const double a = 0.6;
  EXPECT_NEAR(comparison::disk_rectangle_area(r, a, 5, -5, 5), r * r * std::acos(a / r) - a * std::sqrt(r * r - a * a),
              1e-14);
  EXPECT_NEAR(comparison::disk_rectangle_area(r, -5, 5, a, 5), r * r * std::acos(a / r) - a * std::sqrt(r * r - a * a),
              1e-14);
  // A small square inside the disk is all inside.
  EXPECT_NEAR(comparison::disk_rectangle_area(r, 0.1, 0.3, -0.4, 0.2), 0.2 * 0.6, 1e-14);
  EXPECT_EQ(comparison::disk_rectangle_area(r, 2, 3, -1, 1), 0.0);
  EXPECT_EQ(comparison::disk_rectangle_area(0.0, -1, 1, -1, 1), 0.0);
}

TEST(SphereBoxVolume, WholeHalfQuarterEighthAndCapsAreExact) {
  const double r = 0.7;
  const Vector3 o{0, 0, 0};
  const double v = sphere_volume(r);
  const double tol = 1e-14 * v;  // round-off of the quadrature: a few ulps of the sphere's volume
  EXPECT_DOUBLE_EQ(comparison::sphere_box_volume(o, r, cube(1.0)), v);
  EXPECT_NEAR(comparison::sphere_box_volume(o, r, Box{{0, -1, -1}, {1, 1, 1}}), v / 2, tol);
  EXPECT_NEAR(comparison::sphere_box_volume(o, r, Box{{-1, -1, 0}, {1, 1, 1}}), v / 2, tol);
  EXPECT_NEAR(comparison::sphere_box_volume(o, r, Box{{0, 0, -1}, {1, 1, 1}}), v / 4, tol);
  EXPECT_NEAR(comparison::sphere_box_volume(o, r, Box{{0, 0, 0}, {1, 1, 1}}), v / 8, tol);
  for (const double h : {0.05, 0.3, 0.7, 1.1, 1.35}) {
    // A cap of height h cut off by each of the six faces in turn.
    const double cut = r - h;
    EXPECT_NEAR(comparison::sphere_box_volume(o, r, Box{{cut, -1, -1}, {1, 1, 1}}), cap_volume(r, h), tol) << h;
    EXPECT_NEAR(comparison::sphere_box_volume(o, r, Box{{-1, -1, -1}, {-cut, 1, 1}}), cap_volume(r, h), tol) << h;
    EXPECT_NEAR(comparison::sphere_box_volume(o, r, Box{{-1, cut, -1}, {1, 1, 1}}), cap_volume(r, h), tol) << h;
    EXPECT_NEAR(comparison::sphere_box_volume(o, r, Box{{-1, -1, cut}, {1, 1, 1}}), cap_volume(r, h), tol) << h;
  }
  // A box inside the sphere is its own volume; one whose corner pokes out holds less.
  EXPECT_EQ(comparison::sphere_box_volume(o, r, Box{{-0.3, -0.2, -0.1}, {0.3, 0.2, 0.4}}), 0.6 * 0.4 * 0.5);
  const double poking = comparison::sphere_box_volume(o, r, Box{{0.0, 0.0, 0.0}, {0.41, 0.41, 0.41}});
  EXPECT_LT(poking, 0.41 * 0.41 * 0.41);
  EXPECT_GT(poking, 0.41 * 0.41 * 0.41 - 0.01);
  EXPECT_EQ(comparison::sphere_box_volume(o, r, Box{{0.7, -1, -1}, {1, 1, 1}}), 0.0);  // touching only
  EXPECT_EQ(comparison::sphere_box_volume(o, r, Box{{1, 1, 1}, {0, 0, 0}}), 0.0);       // empty box
  EXPECT_EQ(comparison::sphere_box_volume(o, 0.0, cube(1.0)), 0.0);
}

TEST(SphereBoxVolume, BoxesThatTileSpaceShareOutTheWholeSphere) {
  // Random cut planes split space into 4 × 4 × 4 boxes (the outer ones reaching far out); the
  // pieces of a sphere must add up to its volume wherever the planes cut it.
  std::mt19937_64 rng(20261205);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const double r = 0.2 + 0.8 * (0.5 + 0.5 * unit(rng));
    const Vector3 c{0.3 * unit(rng), 0.3 * unit(rng), 0.3 * unit(rng)};
    std::array<std::array<double, 5>, 3> planes{};
    for (auto& p : planes) {
      p = {-10.0, unit(rng), unit(rng), unit(rng), 10.0};
      std::sort(p.begin() + 1, p.end() - 1);
    }
    double sum = 0.0;
    for (int a = 0; a < 4; ++a) {
      for (int b = 0; b < 4; ++b) {
        for (int k = 0; k < 4; ++k) {
          const Box box{{planes[0][a], planes[1][b], planes[2][k]}, {planes[0][a + 1], planes[1][b + 1], planes[2][k + 1]}};
          sum += comparison::sphere_box_volume(c, r, box);
        }
      }
    }
    EXPECT_NEAR(sum, sphere_volume(r), 1e-12 * sphere_volume(r)) << "trial " << trial;
  }
}

TEST(PackingFraction, SumsClippedVolumesOverTheRegion) {
  // A simple cubic lattice of touching spheres fills π/6 of a box cut through the sphere centres
  // as well as of one cut along the lattice's cells.
  const double r = 0.5;
  std::vector<Vector3> centres;
  std::vector<double> radii;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      for (int k = 0; k < 6; ++k) {
        centres.push_back({static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)});
        radii.push_back(r);
      }
    }
  }
  EXPECT_NEAR(comparison::packing_fraction(centres, radii, Box{{0.5, 0.5, 0.5}, {4.5, 4.5, 4.5}}), kPi / 6, 1e-13);
  EXPECT_NEAR(comparison::packing_fraction(centres, radii, Box{{1, 1, 1}, {5, 5, 5}}), kPi / 6, 1e-13);
  EXPECT_NEAR(comparison::packing_fraction(centres, radii, Box{{1, 1, 1}, {3, 4, 5}}), kPi / 6, 1e-13);
  EXPECT_THROW((void)comparison::packing_fraction(centres, radii, Box{{0, 0, 0}, {0, 1, 1}}), std::invalid_argument);
  radii.pop_back();
  EXPECT_THROW((void)comparison::packing_fraction(centres, radii, cube(1)), std::invalid_argument);
}

TEST(PackingFraction, TheInteriorIsTheRegionShrunkOnEverySide) {
  const Box in = comparison::interior(Box{{0, 0, 0}, {10, 6, 4}}, 1.5);
  EXPECT_EQ(in.lo, (Vector3{1.5, 1.5, 1.5}));
  EXPECT_EQ(in.hi, (Vector3{8.5, 4.5, 2.5}));
  EXPECT_THROW((void)comparison::interior(Box{{0, 0, 0}, {10, 6, 3}}, 1.5), std::invalid_argument);
}

TEST(ObscuredFraction, CountsTheGridPointsInsideEachSpheresShadow) {
  // A 2 × 6 × 2 reservoir seen along x on the thesis' 45 × 15 grid: point spacing 2/15.
  const Box reservoir{{0, 0, 0}, {2, 6, 2}};
  const std::vector<Vector3> one{{1.0, 3.0, 1.0}};
  // Grid points at y = (a + ½)·2/15, z = (b + ½)·2/15; count those with (y − 3)² + (z − 1)² < r².
  const auto hand_count = [](double r) {
    int n = 0;
    for (int a = 0; a < 45; ++a) {
      for (int b = 0; b < 15; ++b) {
        const double y = (a + 0.5) * 6.0 / 45.0 - 3.0;
        const double z = (b + 0.5) * 2.0 / 15.0 - 1.0;
        if (y * y + z * z < r * r) ++n;
      }
    }
    return n;
  };
  for (const double r : {0.05, 0.2, 0.5, 0.9}) {
    const std::vector<double> radius{r};
    EXPECT_DOUBLE_EQ(comparison::obscured_fraction(one, radius, reservoir, 45, 15), hand_count(r) / 675.0) << r;
  }
  // Below the spacing, a sphere between points covers none; a sphere covering the face covers all.
  EXPECT_EQ(comparison::obscured_fraction(std::vector<Vector3>{{1.0, 0.1333, 0.1333}}, std::vector<double>{0.01},
                                          reservoir, 45, 15),
            0.0);
  EXPECT_EQ(comparison::obscured_fraction(one, std::vector<double>{10.0}, reservoir, 45, 15), 1.0);
  // Two spheres whose shadows overlap count the shared points once; a sphere outside the
  // reservoir (centre beyond x = 2) casts no shadow.
  const std::vector<Vector3> two{{0.5, 3.0, 1.0}, {1.5, 3.0, 1.0}, {2.5, 1.0, 1.0}};
  EXPECT_DOUBLE_EQ(comparison::obscured_fraction(two, std::vector<double>{0.5, 0.5, 0.9}, reservoir, 45, 15),
                   hand_count(0.5) / 675.0);
  EXPECT_THROW((void)comparison::obscured_fraction(one, std::vector<double>{0.5}, reservoir, 0, 15), std::invalid_argument);
}

TEST(ShareInside, CountsCentresInTheRegion) {
  const std::vector<Vector3> c{{0.5, 0.5, 0.5}, {1.5, 0.5, 0.5}, {1.0, 0.2, 0.9}, {-0.1, 0.5, 0.5}};
  EXPECT_DOUBLE_EQ(comparison::share_inside(c, Box{{0, 0, 0}, {1, 1, 1}}), 0.5);
  EXPECT_EQ(comparison::share_inside({}, Box{{0, 0, 0}, {1, 1, 1}}), 0.0);
}

}  // namespace
