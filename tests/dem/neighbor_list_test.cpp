// SPDX-License-Identifier: MIT
// The Verlet list against the brute-force oracle (thesis appendix B): random polydisperse
// scenes, periodic images, moving spheres, history across rebuilds and reorders.
#include <algorithm>
#include <cstdio>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "dem/neighbors/brute_force.hpp"
#include "dem/neighbors/neighbor_list.hpp"
#include "dem/particles/spatial_order.hpp"
#include "many_body_fixture.hpp"

namespace neighbor_list_test {

using dem::Vec3;
using dem::Vec3Array;
using Pair = std::pair<std::uint32_t, std::uint32_t>;

/// Builds the list of `s` with skin `skin` in `box`.
dem::NeighborList build_list(const test_support::RandomSpheres& s, const dem::PeriodicBox& box,
                             double skin, int threads = 1,
                             std::span<const std::uint32_t> new_of_old = {},
                             dem::NeighborList list = {}) {
  std::vector<double> h;
  for (const auto& p : s.spheres) h.push_back(p.half_reach);
  const dem::SizeClasses classes = dem::size_classes(h);
  list.build({s.spheres, s.still, classes.of, classes.max_half_reach, &box, skin, threads, true}, new_of_old);
  return list;
}

/// Every listed pair as (min, max), checking on the way that no pair is listed twice and that
/// each lies within its cut-off at its stored image.
std::set<Pair> listed_pairs(const dem::NeighborList& list, const test_support::RandomSpheres& s,
                            double skin) {
  std::set<Pair> out;
  for (std::uint32_t i = 0; i < list.sphere_count(); ++i) {
    for (std::uint32_t k = list.begin(i); k < list.begin(i + 1); ++k) {
      const dem::PartnerCode partner = list.partners()[k];
      const std::uint32_t j = partner & dem::kPartnerMask;
      const Vec3 shift = list.shift(partner >> dem::kPartnerBits);
      const Vec3 d = Vec3(s.spheres[i].x, s.spheres[i].y, s.spheres[i].z) -
                     (Vec3(s.spheres[j].x, s.spheres[j].y, s.spheres[j].z) - shift);
      const double cut = s.spheres[i].half_reach + s.spheres[j].half_reach + skin;
      EXPECT_LT(d.norm(), cut) << i << "–" << j;
      EXPECT_TRUE(list.slabs().owns(i, j)) << i << "–" << j;
      EXPECT_TRUE(out.insert({std::min(i, j), std::max(i, j)}).second) << "listed twice: " << i << "–" << j;
    }
  }
  return out;
}

std::set<Pair> oracle(const test_support::RandomSpheres& s, const dem::PeriodicBox& box, double skin) {
  const auto pairs = dem::brute_force_pairs(s.spheres, s.still, box, skin);
  return {pairs.begin(), pairs.end()};
}

/// The pair loop walks each slab's entries as runs: every run must hold consecutive entries of
/// that slab's owners (alike in `shifted`), and the runs of a slab, end to end, exactly the
/// entries of its owners in owner order — never an entry of another slab's owner, whose forces
/// would then be summed twice.
void expect_runs_cover_the_slabs(const dem::NeighborList& list, const char* what) {
  std::vector<std::uint32_t> owner_of(list.size());
  for (std::uint32_t i = 0; i < list.sphere_count(); ++i) {
    for (std::uint32_t k = list.begin(i); k < list.begin(i + 1); ++k) owner_of[k] = i;
  }
  for (std::uint32_t sl = 0; sl < list.slabs().count(); ++sl) {
    std::vector<std::uint32_t> owned;
    for (const std::uint32_t i : list.slabs().members(sl)) {
      for (std::uint32_t k = list.begin(i); k < list.begin(i + 1); ++k) owned.push_back(k);
    }
    std::vector<std::uint32_t> walked;
    for (const dem::NeighborList::EntryRun& r : list.runs(sl)) {
      EXPECT_LT(r.begin, r.end) << what << ": an empty run in slab " << sl;
      for (std::uint32_t k = r.begin; k < r.end; ++k) {
        walked.push_back(k);
        EXPECT_EQ(r.first_owner + list.owner_steps()[k], owner_of[k]) << what << ": owner of entry " << k;
        EXPECT_EQ(r.shifted, list.shifted(owner_of[k])) << what << ": entry " << k;
      }
    }
    EXPECT_EQ(walked, owned) << what << ": slab " << sl;
  }
}

dem::PeriodicBox box_of(const Vec3& lo, const Vec3& hi, bool px, bool py, bool pz) {
  dem::PeriodicBox b;
  b.lo = lo;
  b.hi = hi;
  b.periodic = {px, py, pz};
  return b;
}

TEST(NeighborList, RandomPolydisperseScenesMatchTheBruteForceOracle) {
  // Size ratio up to 10, open and periodic boxes, 1 to 3 threads: never a missed or extra pair.
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    const double ratio = seed % 3 == 0 ? 10.0 : (seed % 3 == 1 ? 1.0 : 3.0);
    const Vec3 lo(-0.3, 0.1, 0.0);
    const Vec3 hi(1.7, 1.3, 0.9 + 0.1 * seed);
    const auto s = test_support::random_spheres(seed, 600, lo, hi, 0.01, 0.01 * ratio);
    const dem::PeriodicBox box = box_of(lo, hi, seed % 2 == 0, seed % 4 == 1, seed % 5 == 0);
    const double skin = 0.002 * seed;
    const dem::NeighborList list = build_list(s, box, skin, 1 + static_cast<int>(seed % 3));
    EXPECT_EQ(listed_pairs(list, s, skin), oracle(s, box, skin)) << "seed " << seed;
    expect_runs_cover_the_slabs(list, "random scene");
  }
}

