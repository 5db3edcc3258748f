// SPDX-License-Identifier: MIT
// The pair loop's batched kernel inside whole runs: a run without an energy ledger (batched
// kernel) and the same run with one (evaluate_contact per pair) must stay bit-identical, step
// after step, through contacts that open and close, list rebuilds, reorders, two materials,
// both lever arms (and for Mindlin the r contact velocity), both tangential-history rules, a
// sphere under prescribed motion and any thread count. And the closing kick that the force field
// folds into its last pass must equal the scheme's own kick.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>
#include <string>

#include "dem/simulation/simulation.hpp"
#include "tests/dem/many_body_fixture.hpp"

namespace {

/// A settling box of two materials in a law the batched kernel evaluates: `normal` "linear" or
/// "hertz" with LAMMPS's mass-scaled dashpot and spring–Coulomb friction, "hertz_mindlin"
/// (Hertz, Tsuji's dashpot, incremental Mindlin friction, the tensile clamp) or
/// "hertz_mindlin_total" (the same with Mindlin friction in the total form: the box benchmark's).
dem::SimulationSetup batched_box(std::uint32_t seed, const std::string& normal, dem::PairLeverArm arm,
                                 dem::TangentialHistory history) {
  dem::SimulationSetup s =
      test_support::settling_box(seed, test_support::full_or_sanitized<std::size_t>(1000, 300), 1e-3, 0.3, 1, 1.6);
  dem::MaterialProperties a = test_support::grain(1e3);
  a.damping_rate = 40.0;
  a.youngs_modulus = 2e6;
  a.poisson_ratio = 0.3;
  dem::MaterialProperties b = test_support::grain(2e3);
  b.name = "harder";
  b.damping_rate = 80.0;
  b.friction = 0.3;
  b.youngs_modulus = 5e6;
  b.poisson_ratio = 0.25;
  s.materials = {a, b};
  for (std::size_t k = 0; k < s.particles.size(); k += 3) s.particles[k].material = 1;
  if (normal.starts_with("hertz_mindlin")) {  // the packing cases' law: Tsuji's dashpot, Mindlin
    s.model.normal = "hertz";
    s.model.damping = "tsuji";
    s.model.tangential = "mindlin_8g";
    s.model.mindlin_form = normal == "hertz_mindlin" ? dem::MindlinForm::incremental : dem::MindlinForm::total;
    s.model.clamp_tensile = true;
    s.materials[1].restitution = 0.8;
  } else {
    s.model.normal = normal;
    s.model.damping = "lammps_mass_velocity";
    s.model.tangential = "spring_coulomb";
  }
  s.model.pair_lever_arm = arm;
  s.model.tangential_history = history;
  s.model.friction_limit = dem::FrictionLimit::elastic_damping;
  return s;
}

/// Positions, velocities and spins of every sphere in setup order after `steps` steps.
struct Snapshot {
  dem::Vec3Array x, u, w;
};
Snapshot run(dem::SimulationSetup setup, bool ledger, int threads, int steps) {
  setup.track_energy = ledger;
  setup.threads = threads;
  dem::Simulation sim(setup);
  for (int n = 0; n < steps; ++n) sim.step();
  const auto count = static_cast<Eigen::Index>(setup.particles.size());
  Snapshot out{dem::Vec3Array(3, count), dem::Vec3Array(3, count), dem::Vec3Array(3, count)};
  for (std::uint32_t id = 0; id < setup.particles.size(); ++id) {
    const Eigen::Index at = sim.slot(id);
    out.x.col(id) = sim.state().position.col(at);
    out.u.col(id) = sim.state().velocity.col(at);
    out.w.col(id) = sim.state().angular_velocity.col(at);
  }
  EXPECT_GT(sim.force_field().interacting_pairs(), 100U);
  return out;
}

void expect_same(const Snapshot& a, const Snapshot& b, const std::string& what) {
  EXPECT_TRUE(a.x.cwiseEqual(b.x).all()) << what << ": positions differ";
  EXPECT_TRUE(a.u.cwiseEqual(b.u).all()) << what << ": velocities differ";
  EXPECT_TRUE(a.w.cwiseEqual(b.w).all()) << what << ": spins differ";
}

TEST(BatchedPairLoop, ALedgerNeverChangesTheTrajectory) {
  const int steps = test_support::full_or_sanitized(300, 100);
  std::uint32_t seed = 31;
  for (const char* normal : {"linear", "hertz", "hertz_mindlin", "hertz_mindlin_total"}) {
    int arm_index = 0;
    for (const auto arm : {dem::PairLeverArm::contact_point, dem::PairLeverArm::radius,
                           dem::PairLeverArm::radius_velocity}) {
      ++arm_index;
      if (arm == dem::PairLeverArm::radius_velocity && !std::string(normal).starts_with("hertz_mindlin")) continue;
      int history_index = 0;
      for (const auto history : {dem::TangentialHistory::project_rescale, dem::TangentialHistory::increment_project}) {
        const dem::SimulationSetup setup = batched_box(seed++, normal, arm, history);
        // Under the sanitizers every law meets every arm and both history rules, the rules
        // alternating over the arms, without the 2-thread rerun (thread counts: ManyBodyDeterminism).
        if (test_support::kSanitized && (arm_index + history_index++) % 2 == 0) continue;
        const std::string what = std::string(normal) + " arm " + std::to_string(static_cast<int>(arm)) +
                                 " history " + std::to_string(static_cast<int>(history));
        const Snapshot batched = run(setup, false, 1, steps);
        expect_same(batched, run(setup, true, 1, steps), what + ", ledger");
        if (!test_support::kSanitized) expect_same(batched, run(setup, false, 2, steps), what + ", 2 threads");
      }
    }
  }
}

TEST(BatchedPairLoop, TheSpringAloneCoulombTestIsNeverBatched) {
  // The kernel tests the whole force against the Coulomb limit; under CoulombTest::spring the pair
  // loop must leave every pair to evaluate_contact. With a tangential dashpot the two tests differ,
  // so a batched run would leave the ledger's (always unbatched) trajectory.
  const int steps = test_support::full_or_sanitized(300, 100);
  for (const char* normal : {"hertz", "hertz_mindlin_total"}) {
    dem::SimulationSetup setup =
        batched_box(47, normal, dem::PairLeverArm::contact_point, dem::TangentialHistory::project_rescale);
    setup.model.coulomb_test = dem::CoulombTest::spring;
    for (dem::MaterialProperties& m : setup.materials) m.tangential_damping_ratio = 0.5;
    expect_same(run(setup, false, 1, steps), run(setup, true, 1, steps), std::string(normal) + ", spring test");
  }
}

TEST(BatchedPairLoop, ADrivenSpherePushesThroughTheBatchAsThroughEvaluateContact) {
  // A fixed sphere under prescribed motion ploughs through the box: the batch must take its
  // motion's velocity, as evaluate_contact does.
  dem::SimulationSetup setup = batched_box(11, "hertz", dem::PairLeverArm::contact_point,
                                           dem::TangentialHistory::project_rescale);
  const std::uint32_t driven = static_cast<std::uint32_t>(setup.particles.size() / 2);
  setup.particles[driven].fixed = true;
  // The velocity changes every 3.05 steps: at those evaluations the motion's velocity differs
  // from the one the state held since the last step.
  std::vector<dem::MotionSegment> segments;
  for (int k = 0; k < 40; ++k) {
    segments.push_back({3.05 * setup.timestep, dem::Vec3(0.5 * std::cos(k), -0.3, 0.2 * std::sin(k))});
  }
  setup.motions = {{driven, setup.particles[driven].position, segments}};
  const int steps = test_support::full_or_sanitized(300, 100);
  expect_same(run(setup, false, 1, steps), run(setup, true, 1, steps), "driven sphere");
}

TEST(BatchedPairLoop, TheFoldedKickIsTheSchemesKick) {
  // One commit of the same state through ContactForceField's folded kick and through the
  // interface's plain commit-then-kick: identical velocities and spins, fixed spheres included.
  dem::SimulationSetup setup = batched_box(7, "linear", dem::PairLeverArm::radius,
                                           dem::TangentialHistory::increment_project);
  setup.particles[5].fixed = true;
  for (int s = 0; s < 20; ++s) {
    dem::Simulation folded(setup);
    dem::Simulation plain(setup);
    for (int n = 0; n < s; ++n) {
      folded.step();
      plain.step();
    }
    dem::KinematicState a = folded.state();
    dem::KinematicState b = plain.state();
    dem::Accelerations acc_a;
    dem::Accelerations acc_b;
    dem::ContactForceField& field_a = folded.force_field();
    dem::ContactForceField& field_b = plain.force_field();
    field_a.commit_and_kick(a, setup.timestep, acc_a, 0.5 * setup.timestep, true);
    field_b.ForceEvaluator::commit_and_kick(b, setup.timestep, acc_b, 0.5 * setup.timestep, true);
    ASSERT_TRUE(a.velocity.cwiseEqual(b.velocity).all()) << "after " << s << " steps";
    ASSERT_TRUE(a.angular_velocity.cwiseEqual(b.angular_velocity).all()) << "after " << s << " steps";
    ASSERT_TRUE(acc_a.linear.cwiseEqual(acc_b.linear).all());
  }
}

}  // namespace
