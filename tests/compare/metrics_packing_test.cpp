// SPDX-License-Identifier: MIT
// The packing metrics of a run, from its last snapshot in the case's compare.packing region.
#include "compare/metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

/// A 6 × 6 × 6 simple cubic lattice of touching mobile spheres (r = 0.5, centres on the
/// integers 0…5) plus one fixed sphere inside the region, and a run whose last snapshot holds
/// them (the first is somewhere else).
struct Lattice {
  cases::Scene scene;
  cases::RunResult run;
};

Lattice lattice() {
  Lattice l;
  cases::Snapshot first;
  cases::Snapshot last;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      for (int k = 0; k < 6; ++k) {
        cases::ParticleSpec p;
        p.radius = 0.5;
        p.position = {static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)};
        l.scene.particles.push_back(p);
        last.position.push_back(p.position);
        first.position.push_back({100.0, 100.0, 100.0});
      }
    }
  }
  cases::ParticleSpec base;
  base.radius = 2.0;
  base.fixed = true;
  base.position = {2.5, 2.5, 2.5};
  l.scene.particles.push_back(base);
  last.position.push_back(base.position);
  first.position.push_back(base.position);
  l.scene.compare.packing = cases::PackingSpec{{0.5, 0.5, 0.5}, {4.5, 4.5, 4.5}, std::nullopt, 45, 15};
  l.scene.compare.metrics = {"packing_fraction", "packing_fraction_interior", "orf", "dose_remaining"};
  l.run.status = cases::RunStatus::ok;
  l.run.snapshots = {first, last};
  return l;
}

TEST(PackingMetrics, AreMeasuredOnTheLastSnapshotCountingMobileSpheresOnly) {
  const Lattice l = lattice();
  const comparison::MetricSet m = comparison::compute_metrics(l.scene, l.run, nullptr);
  // The fixed sphere (radius 2 inside the region) would add 33.5 of the region's 64 if counted.
  EXPECT_NEAR(*m.at("packing_fraction").value, std::numbers::pi / 6, 1e-13);
  // Default margin: two mean mobile diameters = 2, leaving [2.5, 2.5]: no interior; with 1 it is
  // [1.5, 3.5]³, cut through the lattice's cell boundaries.
  EXPECT_FALSE(m.at("packing_fraction_interior").value.has_value());
  EXPECT_NE(m.at("packing_fraction_interior").problem.find("no interior"), std::string::npos)
      << m.at("packing_fraction_interior").problem;
  // Seen along x, the spheres with centres in [0.5, 4.5]² (y, z = 1…4) cover the region's face
  // but for the gaps between touching circles: counted on the 45 × 15 grid below.
  int covered = 0;
  for (int a = 0; a < 45; ++a) {
    for (int b = 0; b < 15; ++b) {
      const double y = 0.5 + (a + 0.5) * 4.0 / 45.0;
      const double z = 0.5 + (b + 0.5) * 4.0 / 15.0;
      bool hit = false;
      for (int cy = 1; cy <= 4 && !hit; ++cy) {
        for (int cz = 1; cz <= 4 && !hit; ++cz) hit = (y - cy) * (y - cy) + (z - cz) * (z - cz) < 0.25;
      }
      covered += hit ? 1 : 0;
    }
  }
  EXPECT_DOUBLE_EQ(*m.at("orf").value, covered / 675.0);
  EXPECT_DOUBLE_EQ(*m.at("dose_remaining").value, 64.0 / 216.0);  // centres 1…4 on each axis

  cases::Scene with_margin = l.scene;
  with_margin.compare.packing->interior_margin = 1.0;
  EXPECT_NEAR(*comparison::compute_metrics(with_margin, l.run, nullptr).at("packing_fraction_interior").value,
              std::numbers::pi / 6, 1e-13);
}