TEST(NeighborList, RunsOfMoreOwnersThanAStepCountsAreSplit) {
  // An entry's owner is its run's first plus a one-byte step: four slabs along x of ~500 spheres
  // each, numbered along x (so that each slab's owners follow each other), need runs cut every
  // 256 owners.
  auto s = test_support::random_spheres(21, 2000, Vec3(0, 0, 0), Vec3(0.5, 0.45, 0.45), 0.03, 0.05);
  std::vector<std::size_t> order(s.spheres.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return s.spheres[a].x < s.spheres[b].x; });
  test_support::RandomSpheres sorted;
  for (const std::size_t k : order) {
    sorted.spheres.push_back(s.spheres[k]);
    sorted.still.push_back(s.still[k]);
  }
  s = sorted;
  const dem::NeighborList list = build_list(s, dem::PeriodicBox{}, 0.01);
  EXPECT_LE(list.slabs().count(), 4U);
  std::uint32_t longest = 0;
  for (std::uint32_t sl = 0; sl < list.slabs().count(); ++sl) {
    for (const dem::NeighborList::EntryRun& r : list.runs(sl)) {
      for (std::uint32_t k = r.begin; k < r.end; ++k) longest = std::max<std::uint32_t>(longest, list.owner_steps()[k]);
    }
  }
  EXPECT_GT(longest, 200U) << "runs long enough to need the cut";
  expect_runs_cover_the_slabs(list, "2,000 spheres in few slabs");
  EXPECT_EQ(listed_pairs(list, s, 0.01), oracle(s, dem::PeriodicBox{}, 0.01));
}

TEST(NeighborList, FewSlabsAlongAnOpenAxisListEveryPairOnce) {
  // A row of spheres two or three slabs long (a non-periodic axis): the first and last slabs
  // are not neighbours, so no pair may be owned from both ends.
  for (const int spheres : {4, 5, 6, 8, 9, 12}) {
    test_support::RandomSpheres s;
    for (int k = 0; k < spheres; ++k) {
      s.spheres.push_back({k * 0.0115, 0.0, 0.0, 0.0075});
      s.still.push_back(0);
    }
    const dem::PeriodicBox open;
    const dem::NeighborList list = build_list(s, open, 0.001);
    EXPECT_EQ(listed_pairs(list, s, 0.001), oracle(s, open, 0.001)) << spheres << " spheres, " << list.slabs().count() << " slabs";
  }
}

