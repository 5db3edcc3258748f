// SPDX-License-Identifier: MIT
// The many-body loop: forces against a brute-force sum over all pairs, determinism across
// thread counts, reordering, wall history per (sphere, wall), periodic boundaries.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/core/model_error.hpp"
#include "many_body_fixture.hpp"

namespace many_body_test {

using dem::Vec3;

/// Random overlapping spheres (a dense, jammed start) with random velocities and spins.
dem::SimulationSetup jammed(std::uint32_t seed, std::size_t n, double side, bool periodic) {
  dem::SimulationSetup s = test_support::settling_box(seed, 1);
  s.particles.clear();
  s.walls.clear();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (std::size_t k = 0; k < n; ++k) {
    const double r = 1e-3 * (0.5 + unit(rng));
    s.particles.push_back({r, r, 2500.0, 0, Vec3(unit(rng), unit(rng), unit(rng)) * side,
                           Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5),
                           Vec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5) * 100.0, k % 7 == 0});
    if (k % 7 == 0) {
      s.particles.back().velocity.setZero();
      s.particles.back().angular_velocity.setZero();
    }
  }
  if (periodic) {
    s.box.lo = Vec3::Zero();
    s.box.hi = Vec3::Constant(side);
    s.box.periodic = {true, true, true};
  }
  return s;
}

/// Forces on every sphere from a brute-force sum of evaluate_contact over all pairs (fresh
/// history, minimum image), plus gravity on the mobile ones.
dem::Vec3Array brute_force_forces(const dem::Simulation& sim) {
  const auto& props = sim.particles();
  const auto& state = sim.state();
  const auto n = static_cast<Eigen::Index>(props.size());
  dem::Vec3Array f = dem::Vec3Array::Zero(3, n);
  const dem::PeriodicBox& box = sim.force_field().box();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i + 1; j < n; ++j) {
      if (props.fixed[static_cast<std::size_t>(i)] != 0 && props.fixed[static_cast<std::size_t>(j)] != 0) continue;
      const dem::SphereState p{state.position.col(i), state.velocity.col(i), state.angular_velocity.col(i),
                               props.radius[i], props.effect_radius[i], props.inverse_mass[i]};
      dem::SphereState q{state.position.col(j), state.velocity.col(j), state.angular_velocity.col(j),
                         props.radius[j], props.effect_radius[j], props.inverse_mass[j]};
      q.position -= box.minimum_image_shift(p.position - q.position);
      const auto c = dem::evaluate_contact(sim.pair_table().law(0, 0), dem::pair_geometry(p, q), {}, 0.0);
      if (!c.interacting) continue;
      f.col(i) += c.force_on_p;
      f.col(j) -= c.force_on_p;
    }
    if (props.fixed[static_cast<std::size_t>(i)] == 0) f.col(i) += props.mass[i] * sim.force_field().fields().gravity;
  }
  return f;
}

TEST(ManyBodyForces, MatchABruteForceSumOverAllPairs) {
  for (const bool periodic : {false, true}) {
    for (std::uint32_t seed = 1; seed <= test_support::full_or_sanitized(4U, 2U); ++seed) {
      const dem::Simulation sim(jammed(seed, 700, 0.02, periodic));
      const dem::Vec3Array expected = brute_force_forces(sim);
      const dem::Vec3Array& got = sim.force_field().forces();
      ASSERT_GT(sim.force_field().interacting_pairs(), 200U);
      for (Eigen::Index i = 0; i < expected.cols(); ++i) {
        const double scale = std::max(1.0, expected.col(i).norm());
        ASSERT_LT((got.col(i) - expected.col(i)).norm(), 1e-12 * scale)
            << "seed " << seed << (periodic ? " periodic" : "") << " sphere " << i;
      }
    }
  }
}

