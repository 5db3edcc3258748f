// SPDX-License-Identifier: MIT
// Mesh walls: a sphere feels a triangulated surface as the surface itself — one contact per
// point however many facets meet there. A flat floor cut into irregular triangles (fans, seams,
// corners) pushes like a plane at random places and exactly on its seams and corners; outside a
// subdivided cube a sphere feels the one nearest point of the solid; inside it, the faces it
// touches and never an edge; and a sphere sliding over the seams of a floor without friction
// follows the plane's trajectory.
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "dem/contact/mesh_topology.hpp"
#include "dem/neighbors/interaction_reach.hpp"
#include "dem/simulation/simulation.hpp"

namespace mesh_wall_test {

using dem::Vec3;
using Facet = std::array<Vec3, 3>;

// Tolerances: a facet meets a sphere through its own frame (corner 0, normal, in-plane axes),
// the plane or cube face it tiles through another, so the two agree to rounding — distances to
// ~1e-16 of the coordinates, forces to ~1e-12 of themselves at the overlaps used here. The
// tests allow 1e-9 of the force or of the path: room for that rounding to grow over tens of
// thousands of steps, and six orders below what a missed or doubled contact does (a whole
// contact's force, or the 3e-8 m a restarted spring puts on the path).
constexpr double kStiffness = 2e3;  // N/m
constexpr double kRadius = 3e-4;    // m

dem::MaterialProperties elastic() {
  dem::MaterialProperties m;
  m.name = "elastic";
  m.density = 2500.0;
  m.normal_stiffness = kStiffness;
  return m;
}

/// One sphere of radius r at x with velocity u, no gravity, elastic frictionless linear law.
dem::SimulationSetup one_sphere(const Vec3& x, double r, const Vec3& u = Vec3::Zero()) {
  dem::SimulationSetup s;
  s.materials = {elastic()};
  s.particles.push_back({r, r, 2500.0, 0, x, u, Vec3::Zero(), false});
  s.timestep = 1e-6;
  s.scheme_settings.rotation = false;
  return s;
}

/// `s` with the facets as one mesh wall (after its other walls).
void add_mesh(dem::SimulationSetup& s, const std::vector<Facet>& facets) {
  const auto first = static_cast<std::uint32_t>(s.walls.size());
  for (const Facet& f : facets) {
    dem::Wall w = dem::triangle_wall(f[0], f[1], f[2]);
    w.mesh = static_cast<std::uint32_t>(s.meshes.size());
    s.walls.push_back(w);
  }
  s.meshes.push_back(dem::build_mesh_topology(facets, first));
}

/// Adds the floor to `s`: its facets as one mesh, or (mesh false) the plane z = 0 they tile.
void add_floor(dem::SimulationSetup& s, bool mesh, const std::vector<Facet>& facets) {
  if (mesh) {
    add_mesh(s, facets);
  } else {
    s.walls.push_back(dem::Wall{Vec3::Zero(), Vec3::UnitZ()});
  }
}

/// The force on the single sphere at t = 0.
Vec3 force_at_start(const dem::SimulationSetup& s) {
  const dem::Simulation sim(s);
  return sim.force_field().forces().col(0);
}

/// Expects the force of the mesh `facets` on a sphere of radius r at x to be `expected`.
void expect_mesh_force(const std::vector<Facet>& facets, const Vec3& x, double r, const Vec3& expected) {
  dem::SimulationSetup s = one_sphere(x, r);
  add_mesh(s, facets);
  const Vec3 got = force_at_start(s);
  EXPECT_LT((got - expected).norm(), 1e-9 * expected.norm())
      << "centre " << x.transpose() << ": mesh " << got.transpose() << ", expected " << expected.transpose();
}

/// Corners of an n × n grid over [0, n·h]² at z = 0, the interior ones moved in the plane by up
/// to a quarter cell, and its cells cut into triangles: diagonals alternating, and every fourth
/// cell a fan of four around its centre (a corner shared by eight facets nearby).
struct Floor {
  std::vector<Facet> facets;
  std::vector<Vec3> corners;  ///< every corner, cell centres of fans included
};

Floor jittered_floor(int n, double h, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> jitter(-0.25 * h, 0.25 * h);
  std::vector<Vec3> grid;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const bool inner = i > 0 && j > 0 && i < n && j < n;
      grid.emplace_back(i * h + (inner ? jitter(rng) : 0.0), j * h + (inner ? jitter(rng) : 0.0), 0.0);
    }
  }
  const auto at = [&](int i, int j) { return grid[static_cast<std::size_t>(j * (n + 1) + i)]; };
  Floor floor{{}, grid};
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const Vec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if ((i + 2 * j) % 4 == 3) {
        const Vec3 m = 0.25 * (a + b + c + d);
        floor.corners.push_back(m);
        floor.facets.insert(floor.facets.end(), {Facet{a, b, m}, Facet{b, c, m}, Facet{c, d, m}, Facet{d, a, m}});
      } else if ((i + j) % 2 == 0) {
        floor.facets.insert(floor.facets.end(), {Facet{a, b, c}, Facet{a, c, d}});
      } else {
        floor.facets.insert(floor.facets.end(), {Facet{a, b, d}, Facet{b, c, d}});
      }
    }
  }
  return floor;
}

