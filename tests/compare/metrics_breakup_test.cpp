// SPDX-License-Identifier: MIT
// Agglomerate breakup metrics (thesis §5.2.4) against hand-built configurations and an all-pairs
// oracle on random scenes.
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "compare/metrics_breakup.hpp"

namespace metrics_breakup_test {

using comparison::breakup::BondRule;
using comparison::breakup::SnapshotSphere;
using dem::Vec3;

/// A 2 × 2 × 2 cube of spheres of radius r whose neighbours along an edge overlap slightly.
std::vector<SnapshotSphere> cube(double r) {
  std::vector<SnapshotSphere> out;
  const double spacing = 1.98 * r;
  for (int k = 0; k < 8; ++k) out.push_back({Vec3(k % 2, k / 2 % 2, k / 4) * spacing, r});
  return out;
}

TEST(BreakupMetrics, AnUntouchedAgglomerateIsWholeAndUndamaged) {
  const auto before = cube(0.005);
  const auto m = comparison::breakup::breakup_metrics(before, before, comparison::breakup::body_contact(before));
  EXPECT_EQ(m.kappa_vol, 1.0);
  EXPECT_EQ(m.kappa_damage, 0.0);
  EXPECT_EQ(m.fragments, 1U);
  EXPECT_EQ(m.coordination_before, 3.0);  // 12 edges, 8 spheres
  EXPECT_EQ(m.coordination_after, 3.0);
}

TEST(BreakupMetrics, OneLostSphereBreaksItsThreeContacts) {
  const auto before = cube(0.005);
  auto after = before;
  after[7].position += Vec3(0.1, 0.0, 0.0);
  const auto m = comparison::breakup::breakup_metrics(before, after, comparison::breakup::body_contact(after));
  EXPECT_DOUBLE_EQ(m.kappa_vol, 7.0 / 8.0);
  EXPECT_DOUBLE_EQ(m.kappa_damage, 3.0 / 12.0);
  EXPECT_EQ(m.fragments, 2U);
  ASSERT_EQ(m.fragment_volume.size(), 2U);
  EXPECT_DOUBLE_EQ(m.fragment_volume[0], 7.0 * m.fragment_volume[1]);
  EXPECT_DOUBLE_EQ(m.coordination_after, 2.0 * 9.0 / 8.0);
}

TEST(BreakupMetrics, ARowSplitInTwoHalves) {
  std::vector<SnapshotSphere> before;
  for (int k = 0; k < 4; ++k) before.push_back({Vec3(1.9 * k, 0, 0), 1.0});
  auto after = before;
  after[2].position.x() += 1.0;
  after[3].position.x() += 1.0;
  const auto m = comparison::breakup::breakup_metrics(before, after, comparison::breakup::body_contact(after));
  EXPECT_DOUBLE_EQ(m.kappa_vol, 0.5);
  EXPECT_DOUBLE_EQ(m.kappa_damage, 1.0 / 3.0);
  EXPECT_EQ(m.fragments, 2U);
  const auto f = comparison::breakup::fragments(after, comparison::breakup::body_contact(after));
  // Equal volumes: the fragment holding the smaller index comes first.
  EXPECT_EQ(f.of, (std::vector<std::uint32_t>{0, 0, 1, 1}));
  EXPECT_EQ(f.size, (std::vector<std::uint32_t>{2, 2}));
}

TEST(BreakupMetrics, VolumeRatioWeighsSpheresByTheirVolume) {
  const std::vector<SnapshotSphere> before{{Vec3(0, 0, 0), 1.0}, {Vec3(2.9, 0, 0), 2.0}};
  auto after = before;
  after[0].position.x() -= 1.0;
  const auto m = comparison::breakup::breakup_metrics(before, after, comparison::breakup::body_contact(after));
  EXPECT_DOUBLE_EQ(m.kappa_vol, 8.0 / 9.0);
  EXPECT_EQ(m.kappa_damage, 1.0);
  EXPECT_EQ(m.fragments, 2U);
}

TEST(BreakupMetrics, CohesionReachingPastContactKeepsAFragmentWhole) {
  // Apart by 0.2 r after the impact: no body contact, but within effect radii of 1.5 r.
  const std::vector<SnapshotSphere> before{{Vec3(0, 0, 0), 1.0}, {Vec3(1.9, 0, 0), 1.0}};
  auto after = before;
  after[1].position.x() = 2.2;
  BondRule linear;
  linear.half_reach = {1.5, 1.5};
  const auto m = comparison::breakup::breakup_metrics(before, after, linear);
  EXPECT_EQ(m.fragments, 1U);
  EXPECT_EQ(m.kappa_vol, 1.0);
  EXPECT_EQ(m.kappa_damage, 1.0);  // the body contact broke all the same
  EXPECT_EQ(comparison::breakup::breakup_metrics(before, after, comparison::breakup::body_contact(after)).fragments, 2U);
  // A pair rule (a neck that holds down to a rupture overlap of −0.1 r) decides within the reach.
  BondRule neck;
  neck.half_reach = {1.1, 1.1};
  neck.bonded = [](std::uint32_t, std::uint32_t, double distance) { return distance < 2.1; };
  EXPECT_EQ(comparison::breakup::breakup_metrics(before, after, neck).fragments, 2U);
  after[1].position.x() = 2.05;
  EXPECT_EQ(comparison::breakup::breakup_metrics(before, after, neck).fragments, 1U);
}

/// Fragment of each sphere by joining every pair closer than h_i + h_j, scanning all pairs.
std::vector<std::uint32_t> oracle_fragments(const std::vector<SnapshotSphere>& s, const std::vector<double>& h) {
  std::vector<std::uint32_t> label(s.size());
  for (std::uint32_t i = 0; i < s.size(); ++i) label[i] = i;
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::uint32_t i = 0; i < s.size(); ++i) {
      for (std::uint32_t j = i + 1; j < s.size(); ++j) {
        if ((s[i].position - s[j].position).norm() >= h[i] + h[j]) continue;
        const std::uint32_t low = std::min(label[i], label[j]);
        if (label[i] != low || label[j] != low) {
          label[i] = label[j] = low;
          changed = true;
        }
      }
    }
  }
  return label;
}