/// Positions of every sphere in setup order after `steps` steps with `threads` threads.
dem::Vec3Array run(dem::SimulationSetup setup, int threads, int steps, std::uint64_t* reorders = nullptr) {
  setup.threads = threads;
  dem::Simulation sim(setup);
  for (int n = 0; n < steps; ++n) sim.step();
  dem::Vec3Array out(3, static_cast<Eigen::Index>(setup.particles.size()));
  for (std::uint32_t id = 0; id < setup.particles.size(); ++id) {
    out.col(id) = sim.state().position.col(sim.slot(id));
  }
  if (reorders != nullptr) *reorders = sim.reorders();
  return out;
}

TEST(ManyBodyDeterminism, RerunsAreBitIdenticalForAnyThreadCount) {
  // 2,000 frictional spheres settling in a walled box: contacts, walls, list rebuilds and
  // Morton reorders all happen within the run. Under the sanitizers 600: still more than one of
  // the 512-sphere chunks the threads share out (dem::balanced_for), so that code runs there too.
  const dem::SimulationSetup setup =
      test_support::settling_box(21, test_support::full_or_sanitized<std::size_t>(2000, 600));
  std::uint64_t reorders = 0;
  const dem::Vec3Array one = run(setup, 1, 400, &reorders);
  EXPECT_GT(reorders, 0U);
  EXPECT_TRUE(one.cwiseEqual(run(setup, 1, 400)).all()) << "rerun differs";
  EXPECT_TRUE(one.cwiseEqual(run(setup, 2, 400)).all()) << "2 threads differ";
  EXPECT_TRUE(one.cwiseEqual(run(setup, 3, 400)).all()) << "3 threads differ";
}

TEST(ManyBodyDeterminism, PeriodicJammedScenesToo) {
  // Under the sanitizers a third of the spheres in a third of the volume (the same density).
  dem::SimulationSetup setup = test_support::kSanitized ? jammed(5, 500, 0.03 / std::cbrt(3.0), true)
                                                         : jammed(5, 1500, 0.03, true);
  setup.timestep = 5e-6;
  const dem::Vec3Array one = run(setup, 1, 200);
  EXPECT_TRUE(one.cwiseEqual(run(setup, 2, 200)).all());
}

TEST(ManyBodyReorder, KeepsEveryContactAndItsHistory) {
  // Equal spheres on a lattice 1 % tighter than touching: every neighbour is in contact.
  dem::SimulationSetup setup =
      test_support::settling_box(8, test_support::full_or_sanitized<std::size_t>(1000, 343), 1e-3, 0.0, 1, 1.98);
  setup.neighbors.sort_every = 0;  // reorder only when asked
  dem::Simulation plain(setup);
  dem::Simulation sorted(setup);
  for (int n = 0; n < 300; ++n) {
    plain.step();
    sorted.step();
  }
  sorted.reorder();
  ASSERT_EQ(sorted.reorders(), 1U);
  ASSERT_GT(plain.force_field().interacting_pairs(), 500U);
  EXPECT_EQ(sorted.force_field().interacting_pairs(), plain.force_field().interacting_pairs());
  for (std::uint32_t a = 0; a < setup.particles.size(); a += 7) {
    for (std::uint32_t b = a + 1; b < setup.particles.size(); b += 13) {
      const dem::ContactHistory h1 = plain.force_field().pair_history(plain.slot(a), plain.slot(b));
      const dem::ContactHistory h2 = sorted.force_field().pair_history(sorted.slot(a), sorted.slot(b));
      ASSERT_EQ(h1.tangential_slip, h2.tangential_slip) << a << "–" << b;
    }
  }
  for (int n = 0; n < 50; ++n) {
    plain.step();
    sorted.step();
  }
  double worst = 0.0;
  for (std::uint32_t id = 0; id < setup.particles.size(); ++id) {
    worst = std::max(worst, (plain.state().position.col(plain.slot(id)) -
                             sorted.state().position.col(sorted.slot(id))).norm());
  }
  EXPECT_LT(worst, 1e-12);  // summation order only: round-off
}