TEST(NeighborList, PeriodicImagesAcrossEveryFaceAreFound) {
  // Spheres hugging the faces and corners of a small periodic box: pairs only meet through images.
  dem::PeriodicBox box = box_of(Vec3(0, 0, 0), Vec3(1, 1, 1), true, true, true);
  test_support::RandomSpheres s;
  for (const double x : {0.01, 0.99}) {
    for (const double y : {0.02, 0.98}) {
      for (const double z : {0.015, 0.985}) {
        s.spheres.push_back({x, y, z, 0.03});
        s.still.push_back(0);
      }
    }
  }
  const dem::NeighborList list = build_list(s, box, 0.01);
  const auto found = listed_pairs(list, s, 0.01);
  EXPECT_EQ(found, oracle(s, box, 0.01));
  EXPECT_EQ(found.size(), 28U);  // all eight corners meet through the images
  EXPECT_TRUE(list.periodic());
}

TEST(NeighborList, BoxesShorterThanTwoReachesFindTheNearestImageOfEachSphere) {
  // A periodic axis only a few reaches long makes the search stencil wrap onto itself there: the
  // cells along it cannot name one image for all their spheres, so each pair's nearest image is
  // found sphere by sphere — on every axis, the well-sized ones included.
  for (std::uint32_t seed = 1; seed <= 8; ++seed) {
    const Vec3 lo(0.0, 0.0, 0.0);
    const double thin = 0.05 + 0.01 * seed;  // about 2 to 3 of the largest reaches
    const Vec3 hi(seed % 2 == 0 ? thin : 0.6, 0.5, seed % 2 == 0 ? 0.4 : thin);
    const auto s = test_support::random_spheres(seed, 300, lo, hi, 0.005, 0.01 + 0.001 * seed);
    const dem::PeriodicBox box = box_of(lo, hi, true, seed % 3 != 0, true);
    const double skin = 0.002;
    const dem::NeighborList list = build_list(s, box, skin, 1 + static_cast<int>(seed % 2));
    EXPECT_EQ(listed_pairs(list, s, skin), oracle(s, box, skin)) << "seed " << seed;
  }
}

/// Distance tests per listed pair and cells visited per sphere in one build of a bidisperse
/// random scene: 20,000 small spheres and as many `ratio` times larger ones as fill the same
/// volume, each size filling 20 % of the box.
std::pair<double, double> search_cost(double ratio) {
  constexpr double kSmall = 0.005;
  const double small_volume = 20000.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(kSmall, 3);
  const double side = std::cbrt(small_volume / 0.2);
  const auto large = static_cast<int>(std::lround(20000.0 / std::pow(ratio, 3)));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, side);
  test_support::RandomSpheres s;
  for (int i = 0; i < 20000 + large; ++i) {
    s.spheres.push_back({unit(rng), unit(rng), unit(rng), i < large ? kSmall * ratio : kSmall});
    s.still.push_back(0);
  }
  const dem::NeighborList list = build_list(s, dem::PeriodicBox{}, 0.001);
  // Correctness at these ratios is the oracle test's job (600 spheres); a brute-force check of
  // 40,000 spheres costs minutes under the sanitizers.
  EXPECT_GT(list.size(), s.spheres.size()) << "ratio " << ratio;
  return {static_cast<double>(list.last_build_candidates()) / static_cast<double>(list.size()),
          static_cast<double>(list.last_build_cells()) / static_cast<double>(s.spheres.size())};
}