TEST(BreakupMetrics, RandomPolydisperseScenesMatchAnAllPairsOracle) {
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<SnapshotSphere> s;
    std::vector<double> h;
    const double ratio = seed % 2 == 0 ? 10.0 : 2.0;
    for (int k = 0; k < 300; ++k) {
      const double r = 0.01 * std::pow(ratio, unit(rng));
      s.push_back({Vec3(unit(rng), unit(rng), unit(rng)) * (0.3 + 0.05 * seed), r});
      h.push_back(r * (1.0 + 0.5 * unit(rng)));
    }
    BondRule rule;
    rule.half_reach = h;
    const auto f = comparison::breakup::fragments(s, rule);
    const auto label = oracle_fragments(s, h);
    // Same partition: spheres share a fragment exactly when they share an oracle label.
    std::map<std::uint32_t, std::uint32_t> fragment_of_label;
    std::size_t distinct = 0;
    for (std::uint32_t i = 0; i < s.size(); ++i) {
      const auto [it, inserted] = fragment_of_label.emplace(label[i], f.of[i]);
      if (inserted) ++distinct;
      EXPECT_EQ(it->second, f.of[i]) << "seed " << seed << " sphere " << i;
    }
    EXPECT_EQ(distinct, f.volume.size()) << "seed " << seed;
    // The scenes are neither one cluster nor all loose spheres.
    EXPECT_GT(f.volume.size(), 1U) << "seed " << seed;
    EXPECT_GE(f.size.front(), 2U) << "seed " << seed;
    EXPECT_LT(f.volume.size(), s.size()) << "seed " << seed;
    for (std::size_t k = 1; k < f.volume.size(); ++k) EXPECT_GE(f.volume[k - 1], f.volume[k]);
  }
}

TEST(BreakupMetrics, BadSnapshotsAreClearErrors) {
  const auto before = cube(0.005);
  auto fewer = before;
  fewer.pop_back();
  const BondRule rule = comparison::breakup::body_contact(before);
  EXPECT_THROW((void)comparison::breakup::breakup_metrics(before, fewer, rule), std::invalid_argument);
  EXPECT_THROW((void)comparison::breakup::breakup_metrics({}, {}, BondRule{}), std::invalid_argument);
  auto bad = before;
  bad[3].radius = 0.0;
  EXPECT_THROW((void)comparison::breakup::breakup_metrics(before, bad, rule), std::invalid_argument);
  bad = before;
  bad[2].position.y() = std::nan("");
  EXPECT_THROW((void)comparison::breakup::breakup_metrics(before, bad, rule), std::invalid_argument);
  std::vector<SnapshotSphere> apart{{Vec3(0, 0, 0), 1.0}, {Vec3(3, 0, 0), 1.0}};
  EXPECT_THROW((void)comparison::breakup::breakup_metrics(apart, apart, comparison::breakup::body_contact(apart)),
               std::invalid_argument);
  BondRule short_rule;
  short_rule.half_reach = {1.0};
  EXPECT_THROW((void)comparison::breakup::fragments(apart, short_rule), std::invalid_argument);
  try {
    (void)comparison::breakup::breakup_metrics(before, bad, rule);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sphere 2"), std::string::npos) << e.what();
  }
}

}  // namespace
