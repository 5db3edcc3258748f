// SPDX-License-Identifier: MIT
// Bounded walls in the many-body loop: forces against a brute-force sum over every sphere and
// wall along a run (never a missed contact), a plate's face against a plane, rebounds off an edge
// and a cylinder, and a plate removed under a resting sphere (an orifice that opens).
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/simulation/simulation.hpp"
#include "wall_builders.hpp"

namespace bounded_walls_test {

using dem::Vec3;
using dem::Wall;
using dem::WallShape;

using test_support::annulus;
using test_support::frustum;
using test_support::rectangle;

/// Elastic, frictionless linear spheres (forces depend on positions only).
dem::MaterialProperties elastic(double stiffness) {
  dem::MaterialProperties m;
  m.name = "elastic";
  m.density = 2500.0;
  m.normal_stiffness = stiffness;
  return m;
}

/// A funnel over a catch plate: a cylinder on a cone with a round orifice, a ring shelf, a tilted
/// plate below, and random spheres (radii 0.4–1 mm, not overlapping) thrown down through it.
dem::SimulationSetup funnel(std::uint32_t seed, std::size_t n) {
  dem::SimulationSetup s;
  s.materials = {elastic(2e3)};
  s.walls = {frustum(Vec3(0, 0, 0.010), Vec3::UnitZ(), 0.02, 0.008, 0.008),
             frustum(Vec3(0, 0, 0.0), Vec3::UnitZ(), 0.010, 0.003, 0.008),
             annulus(Vec3(0, 0, 0.004), Vec3::UnitZ(), 0.0045, 0.0065),
             rectangle(Vec3(0.001, 0, -0.006), Vec3(0.2, 0, 1).normalized(), Vec3(1, 0, -0.2).normalized(), 0.006, 0.004)};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  while (s.particles.size() < n) {
    const double r = 4e-4 + 6e-4 * unit(rng);
    const double rho = (0.0075 - r) * std::sqrt(unit(rng));
    const double phi = 2.0 * std::numbers::pi * unit(rng);
    const Vec3 x(rho * std::cos(phi), rho * std::sin(phi), 0.011 + 0.014 * unit(rng));
    bool free = true;
    for (const auto& p : s.particles) free = free && (p.position - x).norm() > p.radius + r;
    if (!free) continue;
    s.particles.push_back({r, r, 2500.0, 0, x, Vec3(2.0 * unit(rng) - 1.0, 2.0 * unit(rng) - 1.0, -1.0 - 2.0 * unit(rng)),
                           Vec3::Zero(), false});
  }
  s.fields.gravity = Vec3(0, 0, -9.81);
  s.timestep = 5e-6;
  s.scheme_settings.rotation = false;
  return s;
}

/// Forces on every sphere from a brute-force sum over all pairs and all (sphere, wall) pairs;
/// `wall_contacts` counts the interacting (sphere, wall) pairs.
dem::Vec3Array brute_force_forces(const dem::Simulation& sim, int& wall_contacts) {
  const auto& props = sim.particles();
  const auto& state = sim.state();
  const auto n = static_cast<Eigen::Index>(props.size());
  dem::Vec3Array f = dem::Vec3Array::Zero(3, n);
  const auto sphere = [&](Eigen::Index i) {
    return dem::SphereState{state.position.col(i), state.velocity.col(i), state.angular_velocity.col(i),
                            props.radius[i], props.effect_radius[i], props.inverse_mass[i]};
  };
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i + 1; j < n; ++j) {
      const auto c = dem::evaluate_contact(sim.pair_table().law(0, 0), dem::pair_geometry(sphere(i), sphere(j)), {}, 0.0);
      if (!c.interacting) continue;
      f.col(i) += c.force_on_p;
      f.col(j) -= c.force_on_p;
    }
    for (const Wall& w : sim.force_field().walls()) {
      const dem::ContactGeometry g = dem::wall_geometry(sphere(i), w, sim.time(), dem::WallLeverArm::contact_point);
      const auto c = dem::evaluate_contact(sim.pair_table().law(0, w.material), g, {}, 0.0);
      if (!c.interacting) continue;
      f.col(i) += c.force_on_p;
      ++wall_contacts;
    }
    f.col(i) += props.mass[i] * sim.force_field().fields().gravity;
  }
  return f;
}

