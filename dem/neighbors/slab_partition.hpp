// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "dem/core/vector.hpp"
#include "dem/domain/periodic_box.hpp"
#include "dem/neighbors/packed_sphere.hpp"

namespace dem {

/// Slabs along one axis, each at least as wide as the longest pair in the neighbour list, so
/// that a pair joins spheres of the same or of adjacent slabs. A pair is owned by its lower slab
/// (in ring order along a periodic axis), and within a slab by its lower index. The pair loop
/// then runs the even slabs in parallel, then the odd ones: two slabs of one colour never touch
/// the same sphere, so threads need neither atomics nor private force buffers, and every sphere
/// receives its pair forces in an order fixed by the slabs alone — the same for any number of
/// threads (the deterministic mode is the only mode).
class SlabPartition {
 public:
  /// Slabs of width ≥ `min_width` along the longest axis of the spheres' extent (the box length
  /// along a periodic axis), at most one per sphere. Fewer than two slabs (four along a periodic
  /// axis, an even number there) make one slab.
  void assign(std::span<const PackedSphere> spheres, const Vec3& lo, const Vec3& hi,
              const PeriodicBox& box, double min_width);

  /// Number of slabs.
  [[nodiscard]] std::uint32_t count() const noexcept { return count_; }
  /// Slab of sphere i.
  [[nodiscard]] std::uint32_t of(std::uint32_t i) const noexcept { return slab_of_[i]; }
  /// Slab of every sphere.
  [[nodiscard]] std::span<const std::uint32_t> all() const noexcept { return slab_of_; }
  /// The spheres of slab s, in increasing index order.
  [[nodiscard]] std::span<const std::uint32_t> members(std::uint32_t s) const noexcept {
    return {members_.data() + start_[s], members_.data() + start_[s + 1]};
  }
  /// The slab whose pairs with slab s slab s owns: the one after it (the first after the last
  /// along a periodic axis), or count() — no slab — after the last along an open axis.
  [[nodiscard]] std::uint32_t next(std::uint32_t s) const noexcept {
    const std::uint32_t after = s + 1;
    return ring_ && after == count_ ? 0 : after;
  }
  /// True when sphere i owns its pair with sphere j (see the class comment).
  [[nodiscard]] bool owns(std::uint32_t i, std::uint32_t j) const noexcept {
    const std::uint32_t si = slab_of_[i];
    const std::uint32_t sj = slab_of_[j];
    if (si == sj) return i < j;
    return sj == next(si);
  }
  /// Bytes held.
  [[nodiscard]] std::size_t bytes() const noexcept {
    return (slab_of_.capacity() + start_.capacity() + members_.capacity()) * sizeof(std::uint32_t);
  }

 private:
  std::uint32_t count_ = 1;
  bool ring_ = false;  // periodic along the slab axis: the last slab's next is the first
  std::vector<std::uint32_t> slab_of_;
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> members_;
  std::vector<std::uint32_t> cursor_;  // scratch of assign()
};

}  // namespace dem
