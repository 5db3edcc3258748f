// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "dem/core/vector.hpp"
#include "dem/domain/periodic_box.hpp"
#include "dem/neighbors/packed_sphere.hpp"

namespace dem {

/// An axis-aligned grid of cubic-ish cells over the spheres of one size class (thesis appendix
/// B.1, "spatial zoning"), as a CSR table cell → member spheres in increasing index order.
/// Along a periodic axis the grid spans the box exactly; along the others it spans the spheres'
/// bounding box, and coordinates outside it fall in the end cells.
class CellGrid {
 public:
  /// Slots past the last member that may be read (they hold no sphere), so that copies of a run
  /// of members may go a few past its end.
  static constexpr std::size_t kPadding = 8;

  /// Bins `members` (indices into `spheres`) into cells with edges ≥ `min_edge` over the region
  /// [lo, hi] (the box along periodic axes). The cell count is capped near 2 per member plus 64
  /// (edges grow instead), so sparse scenes do not allocate empty space.
  void assign(std::span<const PackedSphere> spheres, std::span<const std::uint32_t> members,
              const Vec3& lo, const Vec3& hi, const PeriodicBox& box, double min_edge);

  /// Cell coordinates of a point (clamped into the grid).
  [[nodiscard]] std::array<int, 3> coordinates(double x, double y, double z) const noexcept {
    const double p[3] = {x, y, z};
    std::array<int, 3> c{};
    for (int k = 0; k < 3; ++k) {
      const double f = (p[k] - origin_[k]) / edge_[k];
      // floor(f), which for 0 ≤ f < dims is the truncation (no call to floor); NaN and points
      // below the grid go to cell 0, points at or above its top to the last cell.
      c[k] = !(f >= 0.0) ? 0 : (f >= dims_[k] ? dims_[k] - 1 : static_cast<int>(f));
    }
    return c;
  }
  /// Records, per cell, the smallest and largest `tag` (indexed by sphere, each < 65,536) of its
  /// members: the neighbour search skips cells that cannot hold a sphere it is looking for.
  void summarise(std::span<const std::uint32_t> tag);
  /// False when no member of cell c has tag a or tag b (by the range summarise() recorded).
  [[nodiscard]] bool may_hold(std::size_t c, std::uint32_t a, std::uint32_t b) const noexcept {
    const std::uint32_t lo = tag_range_[c] & 0xFFFFU;
    const std::uint32_t hi = tag_range_[c] >> 16U;
    return (a - lo <= hi - lo) | (b - lo <= hi - lo);  // unsigned: lo ≤ a ≤ hi, or lo ≤ b ≤ hi
  }
  /// Linear index of cell coordinates.
  [[nodiscard]] std::size_t index(int cx, int cy, int cz) const noexcept {
    return (static_cast<std::size_t>(cz) * static_cast<std::size_t>(dims_[1]) +
            static_cast<std::size_t>(cy)) * static_cast<std::size_t>(dims_[0]) +
           static_cast<std::size_t>(cx);
  }
  /// First slot of cell c in members(); cell c holds [first(c), first(c + 1)).
  [[nodiscard]] std::uint32_t first(std::size_t c) const noexcept { return start_[c]; }
  /// The members of every cell, cell after cell (the cells of a row along x follow each other),
  /// followed by kPadding slots that belong to no cell.
  [[nodiscard]] std::span<const std::uint32_t> members() const noexcept {
    return {members_.data(), members_.empty() ? 0 : members_.size() - kPadding};
  }
  /// Number of cells.
  [[nodiscard]] std::size_t cell_count() const noexcept { return start_.empty() ? 0 : start_.size() - 1; }
  /// Cell coordinates of linear index c (the inverse of index()).
  [[nodiscard]] std::array<int, 3> coordinates_of(std::size_t c) const noexcept {
    const auto nx = static_cast<std::size_t>(dims_[0]);
    const auto ny = static_cast<std::size_t>(dims_[1]);
    return {static_cast<int>(c % nx), static_cast<int>(c / nx % ny), static_cast<int>(c / (nx * ny))};
  }
  /// The reach the grid was binned for (the least edge asked of assign()) [m]: no search from one
  /// of its cells needs to reach further.
  [[nodiscard]] double reach() const noexcept { return reach_; }
  /// Cells per axis.
  [[nodiscard]] const std::array<int, 3>& dims() const noexcept { return dims_; }
  /// Cell edge per axis [m].
  [[nodiscard]] const Vec3& edge() const noexcept { return edge_; }
  /// Bytes held.
  [[nodiscard]] std::size_t bytes() const noexcept {
    return (start_.capacity() + members_.capacity() + tag_range_.capacity()) * sizeof(std::uint32_t);
  }

 private:
  Vec3 origin_ = Vec3::Zero();
  Vec3 edge_ = Vec3::Ones();
  double reach_ = 0.0;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> members_;
  std::vector<std::uint32_t> cell_of_;  // scratch: cell of each member
  std::vector<std::uint32_t> cursor_;   // scratch: next free slot per cell
  std::vector<std::uint32_t> tag_range_;  // per cell: smallest tag | largest tag << 16
};

}  // namespace dem