TEST(BoundedWalls, ForcesMatchABruteForceSumAlongARun) {
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    dem::Simulation sim(funnel(seed, 400));
    int wall_contacts = 0;
    for (int step = 0; step <= 2000; ++step) {
      if (step % 100 == 0) {
        const dem::Vec3Array expected = brute_force_forces(sim, wall_contacts);
        const dem::Vec3Array& got = sim.force_field().forces();
        for (Eigen::Index i = 0; i < expected.cols(); ++i) {
          const double weight = sim.particles().mass[i] * 9.81;
          ASSERT_LT((got.col(i) - expected.col(i)).norm(), 1e-9 * std::max(weight, expected.col(i).norm()))
              << "seed " << seed << " step " << step << " sphere " << i;
        }
      }
      sim.step();
    }
    EXPECT_GT(wall_contacts, 100) << "seed " << seed << ": the run must press spheres on the walls";
  }
}

/// One sphere of radius 1 mm falling at 1 m/s onto a wall; linear spring, e = 1.
dem::SimulationSetup drop_onto(const Wall& wall, const Vec3& start, const Vec3& velocity) {
  dem::SimulationSetup s;
  s.materials = {elastic(1e4)};
  s.particles = {{1e-3, 1e-3, 2500.0, 0, start, velocity, Vec3::Zero(), false}};
  s.walls = {wall};
  s.timestep = 1e-7;
  s.scheme_settings.rotation = false;
  return s;
}

TEST(BoundedWalls, APlateFaceActsAsAPlane) {
  const Vec3 start(0.2e-3, -0.1e-3, 1.5e-3);
  const Vec3 velocity(0.05, 0.02, -1.0);
  dem::Simulation plate(drop_onto(rectangle(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 5e-3, 5e-3), start, velocity));
  dem::Simulation plane(drop_onto(Wall{Vec3::Zero(), Vec3::UnitZ()}, start, velocity));
  for (int k = 0; k < 20000; ++k) {
    plate.step();
    plane.step();
    ASSERT_LT((plate.state().position.col(0) - plane.state().position.col(0)).norm(), 1e-15);
    ASSERT_LT((plate.state().velocity.col(0) - plane.state().velocity.col(0)).norm(), 1e-12);
  }
  EXPECT_NEAR(plate.state().velocity(2, 0), 1.0, 1e-3);  // rebounded
}

TEST(BoundedWalls, ASpherePassesBesideAPlateAndIsDeflectedByItsEdge) {
  const Wall plate = rectangle(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 5e-3, 5e-3);
  // Beside the plate (the edge at x = 5 mm, radius 1 mm): it falls past untouched.
  dem::Simulation past(drop_onto(plate, Vec3(6.01e-3, 0, 1.5e-3), Vec3(0, 0, -1.0)));
  while (past.time() < 4e-3) past.step();
  EXPECT_EQ(past.state().velocity.col(0), Vec3(0, 0, -1.0));
  // Onto the edge, centre √½ mm outside it: the contact normal is at 45°, so an elastic,
  // frictionless rebound turns the fall into a sideways flight (u' = u − 2(u·n)n = +x). The
  // normal turns while the sphere rolls over the edge, by about the distance it travels during the
  // contact over r, ∝ √(m/k): stiffer contacts come closer to the reflection.
  const double s = std::sqrt(0.5);
  double deviation_soft = 0.0;
  for (const double k : {1e4, 1e6}) {
    dem::SimulationSetup setup = drop_onto(plate, Vec3(5e-3 + s * 1e-3, 0, 1.5e-3), Vec3(0, 0, -1.0));
    setup.materials[0].normal_stiffness = k;
    setup.timestep = 1e-7 * std::sqrt(1e4 / k);  // the same ω Δt, so the same Verlet energy error
    dem::Simulation edge(setup);
    while (edge.time() < 3e-3) edge.step();
    const Vec3 u = edge.state().velocity.col(0);
    EXPECT_NEAR(u.norm(), 1.0, 1e-5) << "k = " << k;  // elastic: the speed is kept
    EXPECT_EQ(u[1], 0.0);
    const double deviation = std::abs(std::atan2(u[2], u[0]));
    if (k == 1e4) {
      deviation_soft = deviation;
      EXPECT_GT(deviation, 0.02);
      EXPECT_LT(deviation, 0.15);
    } else {
      EXPECT_LT(deviation, 0.15 * deviation_soft);  // ten times stiffer: about a tenth of the turn
      EXPECT_GT(u[0], 0.99);
    }
  }
}

