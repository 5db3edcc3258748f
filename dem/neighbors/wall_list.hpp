// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "dem/contact/contact_geometry.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/neighbors/neighbor_list.hpp"

namespace dem {

/// One sphere–wall candidate: the wall, whether the contact interacted at the last commit and
/// its tangential slip (32 bytes).
struct WallEntry {
  std::uint32_t wall;
  std::uint32_t active;
  Vec3 slip;
};

/// Sphere–wall candidates in CSR form (sphere → its candidate walls, in wall order) with the
/// contact history beside them, keyed by (sphere, wall): every sphere–wall pair owns its own
/// history. Rebuilt with the sphere list; the history of every interacting contact carries over.
class WallList {
 public:
  /// Lists, for every sphere that is not `still`, the walls present at t whose surface lies within
  /// reach(i, w) + skin of its centre at time t. `new_of_old` maps the previous build's sphere
  /// indices to the current ones (empty: unchanged).
  void build(std::span<const PackedSphere> spheres, std::span<const std::uint8_t> still,
             const std::vector<Wall>& walls, double t, double skin,
             const std::function<double(std::uint32_t, std::uint32_t)>& reach,
             bool extended_history, std::span<const std::uint32_t> new_of_old = {});

  /// First candidate of sphere i; its candidates are [begin(i), begin(i + 1)).
  [[nodiscard]] std::uint32_t begin(std::uint32_t i) const noexcept { return offsets_[i]; }
  /// All candidates.
  [[nodiscard]] std::span<WallEntry> entries() noexcept { return entries_; }
  [[nodiscard]] std::span<const WallEntry> entries() const noexcept { return entries_; }
  /// Extended history parallel to entries() (empty unless the build asked for it).
  [[nodiscard]] std::span<ExtendedHistory> extended() noexcept { return extended_; }
  [[nodiscard]] std::span<const ExtendedHistory> extended() const noexcept { return extended_; }
  /// Candidate index of (sphere i, wall w), or −1.
  [[nodiscard]] std::int64_t find(std::uint32_t i, std::uint32_t w) const noexcept;
  /// The committed history of candidate k (fresh when not active).
  [[nodiscard]] ContactHistory history(std::size_t k) const noexcept;
  /// Bytes held.
  [[nodiscard]] std::size_t bytes() const noexcept;

 private:
  struct Carried {
    std::uint32_t sphere;
    std::uint32_t wall;
    Vec3 slip;
    ExtendedHistory extended;
  };
  std::vector<std::uint32_t> offsets_;
  std::vector<WallEntry> entries_;
  std::vector<ExtendedHistory> extended_;
  std::vector<Carried> carried_;
  /// Per wall, a sphere holding a triangle's surface at the build's time (set for triangles only).
  struct Bounds {
    Vec3 centre;
    double radius;
  };
  std::vector<Bounds> bounds_;
};

}  // namespace dem