/// Turns and moves a point: rotation R, then translation t.
struct Placement {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Vec3 shift = Vec3::Zero();
  [[nodiscard]] Vec3 operator()(const Vec3& x) const { return rotation * x + shift; }
};

/// Compares the mesh floor with a plane at the same place, for a sphere above the floor point
/// (a, b) at height z, under placement `place`.
void expect_floor_is_plane(const Floor& floor, const Placement& place, double a, double b, double z, double r) {
  std::vector<Facet> facets;
  for (const Facet& f : floor.facets) facets.push_back({place(f[0]), place(f[1]), place(f[2])});
  const Vec3 x = place(Vec3(a, b, z));
  dem::SimulationSetup with_plane = one_sphere(x, r);
  with_plane.walls = {dem::Wall{place(Vec3::Zero()), place.rotation * Vec3::UnitZ()}};
  const Vec3 expected = force_at_start(with_plane);
  ASSERT_GT(expected.norm(), 0.0);
  SCOPED_TRACE(::testing::Message() << "sphere over (" << a << ", " << b << ") at height " << z);
  expect_mesh_force(facets, x, r, expected);
}

TEST(MeshWall, AFlatFloorOfTrianglesPushesLikeAPlaneAtRandomPlacesAndOnEverySeamAndCorner) {
  for (const std::uint32_t seed : {1U, 2U}) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double h = 1e-3;
    const Floor floor = jittered_floor(6, h, rng);
    // Level and at the origin; then turned by a random rotation and moved half a metre away,
    // where the facets' frames round differently from the plane's.
    std::vector<Placement> places(2);
    places[1].rotation = Eigen::AngleAxisd(2.0 * std::numbers::pi * unit(rng),
                                           Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5).normalized())
                             .toRotationMatrix();
    places[1].shift = Vec3(0.5, -0.3, 0.2);
    for (const Placement& place : places) {
      for (const double r : {kRadius, 4.0 * h}) {  // smaller than a facet, and over many facets
        const auto height = [&] { return r * (1.0 - 0.1 * unit(rng)); };
        for (int q = 0; q < 30; ++q) {
          expect_floor_is_plane(floor, place, 0.1 * h + 5.8 * h * unit(rng), 0.1 * h + 5.8 * h * unit(rng), height(), r);
        }
        // Exactly over every corner, and over the middle of every facet edge.
        for (const Vec3& c : floor.corners) expect_floor_is_plane(floor, place, c.x(), c.y(), height(), r);
        for (std::size_t f = 0; f < floor.facets.size(); f += 3) {
          for (std::size_t k = 0; k < 3; ++k) {
            const Vec3 m = 0.5 * (floor.facets[f][k] + floor.facets[f][(k + 1) % 3]);
            expect_floor_is_plane(floor, place, m.x(), m.y(), height(), r);
          }
        }
      }
    }
  }
}

