// SPDX-License-Identifier: MIT
#include "dem/neighbors/cell_grid.hpp"

#include <algorithm>
#include <cmath>

namespace dem {

void CellGrid::assign(std::span<const PackedSphere> spheres, std::span<const std::uint32_t> members,
                      const Vec3& lo, const Vec3& hi, const PeriodicBox& box, double min_edge) {
  reach_ = min_edge;
  Vec3 extent;
  for (int k = 0; k < 3; ++k) {
    origin_[k] = box.periodic[k] ? box.lo[k] : lo[k];
    extent[k] = box.periodic[k] ? box.hi[k] - box.lo[k] : hi[k] - lo[k];
  }
  // Cells no smaller than min_edge, and not many more than the members (sparse scenes).
  const double cap = 2.0 * static_cast<double>(members.size()) + 64.0;
  double edge = min_edge;
  for (;;) {
    double cells = 1.0;
    for (int k = 0; k < 3; ++k) cells *= std::max(1.0, std::floor(extent[k] / edge));
    if (cells <= cap) break;
    edge *= std::cbrt(cells / cap) * 1.0001;
  }
  std::size_t total = 1;
  for (int k = 0; k < 3; ++k) {
    dims_[k] = static_cast<int>(std::max(1.0, std::floor(extent[k] / edge)));
    // extent / floor(extent / edge) may round a hair below min_edge: one cell fewer, so that no
    // search from a cell needs more than its neighbours (the stencil's reach is min_edge).
    while (dims_[k] > 1 && extent[k] / dims_[k] < min_edge) --dims_[k];
    edge_[k] = extent[k] > 0.0 ? extent[k] / dims_[k] : edge;
    total *= static_cast<std::size_t>(dims_[k]);
  }

  // Counting sort by cell; members are visited in increasing order, so each cell's list is too.
  start_.assign(total + 1, 0);
  cell_of_.resize(members.size());
  for (std::size_t m = 0; m < members.size(); ++m) {
    const PackedSphere& s = spheres[members[m]];
    const auto c = coordinates(s.x, s.y, s.z);
    cell_of_[m] = static_cast<std::uint32_t>(index(c[0], c[1], c[2]));
    ++start_[cell_of_[m] + 1];
  }
  for (std::size_t c = 0; c < total; ++c) start_[c + 1] += start_[c];
  members_.assign(members.size() + kPadding, 0);
  cursor_.assign(start_.begin(), start_.end() - 1);
  for (std::size_t m = 0; m < members.size(); ++m) members_[cursor_[cell_of_[m]]++] = members[m];
}

void CellGrid::summarise(std::span<const std::uint32_t> tag) {
  const std::size_t cells = start_.size() - 1;
  tag_range_.resize(cells);
  for (std::size_t c = 0; c < cells; ++c) {
    if (start_[c] == start_[c + 1]) {
      tag_range_[c] = 0xFFFFU << 16U;  // empty: any tag (there is nothing to scan anyway)
      continue;
    }
    std::uint32_t lo = 0xFFFFU;
    std::uint32_t hi = 0;
    for (std::uint32_t m = start_[c]; m < start_[c + 1]; ++m) {
      const std::uint32_t t = tag[members_[m]];
      lo = std::min(lo, t);
      hi = std::max(hi, t);
    }
    tag_range_[c] = lo | (hi << 16U);
  }
}

}  // namespace dem