TEST(ManyBodyHistory, ContactsOfEachSlabSitInDenseSlotsInListOrder) {
  // After commits with and without rebuilds, slab s's interacting pairs hold the slots
  // base(s), base(s) + 1, … in list order, and their histories match a brute-force pairing.
  dem::SimulationSetup setup =
      test_support::settling_box(10, test_support::full_or_sanitized<std::size_t>(1000, 600), 1e-3, 0.0, 1, 1.98);
  setup.threads = 2;
  dem::Simulation sim(setup);
  std::uint64_t builds_seen = 0;
  for (int n = 0; n < 400; ++n) {
    sim.step();
    if (n % 50 != 49) continue;
    const dem::NeighborList& list = sim.force_field().neighbors();
    builds_seen = list.builds();
    const dem::SlabPartition& slabs = list.slabs();
    ASSERT_GT(slabs.count(), 1U);
    std::size_t contacts = 0;
    for (std::uint32_t s = 0; s < slabs.count(); ++s) {
      std::uint32_t expected = list.slab_contact_base(s);
      for (const std::uint32_t i : slabs.members(s)) {
        for (std::uint32_t k = list.begin(i); k < list.begin(i + 1); ++k) {
          if (!list.active(k)) continue;
          ASSERT_EQ(list.contacts()[k], expected) << "step " << n << ", slab " << s;
          ++expected;
          ++contacts;
        }
      }
      if (s + 1 < slabs.count()) {
        ASSERT_LE(expected, list.slab_contact_base(s + 1));
      }
    }
    EXPECT_EQ(contacts, sim.force_field().interacting_pairs());
    EXPECT_GT(contacts, 500U);
  }
  EXPECT_GT(builds_seen, 2U);  // the layout held across rebuilds too
}

TEST(WallHistory, IsKeptPerSphereAndWall) {
  // Sphere 0 slides on wall 1 while sphere 1 slides on wall 0. Their contacts must not share a
  // history: each sphere moves exactly as it does alone.
  const auto setup_with = [](bool first, bool second) {
    dem::SimulationSetup s = test_support::settling_box(1, 1);
    s.particles.clear();
    s.walls = {{Vec3(0, 0, 0), Vec3(0, 0, 1)}, {Vec3(0, 0, 0), Vec3(1, 0, 0)}};
    s.fields.gravity = Vec3(-9.81, 0, -9.81);
    const double r = 1e-3;
    if (first) s.particles.push_back({r, r, 2500.0, 0, Vec3(r - 1e-6, 0, 0.5), Vec3(0, 0.1, 0), Vec3::Zero(), false});
    if (second) s.particles.push_back({r, r, 2500.0, 0, Vec3(0.5, 0, r - 1e-6), Vec3(0, -0.1, 0), Vec3::Zero(), false});
    return s;
  };
  dem::Simulation both(setup_with(true, true));
  dem::Simulation first(setup_with(true, false));
  dem::Simulation second(setup_with(false, true));
  for (int n = 0; n < 3000; ++n) {
    both.step();
    first.step();
    second.step();
    ASSERT_EQ(both.state().position.col(0), first.state().position.col(0)) << "step " << n;
    ASSERT_EQ(both.state().position.col(1), second.state().position.col(0)) << "step " << n;
  }
  EXPECT_GT(first.state().angular_velocity.col(0).norm(), 1.0);  // friction acted
}

/// An empty 0.1 m box, periodic along x only, without walls or gravity.
dem::SimulationSetup empty_periodic_x_box() {
  dem::SimulationSetup s = test_support::settling_box(1, 1);
  s.particles.clear();
  s.walls.clear();
  s.fields.gravity.setZero();
  s.box.lo = Vec3(0, 0, 0);
  s.box.hi = Vec3(0.1, 0.1, 0.1);
  s.box.periodic = {true, false, false};
  return s;
}

/// x brought into [0, 0.1) from just below 0.
double wrap_x(double x) { return x < 0.0 ? x + 0.1 : x; }