/// The surface of the cube [0, L]³ with each face cut into k × k squares of two triangles.
std::vector<Facet> subdivided_cube(double length, int k) {
  std::vector<Facet> facets;
  const double h = length / k;
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {0.0, length}) {
      const int a1 = (axis + 1) % 3;
      const int a2 = (axis + 2) % 3;
      const auto corner = [&](int i, int j) {
        Vec3 p;
        p[axis] = side;
        p[a1] = i * h;
        p[a2] = j * h;
        return p;
      };
      for (int j = 0; j < k; ++j) {
        for (int i = 0; i < k; ++i) {
          facets.push_back({corner(i, j), corner(i + 1, j), corner(i + 1, j + 1)});
          facets.push_back({corner(i, j), corner(i + 1, j + 1), corner(i, j + 1)});
        }
      }
    }
  }
  return facets;
}

TEST(MeshWall, OutsideASubdividedCubeASphereFeelsTheOneNearestPointOfTheSolid) {
  // Outside a convex solid the distance to its surface has one minimum: on a face, an edge or a
  // corner. The force is k (r − d) along the line from that point to the centre.
  const double length = 2e-3;
  const std::vector<Facet> cube = subdivided_cube(length, 3);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int edges_and_corners = 0;
  for (int q = 0; q < 300; ++q) {
    Vec3 x(length * (1.4 * unit(rng) - 0.2), length * (1.4 * unit(rng) - 0.2), length * (1.4 * unit(rng) - 0.2));
    // Clamp to the cube: the solid's nearest point; keep centres outside and within reach.
    const Vec3 nearest = x.cwiseMax(0.0).cwiseMin(length);
    const double d = (x - nearest).norm();
    if (!(d > 0.05 * kRadius && d < 0.95 * kRadius)) continue;
    int outside_axes = 0;
    for (int a = 0; a < 3; ++a) outside_axes += (x[a] < 0.0 || x[a] > length) ? 1 : 0;
    if (outside_axes > 1) ++edges_and_corners;
    expect_mesh_force(cube, x, kRadius, kStiffness * (kRadius - d) * (x - nearest) / d);
  }
  EXPECT_GT(edges_and_corners, 20);  // the draw reached the edges and corners, not only faces
}

TEST(MeshWall, InsideASubdividedCubeASphereFeelsTheFacesItTouchesAndNoEdge) {
  // Inside the cube every face is a plane to the sphere; at a concave edge or corner it touches
  // two or three faces, each once, and the edge itself is no contact.
  const double length = 2e-3;
  const std::vector<Facet> cube = subdivided_cube(length, 3);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int several = 0;
  for (int q = 0; q < 300; ++q) {
    const Vec3 x(length * unit(rng), length * unit(rng), length * unit(rng));
    Vec3 expected = Vec3::Zero();
    int touched = 0;
    for (int a = 0; a < 3; ++a) {
      for (const double side : {0.0, length}) {
        const double d = std::abs(x[a] - side);
        if (d >= kRadius) continue;
        Vec3 n = Vec3::Zero();
        n[a] = side == 0.0 ? 1.0 : -1.0;
        expected += kStiffness * (kRadius - d) * n;
        ++touched;
      }
    }
    if (touched == 0) continue;
    if (touched > 1) ++several;
    expect_mesh_force(cube, x, kRadius, expected);
  }
  EXPECT_GT(several, 10);
}

TEST(MeshWall, ASphereSlidingOverTheSeamsOfAFrictionlessFloorFollowsThePlanesTrajectory) {
  // Thrown low over a floor of 36 irregular facets under gravity, it bounces and slides across
  // seams and past corners; with no friction the floor is the plane to it all the way.
  std::mt19937_64 rng(5);
  const double h = 1e-3;
  const Floor floor = jittered_floor(6, h, rng);
  const auto setup = [&](bool mesh) {
    dem::SimulationSetup s = one_sphere(Vec3(0.7e-3, 0.9e-3, 1.2 * kRadius), kRadius, Vec3(0.05, 0.031, -0.02));
    s.fields.gravity = Vec3(0, 0, -9.81);
    add_floor(s, mesh, floor.facets);
    return s;
  };
  dem::Simulation on_mesh(setup(true));
  dem::Simulation on_plane(setup(false));
  double deepest = 0.0;
  for (int step = 0; step < 60000; ++step) {
    on_mesh.step();
    on_plane.step();
    deepest = std::max(deepest, kRadius - on_plane.state().position(2, 0));
  }
  const Vec3 travelled = on_plane.state().position.col(0) - Vec3(0.7e-3, 0.9e-3, 1.2 * kRadius);
  ASSERT_GT(travelled.head<2>().norm(), 2.0 * h);  // it crossed several facets
  ASSERT_GT(deepest, 0.0);                          // and pressed into the floor
  EXPECT_LT((on_mesh.state().position.col(0) - on_plane.state().position.col(0)).norm(), 1e-9 * travelled.norm());
}

