// SPDX-License-Identifier: MIT
#include "compare/metrics_breakup.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <fmt/format.h>

#include "dem/domain/periodic_box.hpp"
#include "dem/neighbors/neighbor_list.hpp"
#include "dem/particles/particles.hpp"

namespace comparison::breakup {
namespace {

/// Disjoint sets over sphere indices (union by size, path halving).
class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n), size_(n, 1) { std::iota(parent_.begin(), parent_.end(), 0U); }
  /// The representative of i's set.
  std::uint32_t find(std::uint32_t i) noexcept {
    while (parent_[i] != i) {
      parent_[i] = parent_[parent_[i]];
      i = parent_[i];
    }
    return i;
  }
  /// Joins the sets of a and b.
  void join(std::uint32_t a, std::uint32_t b) noexcept {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (size_[a] < size_[b]) std::swap(a, b);
    parent_[b] = a;
    size_[a] += size_[b];
  }

 private:
  std::vector<std::uint32_t> parent_;
  std::vector<std::uint32_t> size_;
};

void check_radii(std::span<const SnapshotSphere> spheres, const char* which) {
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const double r = spheres[i].radius;
    if (!(r > 0.0) || !std::isfinite(r)) {
      throw std::invalid_argument(fmt::format("{} snapshot: sphere {} has radius {} (must be positive and finite)", which, i, r));
    }
    if (!spheres[i].position.allFinite()) {
      throw std::invalid_argument(fmt::format("{} snapshot: sphere {} has a non-finite position", which, i));
    }
  }
}

}  // namespace

BondRule body_contact(std::span<const SnapshotSphere> spheres) {
  BondRule rule;
  rule.half_reach.reserve(spheres.size());
  for (const SnapshotSphere& s : spheres) rule.half_reach.push_back(s.radius);
  return rule;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> bonded_pairs(std::span<const SnapshotSphere> spheres,
                                                                    const BondRule& rule) {
  if (rule.half_reach.size() != spheres.size()) {
    throw std::invalid_argument(fmt::format("bond rule: {} half reaches for {} spheres", rule.half_reach.size(), spheres.size()));
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  if (spheres.empty()) return out;
  // Candidates from the core's cell search (pairs within h_i + h_j plus a skin far below any
  // sphere), then the exact test.
  std::vector<dem::PackedSphere> packed;
  packed.reserve(spheres.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const double h = rule.half_reach[i];
    if (!(h >= 0.0) || !std::isfinite(h)) {
      throw std::invalid_argument(fmt::format("bond rule: sphere {} has half reach {} (must be ≥ 0 and finite)", i, h));
    }
    const dem::Vec3& x = spheres[i].position;
    packed.push_back({x[0], x[1], x[2], h});
    largest = std::max(largest, h);
  }
  const std::vector<std::uint8_t> still(spheres.size(), 0);
  const dem::SizeClasses classes = dem::size_classes(rule.half_reach);
  const dem::PeriodicBox open;
  dem::NeighborList list;
  const double skin = std::max(largest, 1e-300) * 1e-9;
  list.build({packed, still, classes.of, classes.max_half_reach, &open, skin, 1, false});
  for (std::uint32_t i = 0; i < list.sphere_count(); ++i) {
    for (std::uint32_t k = list.begin(i); k < list.begin(i + 1); ++k) {
      const std::uint32_t j = list.partners()[k] & dem::kPartnerMask;
      const double distance = (spheres[i].position - spheres[j].position).norm();
      if (!(distance < rule.half_reach[i] + rule.half_reach[j])) continue;
      const std::uint32_t a = std::min(i, j);
      const std::uint32_t b = std::max(i, j);
      if (rule.bonded && !rule.bonded(a, b, distance)) continue;
      out.emplace_back(a, b);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

Fragments fragments(std::span<const SnapshotSphere> spheres, const BondRule& rule) {
  const auto n = static_cast<std::uint32_t>(spheres.size());
  UnionFind sets(n);
  for (const auto& [i, j] : bonded_pairs(spheres, rule)) sets.join(i, j);
  // Each root's volume (summed in sphere order), size and smallest member.
  std::vector<double> volume(n, 0.0);
  std::vector<std::uint32_t> size(n, 0);
  std::vector<std::uint32_t> first(n, n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t r = sets.find(i);
    volume[r] += dem::sphere_volume(spheres[i].radius);
    ++size[r];
    first[r] = std::min(first[r], i);
  }
  std::vector<std::uint32_t> roots;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (size[i] > 0) roots.push_back(i);
  }
  std::sort(roots.begin(), roots.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (volume[a] != volume[b]) return volume[a] > volume[b];
    return first[a] < first[b];
  });
  std::vector<std::uint32_t> number(n, 0);
  Fragments out;
  for (std::uint32_t k = 0; k < roots.size(); ++k) {
    number[roots[k]] = k;
    out.volume.push_back(volume[roots[k]]);
    out.size.push_back(size[roots[k]]);
  }
  out.of.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) out.of[i] = number[sets.find(i)];
  return out;
}

BreakupMetrics breakup_metrics(std::span<const SnapshotSphere> before, std::span<const SnapshotSphere> after,
                               const BondRule& after_rule) {
  if (before.empty()) throw std::invalid_argument("breakup metrics: the formed agglomerate has no spheres");
  if (before.size() != after.size()) {
    throw std::invalid_argument(fmt::format("breakup metrics: {} spheres before the impact, {} after", before.size(), after.size()));
  }
  check_radii(before, "formed agglomerate");
  check_radii(after, "final");
  const auto initial = bonded_pairs(before, body_contact(before));
  if (initial.empty()) {
    throw std::invalid_argument("breakup metrics: the formed agglomerate has no body contacts, so κDAMAGE is undefined");
  }
  std::size_t broken = 0;
  for (const auto& [i, j] : initial) {
    const double distance = (after[i].position - after[j].position).norm();
    if (!(distance < after[i].radius + after[j].radius)) ++broken;
  }
  const std::size_t final_contacts = bonded_pairs(after, body_contact(after)).size();
  double total = 0.0;
  for (const SnapshotSphere& s : before) total += dem::sphere_volume(s.radius);
  const Fragments f = fragments(after, after_rule);
  // Volumes from the formed agglomerate's radii (a sphere keeps its radius; a trace may print it
  // with fewer digits), so the largest fragment never exceeds the whole.
  std::vector<double> volume(f.volume.size(), 0.0);
  for (std::size_t i = 0; i < before.size(); ++i) volume[f.of[i]] += dem::sphere_volume(before[i].radius);
  const auto n = static_cast<double>(before.size());
  BreakupMetrics m;
  m.kappa_vol = volume.front() / total;
  m.kappa_damage = static_cast<double>(broken) / static_cast<double>(initial.size());
  m.fragments = static_cast<std::uint32_t>(f.volume.size());
  m.fragment_volume = volume;
  m.coordination_before = 2.0 * static_cast<double>(initial.size()) / n;
  m.coordination_after = 2.0 * static_cast<double>(final_contacts) / n;
  return m;
}

}  // namespace comparison::breakup