TEST(NeighborList, PolydispersityDoesNotBlowUpTheSearch) {
  // Per-class grids keep the distance tests per listed pair and the cells visited per sphere
  // near their monodisperse values (at most 3³ cells of each class's grid searched, fewer where
  // a cell holds no sphere of the owner's slab or the next); one grid sized for the largest
  // spheres would test each small sphere against ~ratio³ times more candidates.
  const auto [mono_tests, mono_cells] = search_cost(1.0);
  for (const double ratio : {3.0, 10.0}) {
    const auto [tests, cells] = search_cost(ratio);
    std::printf("size ratio %4.1f: %.1f distance tests per listed pair (monodisperse %.1f), %.0f cells "
                "per sphere (monodisperse %.0f)\n", ratio, tests, mono_tests, cells, mono_cells);
    EXPECT_LT(tests, 2.0 * mono_tests) << "ratio " << ratio;
    EXPECT_LT(cells, 3.0 * mono_cells) << "ratio " << ratio;
  }
}

TEST(NeighborList, AReachOfMillionsOfCellsVisitsEveryCellOnce) {
  // A 1e8 m sphere beside 1 cm ones (a fuzzed case file): reach / edge = 1e10 does not fit an
  // int; the stencil is clamped to the row before the conversion.
  dem::AxisCells open;
  open.fill(1, 4, 0.01, 1.0e8, false);
  EXPECT_EQ(open.cell, (std::vector<int>{0, 1, 2, 3}));
  dem::AxisCells ring;
  ring.fill(1, 4, 0.01, 1.0e8, true);
  EXPECT_FALSE(ring.imaged);
  EXPECT_EQ(ring.cell, (std::vector<int>{0, 1, 2, 3}));
}

TEST(NeighborList, MovingSpheresAreNeverMissedBetweenRebuilds) {
  // Random walks with the half-skin rule: at every step, every pair within reach (h_i + h_j) is
  // in the list, although the list was built up to many steps before.
  const dem::PeriodicBox box = box_of(Vec3(0, 0, 0), Vec3(1, 1, 1), true, false, true);
  auto s = test_support::random_spheres(3, 500, Vec3(0, 0, 0), Vec3(1, 1, 1), 0.01, 0.04);
  const double skin = 0.01;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> step(0.0, 0.0015);
  dem::NeighborList list = build_list(s, box, skin);
  auto built = s;
  int rebuilds = 0;
  for (int n = 0; n < 150; ++n) {
    double worst = 0.0;
    for (std::size_t i = 0; i < s.spheres.size(); ++i) {
      if (s.still[i] != 0) continue;
      s.spheres[i].x += step(rng);
      s.spheres[i].y += step(rng);
      s.spheres[i].z += step(rng);
      const Vec3 d(s.spheres[i].x - built.spheres[i].x, s.spheres[i].y - built.spheres[i].y,
                   s.spheres[i].z - built.spheres[i].z);
      worst = std::max(worst, d.norm());
    }
    if (worst > 0.5 * skin) {
      // Positions drift out of the box between builds; the list wraps them at the next build.
      for (auto& p : s.spheres) {
        const auto image = box.image_of(Vec3(p.x, p.y, p.z));
        p.x -= image[0];
        p.z -= image[2];
      }
      list = build_list(s, box, skin, 2, {}, std::move(list));
      built = s;
      ++rebuilds;
    }
    const std::set<Pair> listed = [&] {
      std::set<Pair> out;
      for (std::uint32_t i = 0; i < list.sphere_count(); ++i) {
        for (std::uint32_t k = list.begin(i); k < list.begin(i + 1); ++k) {
          const std::uint32_t j = list.partners()[k] & dem::kPartnerMask;
          out.insert({std::min(i, j), std::max(i, j)});
        }
      }
      return out;
    }();
    for (const auto& [i, j] : dem::brute_force_pairs(s.spheres, s.still, box, 0.0)) {
      ASSERT_TRUE(listed.count({i, j})) << "step " << n << ": missed " << i << "–" << j;
    }
  }
  EXPECT_GT(rebuilds, 3);
}