TEST(MeshWall, AFrictionalSphereKeepsItsSpringAcrossSeamsAndFollowsThePlanesTrajectory) {
  // Pressed hard onto the floor and thrown sideways, it slides, then rolls over seams with its
  // tangential spring loaded. The facet that takes the contact over continues the spring, so the
  // mesh is the plane to it — path, spin and the ledger's friction — while a spring restarted at
  // each seam would lose up to (μ m g)² / 2 k_t there and drift from the plane's path.
  std::mt19937_64 rng(9);
  const double h = 1e-3;
  const Floor floor = jittered_floor(6, h, rng);
  constexpr double kPress = 2000.0;  // m/s²: a body force that loads the spring well
  const auto setup = [&](bool mesh) {
    dem::SimulationSetup s = one_sphere(Vec3(0.7e-3, 0.9e-3, kRadius - 1e-7), kRadius, Vec3(0.04, 0.025, 0.0));
    s.materials[0].tangential_stiffness = 1e3;
    s.materials[0].friction = 0.3;
    s.materials[0].tangential_damping_ratio = 0.0;
    s.model.tangential = "spring_coulomb";
    s.scheme_settings.rotation = true;
    s.fields.gravity = Vec3(0, 0, -kPress);
    add_floor(s, mesh, floor.facets);
    return s;
  };
  dem::Simulation on_mesh(setup(true));
  dem::Simulation on_plane(setup(false));
  double worst_error = 0.0;
  double worst_plane_error = 0.0;
  for (int step = 0; step < 40000; ++step) {
    on_mesh.step();
    on_plane.step();
    worst_error = std::max(worst_error, std::abs(on_mesh.energy().integration_error));
    worst_plane_error = std::max(worst_plane_error, std::abs(on_plane.energy().integration_error));
  }
  const Vec3 travelled = on_plane.state().position.col(0) - Vec3(0.7e-3, 0.9e-3, kRadius);
  ASSERT_GT(travelled.head<2>().norm(), h);  // from (0.7, 0.9) mm over the cells' edges at 1 mm and their diagonals
  EXPECT_LT((on_mesh.state().position.col(0) - on_plane.state().position.col(0)).norm(), 1e-9 * travelled.norm());
  const Vec3 spin = on_plane.state().angular_velocity.col(0);
  ASSERT_GT(spin.norm(), 10.0);  // it rolls
  EXPECT_LT((on_mesh.state().angular_velocity.col(0) - spin).norm(), 1e-9 * spin.norm());
  const double mass = 2500.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
  const double one_spring = std::pow(0.3 * mass * kPress, 2) / (2.0 * 1e3);
  const double friction = on_plane.energy().dissipated_friction;
  ASSERT_GT(friction, 3.0 * one_spring);
  EXPECT_NEAR(on_mesh.energy().dissipated_friction, friction, 1e-9 * friction);
  EXPECT_LT(worst_error, 1.01 * worst_plane_error + 1e-3 * one_spring);  // nothing booked twice or lost
}

