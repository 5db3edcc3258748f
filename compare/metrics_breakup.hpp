// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "dem/core/vector.hpp"

// Breakup metrics of an agglomerate (thesis §5.2.4), computed from two snapshots — the formed
// agglomerate and the end of the impact — the same way for every engine (docs/metrics.md,
// "Agglomerate breakup"). Fragments are the connected components of the bond graph, found with
// a union–find over the candidate pairs of a neighbour search (no all-pairs scan).
namespace comparison::breakup {

/// One sphere of a snapshot: centre [m] and body radius [m].
struct SnapshotSphere {
  dem::Vec3 position;
  double radius;
};

/// When two spheres count as one body. i and j can be bonded only while their centres are
/// closer than half_reach[i] + half_reach[j]; `bonded` (optional) then decides from the centre
/// distance, e.g. a JKR neck that holds down to its rupture overlap. Without `bonded`, every
/// pair closer than half_reach[i] + half_reach[j] is bonded (body contact: the radii; linear
/// cohesion: the effect radii).
struct BondRule {
  std::vector<double> half_reach;  ///< [m], one per sphere, ≥ 0
  std::function<bool(std::uint32_t, std::uint32_t, double)> bonded;  ///< (i, j, distance [m])
};

/// The bond rule of body contact: bonded while the bodies overlap (δ > 0), as κDAMAGE counts
/// contacts ("in contact if their base radii overlap", thesis §5.2.4).
[[nodiscard]] BondRule body_contact(std::span<const SnapshotSphere> spheres);

/// Every bonded pair (i < j) of a snapshot under `rule`, in increasing (i, j) order.
[[nodiscard]] std::vector<std::pair<std::uint32_t, std::uint32_t>> bonded_pairs(
    std::span<const SnapshotSphere> spheres, const BondRule& rule);

/// The fragments of a snapshot: connected components of the bond graph.
struct Fragments {
  std::vector<std::uint32_t> of;  ///< fragment of each sphere, 0 = the largest by volume
  std::vector<double> volume;     ///< Σ 4/3 π r³ of each fragment [m³], largest first
  std::vector<std::uint32_t> size;  ///< spheres in each fragment, in the order of `volume`
};

/// Fragments of a snapshot under `rule`. Ties in volume are ordered by the smallest sphere
/// index in the fragment, so the numbering is deterministic.
[[nodiscard]] Fragments fragments(std::span<const SnapshotSphere> spheres, const BondRule& rule);

/// The breakup metrics of one impact.
struct BreakupMetrics {
  double kappa_vol;             ///< volume of the largest final fragment / initial volume (eq 5.2), in [0, 1]
  double kappa_damage;          ///< fraction of the initial body contacts no longer touching, in [0, 1]
  std::uint32_t fragments;      ///< number of final fragments (a lone sphere is one)
  std::vector<double> fragment_volume;  ///< final fragments' volumes [m³], largest first
  double coordination_before;   ///< mean body contacts per sphere, formed agglomerate
  double coordination_after;    ///< mean body contacts per sphere, end of the impact
};

/// κVOL, κDAMAGE, fragments and coordination numbers from the formed agglomerate `before` and
/// the final snapshot `after` (the same spheres in the same order). `after_rule` decides which
/// final spheres are still one fragment (body contact unless cohesion reaches further);
/// contacts for κDAMAGE and coordination are always body contacts. The initial volume is that
/// of every sphere of `before`. Throws std::invalid_argument when the snapshots differ in size,
/// are empty, or hold a radius that is not positive and finite.
[[nodiscard]] BreakupMetrics breakup_metrics(std::span<const SnapshotSphere> before,
                                             std::span<const SnapshotSphere> after,
                                             const BondRule& after_rule);

}  // namespace comparison::breakup
