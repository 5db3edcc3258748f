// SPDX-License-Identifier: MIT
// The packed bed over a run: ORF and dose at every snapshot, and the fluidisation metrics read from
// that curve (the time the ORF falls to a threshold, the largest fall between two snapshots).
#include "compare/packing_series.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "compare/metrics.hpp"

namespace packing_series_test {

/// Two mobile spheres (r = 0.3) and a fixed one in a unit-square reservoir seen along x through a
/// 1 × 1 ORF grid (one point, the face's centre (y, z) = (0.5, 0.5)). Snapshot k moves the mobile
/// spheres out one by one: sphere 0 covers the point until it leaves, sphere 1 sits off the point
/// (it counts in the dose, not the ORF) until it leaves. The fixed sphere covers the point always
/// and counts in neither.
struct Bed {
  cases::Scene scene;
  cases::RunResult run;
};

Bed bed(const std::vector<std::array<bool, 2>>& inside, double dt) {
  Bed b;
  for (const double r : {0.3, 0.3, 0.3}) {
    cases::ParticleSpec p;
    p.radius = r;
    b.scene.particles.push_back(p);
  }
  b.scene.particles[2].fixed = true;
  b.scene.compare.packing = cases::PackingSpec{{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, std::nullopt, 1, 1};
  b.run.status = cases::RunStatus::ok;
  for (std::size_t k = 0; k < inside.size(); ++k) {
    cases::Snapshot s;
    s.time = static_cast<double>(k) * dt;
    s.position = {inside[k][0] ? cases::Vector3{0.5, 0.5, 0.5} : cases::Vector3{0.5, 5.0, 0.5},
                  inside[k][1] ? cases::Vector3{0.5, 0.1, 0.1} : cases::Vector3{0.5, 5.0, 5.0},
                  cases::Vector3{0.5, 0.5, 0.5}};
    b.run.snapshots.push_back(s);
  }
  return b;
}

TEST(PackingSeries, FollowsTheOrfAndTheDoseSnapshotBySnapshotCountingMobileSpheresOnly) {
  const Bed b = bed({{true, true}, {true, false}, {false, false}}, 0.5);
  const auto series = comparison::packing_series(b.scene, b.run);
  const auto& s = std::get<std::vector<comparison::PackingSample>>(series);
  ASSERT_EQ(s.size(), 3U);
  EXPECT_EQ(s[0].time, 0.0);
  EXPECT_EQ(s[2].time, 1.0);
  EXPECT_EQ(s[0].orf, 1.0);
  EXPECT_EQ(s[0].dose_remaining, 1.0);
  EXPECT_EQ(s[1].orf, 1.0);  // sphere 1 never covered the point
  EXPECT_EQ(s[1].dose_remaining, 0.5);
  EXPECT_EQ(s[2].orf, 0.0);  // the fixed sphere still covers it, but is not the dose
  EXPECT_EQ(s[2].dose_remaining, 0.0);
}

TEST(PackingSeries, SaysWhyThereIsNoCurve) {
  Bed b = bed({{true, true}, {false, false}}, 1.0);
  b.run.snapshots[1].position.pop_back();
  const auto short_snapshot = comparison::packing_series(b.scene, b.run);
  ASSERT_TRUE(std::holds_alternative<std::string>(short_snapshot));
  EXPECT_NE(std::get<std::string>(short_snapshot).find("holds 2 spheres, the scene 3"), std::string::npos);
  b.scene.compare.packing.reset();
  const auto no_region = comparison::packing_series(b.scene, b.run);
  ASSERT_TRUE(std::holds_alternative<std::string>(no_region));
  EXPECT_NE(std::get<std::string>(no_region).find("[compare.packing]"), std::string::npos);
}

TEST(FirstTimeAtOrBelow, InterpolatesLinearlyBetweenTheSamplesAroundTheCrossing) {
  const std::vector<double> t{0.0, 1.0, 2.0, 3.0};
  // 0.9 → 0.3 between t = 1 and 2 crosses 0.5 at 1 + 0.4/0.6.
  EXPECT_NEAR(*comparison::first_time_at_or_below(t, std::vector<double>{1.0, 0.9, 0.3, 0.0}, 0.5), 1.0 + 0.4 / 0.6,
              1e-15);
  // A sample exactly at the level is the crossing; a later rise and fall does not count again.
  EXPECT_EQ(*comparison::first_time_at_or_below(t, std::vector<double>{1.0, 0.5, 0.8, 0.1}, 0.5), 1.0);
  // Starting at or below the level: the first time.
  EXPECT_EQ(*comparison::first_time_at_or_below(t, std::vector<double>{0.05, 0.9, 0.9, 0.9}, 0.1), 0.0);
  // Never that low.
  EXPECT_FALSE(comparison::first_time_at_or_below(t, std::vector<double>{1.0, 0.9, 0.8, 0.7}, 0.1));
  // A sample that is not a number neither crosses nor spoils the interpolation.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(*comparison::first_time_at_or_below(t, std::vector<double>{1.0, nan, 0.0, 0.0}, 0.5), 2.0);
  EXPECT_THROW((void)comparison::first_time_at_or_below(t, std::vector<double>{1.0}, 0.5), std::invalid_argument);
}

TEST(LargestDrop, IsTheLargestFallBetweenConsecutiveSamples) {
  EXPECT_DOUBLE_EQ(comparison::largest_drop(std::vector<double>{1.0, 0.8, 0.85, 0.3, 0.3}), 0.55);
  EXPECT_EQ(comparison::largest_drop(std::vector<double>{0.1, 0.2, 0.9}), 0.0);  // rises only
  EXPECT_EQ(comparison::largest_drop(std::vector<double>{0.7}), 0.0);
  EXPECT_EQ(comparison::largest_drop(std::vector<double>{}), 0.0);
}

TEST(FluidisationMetrics, ReadTheRunsOrfCurve) {
  // ORF 1, 1, 0 at t = 0, 0.5, 1: it falls to 0.1 at 0.5 + 0.9 × 0.5, all of it in one step.
  Bed b = bed({{true, true}, {true, false}, {false, false}}, 0.5);
  b.scene.compare.metrics = {"fluidisation_time", "orf_largest_drop"};
  const auto m = comparison::compute_metrics(b.scene, b.run, nullptr);
  ASSERT_TRUE(m.at("fluidisation_time").value) << m.at("fluidisation_time").problem;
  EXPECT_NEAR(*m.at("fluidisation_time").value, 0.95, 1e-15);
  EXPECT_EQ(*m.at("orf_largest_drop").value, 1.0);
  // The threshold is the case's.
  b.scene.compare.packing->orf_threshold = 0.5;
  EXPECT_NEAR(*comparison::compute_metrics(b.scene, b.run, nullptr).at("fluidisation_time").value, 0.75, 1e-15);
}

TEST(FluidisationMetrics, AreMissingWithTheReasonWhenTheBedStays) {
  Bed b = bed({{true, true}, {true, false}, {true, false}}, 0.5);
  b.scene.compare.metrics = {"fluidisation_time", "orf_largest_drop"};
  auto m = comparison::compute_metrics(b.scene, b.run, nullptr);
  EXPECT_FALSE(m.at("fluidisation_time").value);
  EXPECT_NE(m.at("fluidisation_time").problem.find("did not fluidise"), std::string::npos)
      << m.at("fluidisation_time").problem;
  EXPECT_EQ(*m.at("orf_largest_drop").value, 0.0);
  b.run.snapshots.resize(1);
  m = comparison::compute_metrics(b.scene, b.run, nullptr);
  EXPECT_FALSE(m.at("orf_largest_drop").value);
  EXPECT_NE(m.at("orf_largest_drop").problem.find("needs 2"), std::string::npos) << m.at("orf_largest_drop").problem;
}

/// Six mobile spheres in a unit-cube reservoir: radii 1, 1, 1, 2, 1 and 1 (volumes 1, 1, 1, 8, 1,
/// 1 units of 4/3 π; the dose is 13). Snapshot 0 holds them all inside. Snapshot 1: spheres 0 and 1
/// left touching each other (one fragment of 2) and sphere 2 alone; 3, 4 and 5 stay in. Snapshot
/// 2: sphere 3 (r 2) left with sphere 4 4 % of their radii sum apart (one fragment of 9) and
/// sphere 5 6 % apart from sphere 4 (alone); 0, 1 and 2 went far apart.
Bed departing() {
  Bed b;
  for (const double r : {1.0, 1.0, 1.0, 2.0, 1.0, 1.0}) {
    cases::ParticleSpec p;
    p.radius = r;
    b.scene.particles.push_back(p);
  }
  b.scene.compare.packing = cases::PackingSpec{{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, std::nullopt, 1, 1};
  b.run.status = cases::RunStatus::ok;
  const cases::Vector3 in{0.5, 0.5, 0.5};
  const auto snap = [&](double t, std::vector<cases::Vector3> at) {
    cases::Snapshot s;
    s.time = t;
    s.position = std::move(at);
    b.run.snapshots.push_back(s);
  };
  snap(0.0, {in, in, in, in, in, in});
  snap(1.0, {{10.0, 0.0, 0.0}, {11.99, 0.0, 0.0}, {20.0, 0.0, 0.0}, in, in, in});
  snap(2.0, {{100.0, 0.0, 0.0}, {200.0, 0.0, 0.0}, {300.0, 0.0, 0.0},
             {10.0, 10.0, 0.0}, {10.0, 10.0 + 3.0 * 1.04, 0.0}, {10.0, 10.0 + 3.0 * 1.04 + 2.0 * 1.06, 0.0}});
  return b;
}

TEST(PackingSeries, TheLargestDepartedFragmentIsAShareOfTheDosesVolume) {
  const Bed b = departing();
  const auto series = comparison::packing_series(b.scene, b.run);
  const auto& s = std::get<std::vector<comparison::PackingSample>>(series);
  ASSERT_EQ(s.size(), 3U);
  EXPECT_EQ(s[0].largest_departed_fragment, 0.0);                  // nothing has left
  EXPECT_NEAR(s[1].largest_departed_fragment, 2.0 / 13.0, 1e-14);  // 0 and 1, touching
  EXPECT_NEAR(s[2].largest_departed_fragment, 9.0 / 13.0, 1e-14);  // 3 and 4, 4 % apart; 5 is 6 % off
  Bed later = b;
  later.scene.compare.metrics = {"largest_departed_fragment"};
  const auto m = comparison::compute_metrics(later.scene, later.run, nullptr);
  ASSERT_TRUE(m.at("largest_departed_fragment").value) << m.at("largest_departed_fragment").problem;
  EXPECT_NEAR(*m.at("largest_departed_fragment").value, 9.0 / 13.0, 1e-14);  // the largest over the run
  // A stream: the same spheres leaving one by one, far apart, never make more than the largest one.
  later.run.snapshots[2].position[4] = {50.0, 50.0, 0.0};
  EXPECT_NEAR(*comparison::compute_metrics(later.scene, later.run, nullptr).at("largest_departed_fragment").value,
              8.0 / 13.0, 1e-14);
  // A fixed sphere is not the dose: fixing sphere 3 leaves 4 and 5 as lone spheres.
  later.scene.particles[3].fixed = true;
  EXPECT_NEAR(*comparison::compute_metrics(later.scene, later.run, nullptr).at("largest_departed_fragment").value,
              2.0 / 5.0, 1e-14);
}

}  // namespace packing_series_test