TEST(NeighborList, HistorySurvivesRebuildsAndReorders) {
  auto s = test_support::random_spheres(5, 500, Vec3(0, 0, 0), Vec3(1, 1, 1), 0.02, 0.05);
  const dem::PeriodicBox box = box_of(Vec3(0, 0, 0), Vec3(1, 1, 1), true, true, false);
  dem::NeighborList list = build_list(s, box, 0.01);
  // Mark every third pair as interacting, its slip tagged with the pair's identity.
  std::map<Pair, Vec3> tagged;
  for (std::uint32_t i = 0; i < list.sphere_count(); ++i) {
    for (std::uint32_t k = list.begin(i); k < list.begin(i + 1); ++k) {
      if (k % 3 != 0) continue;
      const std::uint32_t j = list.partners()[k] & dem::kPartnerMask;
      dem::ContactHistory h;
      h.tangential_slip = Vec3(i, j, 0.5);
      h.max_overlap = i + 1000.0 * j;
      list.set_history(k, h);
      tagged[{i, j}] = h.tangential_slip;
    }
  }
  ASSERT_GT(tagged.size(), 50U);
  // Reorder the spheres along a Morton curve and rebuild with the permutation.
  Vec3Array positions(3, static_cast<Eigen::Index>(s.spheres.size()));
  for (std::size_t i = 0; i < s.spheres.size(); ++i) {
    positions.col(static_cast<Eigen::Index>(i)) = Vec3(s.spheres[i].x, s.spheres[i].y, s.spheres[i].z);
  }
  const auto order = dem::morton_order(positions, box, 0.1);
  const auto new_of_old = dem::inverse_permutation(order);
  ASSERT_NE(order, new_of_old);  // a real shuffle
  test_support::RandomSpheres moved;
  for (const std::uint32_t k : order) {
    moved.spheres.push_back(s.spheres[k]);
    moved.still.push_back(s.still[k]);
  }
  list = build_list(moved, box, 0.01, 2, new_of_old, std::move(list));
  std::size_t active = 0;
  for (std::size_t k = 0; k < list.size(); ++k) active += list.active(k) ? 1 : 0;
  EXPECT_EQ(active, tagged.size());
  for (const auto& [pair, slip] : tagged) {
    const std::uint32_t i = new_of_old[pair.first];
    const std::uint32_t j = new_of_old[pair.second];
    bool i_owns = true;
    const std::int64_t k = list.find(i, j, i_owns);
    ASSERT_GE(k, 0);
    const dem::ContactHistory h = list.history(static_cast<std::size_t>(k));
    // The slip is oriented owner → partner: it flips when the owner changed.
    EXPECT_EQ(i_owns ? h.tangential_slip : Vec3(-h.tangential_slip), slip);
    EXPECT_EQ(h.max_overlap, pair.first + 1000.0 * pair.second);
  }
}

