// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "dem/core/vector.hpp"
#include "dem/domain/periodic_box.hpp"
#include "dem/neighbors/packed_sphere.hpp"

namespace dem {

/// Every pair i < j whose nearest periodic images lie closer than h_i + h_j + skin, unless both
/// spheres are `still`: the O(N²) search the neighbour list must reproduce exactly (the test
/// oracle of thesis appendix B's near-neighbour search).
[[nodiscard]] inline std::vector<std::pair<std::uint32_t, std::uint32_t>> brute_force_pairs(
    std::span<const PackedSphere> spheres, std::span<const std::uint8_t> still,
    const PeriodicBox& box, double skin) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  const auto n = static_cast<std::uint32_t>(spheres.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = i + 1; j < n; ++j) {
      if (still[i] != 0 && still[j] != 0) continue;
      Vec3 d(spheres[i].x - spheres[j].x, spheres[i].y - spheres[j].y, spheres[i].z - spheres[j].z);
      d += box.minimum_image_shift(d);
      const double cut = spheres[i].half_reach + spheres[j].half_reach + skin;
      if (d.squaredNorm() < cut * cut) out.emplace_back(i, j);
    }
  }
  return out;
}

}  // namespace dem