TEST(PackingMetrics, AreMissingWithTheReasonWhenTheRunHasNoSnapshotOrTheCaseNoRegion) {
  Lattice l = lattice();
  l.run.snapshots.clear();
  EXPECT_NE(comparison::compute_metrics(l.scene, l.run, nullptr).at("orf").problem.find("no snapshot"),
            std::string::npos);
  l = lattice();
  l.run.snapshots.back().position.pop_back();
  EXPECT_NE(comparison::compute_metrics(l.scene, l.run, nullptr).at("packing_fraction").problem.find("216 spheres"),
            std::string::npos);
  l = lattice();
  l.scene.compare.packing.reset();
  EXPECT_NE(comparison::compute_metrics(l.scene, l.run, nullptr).at("dose_remaining").problem.find("[compare.packing]"),
            std::string::npos);
}

TEST(PackingMetrics, AtStartReadTheFirstSnapshot) {
  Lattice l = lattice();
  l.scene.compare.packing->at_start = true;
  // The first snapshot holds every mobile sphere far outside the region.
  const comparison::MetricSet m = comparison::compute_metrics(l.scene, l.run, nullptr);
  EXPECT_DOUBLE_EQ(*m.at("packing_fraction").value, 0.0);
  EXPECT_DOUBLE_EQ(*m.at("dose_remaining").value, 0.0);
  std::swap(l.run.snapshots.front(), l.run.snapshots.back());
  EXPECT_NEAR(*comparison::compute_metrics(l.scene, l.run, nullptr).at("packing_fraction").value, std::numbers::pi / 6,
              1e-13);
}

}  // namespace

namespace coordination_test {

/// An n³ simple cubic lattice of unit pitch whose spheres overlap their six neighbours slightly
/// (r = 0.5001), as the last snapshot of a run, with a fixed sphere overlapping the corner one.
struct Bed {
  cases::Scene scene;
  cases::RunResult run;
};

Bed bed(int n) {
  Bed b;
  cases::Snapshot last;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        cases::ParticleSpec p;
        p.radius = 0.5001;
        p.position = {static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)};
        b.scene.particles.push_back(p);
        last.position.push_back(p.position);
      }
    }
  }
  cases::ParticleSpec base;  // fixed: its contacts are not counted
  base.radius = 0.6;
  base.fixed = true;
  base.position = {-1.0, 0.0, 0.0};
  b.scene.particles.push_back(base);
  last.position.push_back(base.position);
  b.scene.compare.metrics = {"coordination_number"};
  b.run.status = cases::RunStatus::ok;
  b.run.snapshots = {last};
  return b;
}

TEST(PackingMetrics, CoordinationCountsBodyContactsOfTheSpheresInTheRegion) {
  Bed b = bed(6);
  // Spheres 1…4 on every axis have all six neighbours.
  b.scene.compare.packing = cases::PackingSpec{{0.5, 0.5, 0.5}, {4.5, 4.5, 4.5}, std::nullopt, 45, 15};
  EXPECT_DOUBLE_EQ(*comparison::compute_metrics(b.scene, b.run, nullptr).at("coordination_number").value, 6.0);
  // The whole lattice: 3·6·6·5 contacts over 216 spheres, 2·540/216 = 5.
  b.scene.compare.packing = cases::PackingSpec{{-0.5, -0.5, -0.5}, {5.5, 5.5, 5.5}, std::nullopt, 45, 15};
  EXPECT_DOUBLE_EQ(*comparison::compute_metrics(b.scene, b.run, nullptr).at("coordination_number").value, 5.0);
  // Spheres exactly touching (δ = 0) are not in contact.
  for (auto& p : b.scene.particles) p.radius = p.fixed ? p.radius : 0.5;
  EXPECT_DOUBLE_EQ(*comparison::compute_metrics(b.scene, b.run, nullptr).at("coordination_number").value, 0.0);
  // A region holding no centre has no coordination number.
  b.scene.compare.packing = cases::PackingSpec{{10, 10, 10}, {11, 11, 11}, std::nullopt, 45, 15};
  EXPECT_NE(comparison::compute_metrics(b.scene, b.run, nullptr).at("coordination_number").problem.find("no mobile"),
            std::string::npos);
}

}  // namespace coordination_test