TEST(PeriodicBoundary, APairAcrossTheBoundaryActsLikeAnInteriorPair) {
  const auto pair_at = [](double x0) {
    dem::SimulationSetup s = empty_periodic_x_box();
    const double r = 1e-3;
    const auto wrap = wrap_x;
    s.particles.push_back({r, r, 2500.0, 0, Vec3(wrap(x0 - 0.9 * r), 0.05, 0.05), Vec3(0.3, 0.1, 0), Vec3(0, 0, 50), false});
    s.particles.push_back({r, r, 2500.0, 0, Vec3(x0 + 0.9 * r, 0.05, 0.05), Vec3(-0.3, 0, 0.2), Vec3(10, 0, 0), false});
    return s;
  };
  dem::Simulation across(pair_at(0.0));
  dem::Simulation inside(pair_at(0.05));
  for (int n = 0; n < 200; ++n) {
    const Vec3 f1 = across.force_field().forces().col(1);
    const Vec3 f2 = inside.force_field().forces().col(1);
    ASSERT_LT((f1 - f2).norm(), 1e-9 * std::max(1.0, f2.norm())) << "step " << n;
    across.step();
    inside.step();
  }
  EXPECT_GT(across.force_field().forces().col(1).norm() + inside.state().velocity.col(1).norm(), 0.0);
}

TEST(PeriodicBoundary, ASphereUnderPrescribedMotionCrossingTheBoundaryPushesAsInside) {
  // A driven sphere (fixed, moved by its prescribed motion) runs into a free one and crosses the
  // periodic face while they touch: the builds wrap it by where its motion puts it, so the free
  // sphere feels what it feels in the middle of the box.
  const auto push_at = [](double x0) {
    dem::SimulationSetup s = empty_periodic_x_box();
    const double r = 1e-3;
    const auto wrap = wrap_x;
    const Vec3 start(wrap(x0 - 3.0 * r), 0.05, 0.05);
    s.particles.push_back({r, r, 2500.0, 0, start, Vec3::Zero(), Vec3::Zero(), true});
    s.particles.push_back({r, r, 2500.0, 0, Vec3(x0 + 0.9 * r, 0.0502, 0.05), Vec3::Zero(), Vec3::Zero(), false});
    s.motions.push_back({0, start, {{1.0, Vec3(1.0, 0.0, 0.0)}}});
    return s;
  };
  dem::Simulation across(push_at(0.0));
  dem::Simulation inside(push_at(0.05));
  double largest = 0.0;
  for (int n = 0; n < 400; ++n) {
    across.step();
    inside.step();
    const Vec3 f1 = across.force_field().forces().col(1);
    const Vec3 f2 = inside.force_field().forces().col(1);
    ASSERT_LT((f1 - f2).norm(), 1e-9 * std::max(1.0, f2.norm())) << "step " << n;
    largest = std::max(largest, f2.norm());
  }
  EXPECT_GT(across.state().position(0, 0), 0.1) << "the driven sphere crossed the face";
  EXPECT_GT(largest, 1e-2) << "the spheres touched";
  EXPECT_GT(across.state().velocity(0, 1), 0.5) << "the free sphere was pushed along";
  EXPECT_GT(across.force_field().list_builds(), 10U);
}

TEST(PeriodicBoundary, PositionsStayUnwrappedInTheState) {
  dem::SimulationSetup s = test_support::settling_box(1, 1);
  s.particles = {{1e-3, 1e-3, 2500.0, 0, Vec3(0.095, 0.05, 0.05), Vec3(1.0, 0, 0), Vec3::Zero(), false}};
  s.walls.clear();
  s.fields.gravity.setZero();
  s.box.hi = Vec3(0.1, 0.1, 0.1);
  s.box.periodic = {true, true, true};
  dem::Simulation sim(s);
  for (int n = 0; n < 3000; ++n) sim.step();  // 0.03 m at 1 m/s: crosses x = 0.1
  EXPECT_NEAR(sim.state().position(0, 0), 0.125, 1e-12);
}

TEST(PeriodicBoundary, ABoxShorterThanTwiceTheListedReachIsAnError) {
  dem::SimulationSetup s = test_support::settling_box(1, 8);
  s.walls.clear();
  s.box.hi = Vec3(0.003, 1, 1);
  s.box.periodic = {true, false, false};
  EXPECT_THROW(dem::Simulation{s}, dem::ModelError);
}

}  // namespace