TEST(MeshWall, AJkrNeckPassesToTheNextFloorFacetNotToAWallWithinReach) {
  // A JKR sphere rolls along a floor beside a side wall of the same mesh, closer to it than the
  // neck's rupture distance but not touching it: the wall's facets count it (within reach) yet
  // hold no neck. When the sphere crosses a floor seam, the floor's neck passes to the next
  // floor facet, not to the wall (which would then pull the sphere). Against two planes the
  // path is the same to round-off.
  const double r = 5e-4;
  const double mm = 1e-3;
  const std::vector<Facet> wall_and_floor = {
      // the side wall x = 0 first (its facets have the lowest numbers)
      Facet{Vec3(0, 0, 0), Vec3(0, 4 * mm, 0), Vec3(0, 4 * mm, 2 * mm)},
      Facet{Vec3(0, 0, 0), Vec3(0, 4 * mm, 2 * mm), Vec3(0, 0, 2 * mm)},
      // the floor z = 0, two squares of two triangles
      Facet{Vec3(0, 0, 0), Vec3(4 * mm, 0, 0), Vec3(4 * mm, 2 * mm, 0)},
      Facet{Vec3(0, 0, 0), Vec3(4 * mm, 2 * mm, 0), Vec3(0, 2 * mm, 0)},
      Facet{Vec3(0, 2 * mm, 0), Vec3(4 * mm, 2 * mm, 0), Vec3(4 * mm, 4 * mm, 0)},
      Facet{Vec3(0, 2 * mm, 0), Vec3(4 * mm, 4 * mm, 0), Vec3(0, 4 * mm, 0)}};
  const auto setup = [&](bool mesh, double gap) {
    dem::SimulationSetup s;
    dem::MaterialProperties m;
    m.name = "sticky";
    m.density = 2500.0;
    m.youngs_modulus = 1e7;
    m.poisson_ratio = 0.3;
    m.surface_energy = 0.05;
    s.materials = {m};
    s.model.normal = "hertz";
    s.model.cohesion = "jkr";
    s.particles.push_back({r, r, 2500.0, 0, Vec3(r + gap, 1.5 * mm, r - 1e-7), Vec3(0, 0.03, 0), Vec3::Zero(), false});
    s.fields.gravity = Vec3(0, 0, -9.81);
    s.timestep = 1e-6;
    s.scheme_settings.rotation = false;
    if (mesh) {
      add_mesh(s, wall_and_floor);
    } else {
      s.walls = {dem::Wall{Vec3::Zero(), Vec3::UnitX()}, dem::Wall{Vec3::Zero(), Vec3::UnitZ()}};
    }
    return s;
  };
  // Half the rupture distance from the wall: within its reach, not touching.
  const dem::Simulation probe(setup(false, 0.0));
  const double reach = dem::wall_reach(probe.pair_table().law(0, 0), r, r);
  ASSERT_GT(reach, r);
  const double gap = 0.5 * (reach - r);
  dem::Simulation on_mesh(setup(true, gap));
  dem::Simulation on_planes(setup(false, gap));
  for (int step = 0; step < 30000; ++step) {
    on_mesh.step();
    on_planes.step();
  }
  const Vec3 x = on_planes.state().position.col(0);
  ASSERT_GT(x.y(), 2.2 * mm);  // it crossed the floor's seam at y = 2 mm
  ASSERT_NEAR(x.x(), r + gap, 1e-3 * gap);  // and kept its distance from the wall
  EXPECT_LT((on_mesh.state().position.col(0) - x).norm(), 1e-9 * mm);
}

TEST(MeshTopology, WeldsCornersWithTheSameCoordinatesAndListsTheFacetsAroundEach) {
  const std::vector<Facet> facets = {Facet{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)},
                                     Facet{Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)},
                                     Facet{Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0)}};
  const dem::MeshTopology m = dem::build_mesh_topology(facets, 4);
  EXPECT_EQ(m.first_wall, 4U);
  ASSERT_EQ(m.corners.size(), 5U);
  EXPECT_EQ(m.facets[1], (std::array<std::uint32_t, 3>{1, 3, 2}));
  const auto around = [&](std::uint32_t c) {
    return std::vector<std::uint32_t>(m.around.begin() + m.around_offsets[c], m.around.begin() + m.around_offsets[c + 1]);
  };
  EXPECT_EQ(around(1), (std::vector<std::uint32_t>{0, 1, 2}));  // (1, 0, 0)
  EXPECT_EQ(around(2), (std::vector<std::uint32_t>{0, 1}));     // (0, 1, 0)
  EXPECT_EQ(around(4), (std::vector<std::uint32_t>{2}));        // (2, 0, 0)
}

}  // namespace mesh_wall_test