TEST(NeighborList, RenumberingAListEqualsSearchingItAgain) {
  // A reorder right after a build renumbers the list instead of searching again: on random
  // polydisperse scenes (open and periodic, random shuffles and Morton orders, with history on
  // some pairs) it must give exactly what a new search of the reordered spheres gives.
  for (std::uint32_t seed = 1; seed <= 8; ++seed) {
    const Vec3 lo(0.0, -0.2, 0.1);
    const Vec3 hi(1.0, 0.7, 0.8);
    const auto s = test_support::random_spheres(seed, 500, lo, hi, 0.01, 0.01 * (seed % 2 == 0 ? 8.0 : 2.0));
    const dem::PeriodicBox box = box_of(lo, hi, seed % 2 == 1, seed % 3 != 0, seed % 4 == 0);
    const double skin = 0.004;
    dem::NeighborList searched = build_list(s, box, skin);
    for (std::uint32_t k = 0; k < searched.size(); k += 3) {
      dem::ContactHistory h;
      h.tangential_slip = Vec3(k, -0.5 * k, 1.0);
      h.rolling_slip = Vec3(0.0, k, 2.0);
      h.max_overlap = 1e-3 * k;
      h.attached = k % 2 == 0;
      searched.set_history(k, h);
    }
    dem::NeighborList renumbered = searched;
    std::vector<std::uint32_t> order(s.spheres.size());
    std::iota(order.begin(), order.end(), 0U);
    if (seed % 2 == 0) {
      std::mt19937_64 rng(seed);
      std::shuffle(order.begin(), order.end(), rng);
    } else {
      Vec3Array positions(3, static_cast<Eigen::Index>(s.spheres.size()));
      for (std::size_t i = 0; i < s.spheres.size(); ++i) {
        positions.col(static_cast<Eigen::Index>(i)) = Vec3(s.spheres[i].x, s.spheres[i].y, s.spheres[i].z);
      }
      order = dem::morton_order(positions, box, 0.05);
    }
    const auto new_of_old = dem::inverse_permutation(order);
    test_support::RandomSpheres moved;
    for (const std::uint32_t k : order) {
      moved.spheres.push_back(s.spheres[k]);
      moved.still.push_back(s.still[k]);
    }
    const std::uint64_t builds = renumbered.builds();
    renumbered.permute(moved.spheres, box, new_of_old, 1 + static_cast<int>(seed % 2));
    EXPECT_EQ(renumbered.builds(), builds) << "a renumbering is not a build";
    // A shuffle scatters each slab's owners over the indices, with owners of other slabs, some
    // without entries, between them.
    expect_runs_cover_the_slabs(renumbered, seed % 2 == 0 ? "shuffled" : "Morton order");
    searched = build_list(moved, box, skin, 1, new_of_old, std::move(searched));
    ASSERT_EQ(renumbered.size(), searched.size()) << "seed " << seed;
    EXPECT_EQ(renumbered.periodic(), searched.periodic()) << "seed " << seed;
    for (std::uint32_t i = 0; i < searched.sphere_count(); ++i) {
      ASSERT_EQ(renumbered.begin(i), searched.begin(i)) << "seed " << seed << " sphere " << i;
      EXPECT_EQ(renumbered.shifted(i), searched.shifted(i)) << "seed " << seed << " sphere " << i;
      EXPECT_EQ(renumbered.slabs().of(i), searched.slabs().of(i)) << "seed " << seed << " sphere " << i;
    }
    for (std::size_t k = 0; k < searched.size(); ++k) {
      EXPECT_EQ(renumbered.partners()[k], searched.partners()[k]) << "seed " << seed << " entry " << k;
      EXPECT_EQ(renumbered.contacts()[k], searched.contacts()[k]) << "seed " << seed << " entry " << k;
      const dem::ContactHistory a = renumbered.history(k);
      const dem::ContactHistory b = searched.history(k);
      EXPECT_EQ(a.tangential_slip, b.tangential_slip) << "seed " << seed << " entry " << k;
      EXPECT_EQ(a.rolling_slip, b.rolling_slip) << "seed " << seed << " entry " << k;
      EXPECT_EQ(a.max_overlap, b.max_overlap) << "seed " << seed << " entry " << k;
      EXPECT_EQ(a.attached, b.attached) << "seed " << seed << " entry " << k;
    }
  }
}

TEST(SpatialOrder, MortonKeysInterleaveTheBits) {
  EXPECT_EQ(dem::morton_key(1, 0, 0), 1U);
  EXPECT_EQ(dem::morton_key(0, 1, 0), 2U);
  EXPECT_EQ(dem::morton_key(0, 0, 1), 4U);
  EXPECT_EQ(dem::morton_key(3, 3, 3), 63U);
  EXPECT_EQ(dem::morton_key((1U << 21U) - 1U, 0, 0), 0x1249249249249249ULL);
}

}  // namespace