TEST(BoundedWalls, ASphereInsideACylinderRebouncesFromItsSide) {
  const Wall tube = frustum(Vec3(0, 0, -0.01), Vec3::UnitZ(), 0.02, 4e-3, 4e-3);
  dem::Simulation sim(drop_onto(tube, Vec3(1e-3, 1e-3, 0), Vec3(1.0, 0.0, 0.0)));
  double closest_to_axis_far = 0.0;
  while (sim.time() < 8e-3) {
    sim.step();
    const Vec3& x = sim.state().position.col(0);
    closest_to_axis_far = std::max(closest_to_axis_far, std::hypot(x[0], x[1]));
  }
  EXPECT_LT(closest_to_axis_far, 4e-3 - 1e-3 + 1e-4);  // never deeper than a small overlap
  EXPECT_GT(closest_to_axis_far, 4e-3 - 1e-3);          // but it reached the side
  EXPECT_NEAR(sim.state().velocity.col(0).norm(), 1.0, 1e-5);
  EXPECT_NEAR(sim.state().velocity(2, 0), 0.0, 1e-12);
}

TEST(WallRemoval, ASphereRestingOnAPlateFallsOnceItIsRemovedAndTheLedgerBooksItsSpring) {
  // A sphere at rest on a plate, pressed in by exactly its weight (δ = mg/k), no damping.
  const double k = 100.0;
  const double r = 1e-3;
  const double m = 2500.0 * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double g = 9.81;
  const double delta = m * g / k;
  Wall plate = rectangle(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 5e-3, 5e-3);
  plate.removed_at = 2e-3;
  dem::SimulationSetup s = drop_onto(plate, Vec3(0, 0, r - delta), Vec3::Zero());
  s.materials[0].normal_stiffness = k;
  s.fields.gravity = Vec3(0, 0, -g);
  s.timestep = 1e-6;
  dem::Simulation sim(s);
  const double stored = sim.energy().elastic;
  EXPECT_NEAR(stored, 0.5 * k * delta * delta, 1e-9 * stored);
  while (sim.time() < 2e-3 - 0.5e-6) sim.step();
  EXPECT_NEAR(sim.state().position(2, 0), r - delta, 1e-12);  // held while the plate is there
  while (sim.time() < 6e-3 - 0.5e-6) sim.step();
  // Free fall for 4 ms from the release (the step after 2 ms sees no plate).
  const double fall = 0.5 * g * 4e-3 * 4e-3;
  EXPECT_NEAR(sim.state().position(2, 0), r - delta - fall, 1e-3 * fall);
  const dem::EnergyLedger e = sim.energy();
  EXPECT_EQ(e.elastic, 0.0);
  EXPECT_NEAR(e.boundary_work, -stored, 1e-6 * stored);  // the plate took its spring energy away
  // The one energy the integration makes: in the step that ends at the removal, velocity Verlet's
  // closing half kick already sees the plate gone, so the sphere leaves with u = g Δt/2 and no
  // potential spent, ½ m (g Δt/2)² — an O(Δt²) artefact of the force's jump, not the spring's
  // energy (which is 4·10⁵ times more and sits in boundary_work).
  const double kick = 0.5 * m * std::pow(0.5 * g * s.timestep, 2);
  EXPECT_NEAR(e.integration_error, kick, 1e-3 * kick);
}

}  // namespace bounded_walls_test
