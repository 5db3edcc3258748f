// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "dem/particles/particles.hpp"

namespace dem {

/// Calls visit(i, j) for every pair i < j whose centres are within reach(i, j) of each other,
/// unless both spheres stand still (fixed and not `moving`: their contact can change nothing).
/// O(N²): a brute-force search, adequate for the small canonical scenes; a cell list replaces it
/// for large ones.
template <class Visit, class Reach>
void for_each_candidate_pair(const ParticleProperties& props, const std::vector<std::uint8_t>& moving,
                             const Vec3Array& position, Visit&& visit, Reach&& reach) {
  const auto n = static_cast<std::uint32_t>(props.size());
  const auto still = [&](std::uint32_t k) { return props.fixed[k] != 0 && moving[k] == 0; };
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = i + 1; j < n; ++j) {
      if (still(i) && still(j)) continue;
      const double r = reach(i, j);
      if ((position.col(i) - position.col(j)).squaredNorm() <= r * r) visit(i, j);
    }
  }
}

}  // namespace dem
