// SPDX-License-Identifier: MIT
// Simulation::advance carries each velocity-Verlet step's closing kick over to the next step's
// opening pass (ContactForceField::defer_closing_kick): the states must be those of stepping one
// step at a time, bit for bit, in every kind of scene the core runs.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "dem/simulation/simulation.hpp"
#include "many_body_fixture.hpp"

namespace deferred_kick_test {

using dem::Vec3;

/// Steps of a run: a third under the sanitizers (there the core steps ~190 times slower).
std::uint64_t steps(std::uint64_t full) { return test_support::full_or_sanitized<std::uint64_t>(full, full / 3); }

/// The state after `steps` steps, sphere by sphere in setup order, and the forces of the last commit.
struct Snapshot {
  dem::Vec3Array position, velocity, spin, force, torque;
  double time = 0.0;
  std::uint64_t reorders = 0;
  std::uint64_t deferred = 0;
  std::uint64_t weights = 0;
};

Snapshot take(const dem::Simulation& sim) {
  const auto n = static_cast<Eigen::Index>(sim.particles().size());
  Snapshot s;
  for (dem::Vec3Array* a : {&s.position, &s.velocity, &s.spin, &s.force, &s.torque}) a->resize(3, n);
  for (Eigen::Index id = 0; id < n; ++id) {
    const auto k = static_cast<Eigen::Index>(sim.slot(static_cast<std::uint32_t>(id)));
    s.position.col(id) = sim.state().position.col(k);
    s.velocity.col(id) = sim.state().velocity.col(k);
    s.spin.col(id) = sim.state().angular_velocity.col(k);
    s.force.col(id) = sim.force_field().forces().col(k);
    s.torque.col(id) = sim.force_field().torques().col(k);
  }
  s.time = sim.state().time;
  s.reorders = sim.reorders();
  s.deferred = sim.force_field().deferred_kicks();
  s.weights = sim.force_field().deferred_weights();
  return s;
}

/// What a run in stretches did: the closing kicks it deferred, the reorders within it.
struct StretchRun {
  std::uint64_t deferred = 0;
  std::uint64_t reorders = 0;
  std::uint64_t weights = 0;  // steps that owed their field pass (the weights) as well
};

/// Runs `setup` step by step, and in stretches of irregular length through advance(), with
/// snapshots after each stretch; expects every snapshot bit-identical.
StretchRun expect_advance_matches_steps(const dem::SimulationSetup& setup, std::uint64_t total,
                                           const char* what) {
  dem::Simulation by_step(setup);
  dem::Simulation by_stretch(setup);
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::uint64_t> length(1, 40);
  std::uint64_t done = 0;
  while (done < total) {
    const std::uint64_t count = std::min(total - done, length(rng));
    for (std::uint64_t k = 0; k < count; ++k) by_step.step();
    by_stretch.advance(count);
    done += count;
    const Snapshot a = take(by_step);
    const Snapshot b = take(by_stretch);
    EXPECT_EQ(b.time, a.time) << what;
    EXPECT_EQ(b.reorders, a.reorders) << what;
    EXPECT_EQ(a.deferred, 0U) << what << ": step() never defers";
    EXPECT_TRUE(b.position.cwiseEqual(a.position).all()) << what << ", after step " << done;
    EXPECT_TRUE(b.velocity.cwiseEqual(a.velocity).all()) << what << ", after step " << done;
    EXPECT_TRUE(b.spin.cwiseEqual(a.spin).all()) << what << ", after step " << done;
    EXPECT_TRUE(b.force.cwiseEqual(a.force).all()) << what << ", after step " << done;
    EXPECT_TRUE(b.torque.cwiseEqual(a.torque).all()) << what << ", after step " << done;
    if (::testing::Test::HasFailure()) return {b.deferred, b.reorders, b.weights};
  }
  // The stretches crossed contacts, list builds and reorders, not an empty box.
  EXPECT_GT(by_stretch.force_field().interacting_pairs(), 50U) << what;
  EXPECT_GT(by_stretch.force_field().list_builds(), 2U) << what;
  return {by_stretch.force_field().deferred_kicks(), by_stretch.reorders(),
          by_stretch.force_field().deferred_weights()};
}

/// A settling box small enough for every kind of scene below, with Morton reorders within the run.
dem::SimulationSetup box(std::uint32_t seed, int threads = 1) {
  dem::SimulationSetup s = test_support::settling_box(seed, test_support::full_or_sanitized<std::size_t>(600, 300),
                                                      1e-3, 0.3, threads, 1.6);
  s.neighbors.sort_every = 2;
  s.track_energy = false;                   // a run without a ledger: the one that defers
  s.scheme_settings.orientation = false;    // as the case files' velocity-Verlet runs
  return s;
}

/// The chute's kind of scene: no walls, a floor of fixed spheres (the lattice's bottom layer),
/// periodic in x and y, gravity tilted — the field pass would only add the weights, so a step
/// that owes its closing kick owes that pass too.
dem::SimulationSetup wall_free_box(std::uint32_t seed, int threads = 1) {
  dem::SimulationSetup s = box(seed, threads);
  const double width = s.walls[2].point.x();
  const double floor = s.particles.front().position.z();
  for (dem::ParticleInit& p : s.particles) p.fixed = p.position.z() == floor;
  s.walls.clear();
  s.fields.gravity = Vec3(3.0, -2.0, -9.81);
  s.box.lo = Vec3(0.0, 0.0, -0.05);
  s.box.hi = Vec3(width, width, 0.05);
  s.box.periodic = {true, true, false};
  return s;
}

TEST(DeferredClosingKick, AdvanceGivesTheStatesOfSteppingInAWalledBoxWithGravity) {
  for (const int threads : {1, 2}) {
    dem::SimulationSetup s = box(3, threads);
    // A few fixed spheres: never kicked nor drifted, whatever their forces.
    for (std::size_t k = 0; k < s.particles.size(); k += 9) s.particles[k].fixed = true;
    const StretchRun run = expect_advance_matches_steps(s, steps(300), threads == 1 ? "1 thread" : "2 threads");
    EXPECT_GT(run.deferred, steps(200)) << "the stretches deferred their closing kicks";
    EXPECT_GT(run.reorders, 0U) << "a reorder settles an owed kick within a stretch";
    EXPECT_EQ(run.weights, 0U) << "with walls, the field pass is never owed";
  }
}

TEST(DeferredClosingKick, AdvanceGivesTheStatesOfSteppingWithTheWeightsOwed) {
  for (const int threads : {1, 2}) {
    const dem::SimulationSetup s = wall_free_box(15, threads);
    const char* what = threads == 1 ? "no walls, 1 thread" : "no walls, 2 threads";
    const StretchRun run = expect_advance_matches_steps(s, steps(300), what);
    EXPECT_GT(run.deferred, steps(200)) << what;
    EXPECT_EQ(run.weights, run.deferred) << what << ": every deferred step owed the weights too";
    EXPECT_GT(run.reorders, 0U) << what << ": a reorder settles owed weights within a stretch";
  }
  // Only gravity adds nothing but weights: with a fluid the field pass runs at every step.
  dem::SimulationSetup fluid = wall_free_box(16);
  dem::Fluid f;
  f.buoyancy = true;
  fluid.fields.fluid = f;
  const StretchRun run = expect_advance_matches_steps(fluid, steps(200), "no walls, a fluid");
  EXPECT_GT(run.deferred, steps(100));
  EXPECT_EQ(run.weights, 0U);
}

TEST(DeferredClosingKick, AdvanceGivesTheStatesOfSteppingInAPeriodicBox) {
  dem::SimulationSetup s = box(4);
  const double width = s.walls[2].point.x();  // the lattice's side: periodic in x and y
  s.walls = {s.walls[0]};                     // the floor stays
  s.fields.gravity = Vec3(3.0, -2.0, -9.81);
  s.box.lo = Vec3(0.0, 0.0, -0.05);
  s.box.hi = Vec3(width, width, 0.05);
  s.box.periodic = {true, true, false};
  EXPECT_GT(expect_advance_matches_steps(s, steps(300), "periodic").deferred, steps(200));
}

TEST(DeferredClosingKick, AdvanceGivesTheStatesOfSteppingInAFluidWithAddedMass) {
  // Not gravity alone: the accelerations divide by the mass plus the fluid's virtual mass.
  dem::SimulationSetup s = box(5);
  dem::Fluid fluid;
  fluid.virtual_mass = true;
  fluid.buoyancy = true;
  fluid.velocity.uniform = Vec3(0.5, 0.0, 0.2);
  s.fields.fluid = fluid;
  EXPECT_GT(expect_advance_matches_steps(s, steps(300), "fluid").deferred, steps(200));
}

TEST(DeferredClosingKick, AdvanceWithoutSpinsOrWithOrientationsALedgerOrAMotionGivesTheSteppedStates) {
  {
    dem::SimulationSetup s = box(6);
    s.scheme_settings.rotation = false;
    EXPECT_GT(expect_advance_matches_steps(s, steps(200), "no rotation").deferred, steps(100));
  }
  {
    // Orientations are turned by the scheme's own pass: nothing is deferred.
    dem::SimulationSetup s = box(10);
    s.scheme_settings.orientation = true;
    EXPECT_EQ(expect_advance_matches_steps(s, steps(200), "orientation").deferred, 0U);
  }
  {
    // A ledger books every step's velocities: nothing is deferred.
    dem::SimulationSetup s = box(7);
    s.track_energy = true;
    EXPECT_EQ(expect_advance_matches_steps(s, steps(200), "ledger").deferred, 0U);
  }
  {
    // A prescribed motion overwrites its sphere's velocity after every step: nothing is deferred.
    dem::SimulationSetup s = box(8);
    s.track_energy = false;
    s.particles[0].fixed = true;
    s.motions.push_back({0, s.particles[0].position, {{1.0, Vec3(0.0, 0.0, 0.05)}}});
    EXPECT_EQ(expect_advance_matches_steps(s, steps(200), "motion").deferred, 0U);
  }
}

/// The fused step (the field's verlet_step) against the scheme's own passes (kick_and_drift, then
/// commit_and_kick): a run that turns orientations never fuses, and orientations feed back into
/// nothing, so both runs must hold the same states bit for bit — stepped, and advanced.
void expect_fused_matches_own_passes(dem::SimulationSetup setup, const char* what) {
  setup.scheme_settings.orientation = true;
  dem::Simulation own(setup);
  setup.scheme_settings.orientation = false;
  dem::Simulation fused(setup);
  dem::Simulation advanced(setup);
  const std::uint64_t stretch = 9;
  for (std::uint64_t done = 0; done < steps(180); done += stretch) {
    for (std::uint64_t k = 0; k < stretch; ++k) {
      own.step();
      fused.step();
    }
    advanced.advance(stretch);
    const Snapshot a = take(own);
    for (const Snapshot& b : {take(fused), take(advanced)}) {
      EXPECT_TRUE(b.position.cwiseEqual(a.position).all()) << what << ", after step " << done + stretch;
      EXPECT_TRUE(b.velocity.cwiseEqual(a.velocity).all()) << what << ", after step " << done + stretch;
      EXPECT_TRUE(b.spin.cwiseEqual(a.spin).all()) << what << ", after step " << done + stretch;
      EXPECT_TRUE(b.force.cwiseEqual(a.force).all()) << what << ", after step " << done + stretch;
      EXPECT_TRUE(b.torque.cwiseEqual(a.torque).all()) << what << ", after step " << done + stretch;
    }
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(own.force_field().interacting_pairs(), 50U) << what;
  EXPECT_GT(advanced.force_field().deferred_kicks(), steps(100)) << what;
  // Wall-free gravity-only scenes owe their field pass too (the others never do).
  const bool weights = setup.walls.empty() && setup.fields.gravity_only();
  EXPECT_EQ(advanced.force_field().deferred_weights(), weights ? advanced.force_field().deferred_kicks() : 0U) << what;
}

TEST(FusedVerletStep, GivesTheStatesOfTheSchemesOwnPasses) {
  dem::SimulationSetup walled = box(11);
  for (std::size_t k = 0; k < walled.particles.size(); k += 9) walled.particles[k].fixed = true;
  expect_fused_matches_own_passes(walled, "walled box, fixed spheres");
  dem::SimulationSetup fluid = box(12);
  dem::Fluid f;
  f.virtual_mass = true;
  f.velocity.uniform = Vec3(0.3, 0.0, 0.1);
  fluid.fields.fluid = f;
  expect_fused_matches_own_passes(fluid, "fluid with virtual mass");
  dem::SimulationSetup two = box(14, 2);
  expect_fused_matches_own_passes(two, "2 threads");
  expect_fused_matches_own_passes(wall_free_box(17), "no walls: the weights owed with the kick");
}

TEST(DeferredClosingKick, OtherSchemesAdvanceAsTheyStep) {
  dem::SimulationSetup s = box(9);
  s.scheme = dem::SchemeId::leapfrog;
  EXPECT_EQ(expect_advance_matches_steps(s, steps(150), "leapfrog").deferred, 0U);
}

}  // namespace deferred_kick_test
