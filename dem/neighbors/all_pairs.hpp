// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

#include "dem/particles/particles.hpp"

namespace dem {

/// Calls visit(i, j) for every pair i < j, at least one of them mobile, whose centres are within
/// reach(i, j) of each other. O(N²): a brute-force search, adequate for the small canonical
/// scenes; a cell list replaces it for large ones.
template <class Visit, class Reach>
void for_each_candidate_pair(const ParticleProperties& props, const Vec3Array& position,
                             Visit&& visit, Reach&& reach) {
  const auto n = static_cast<std::uint32_t>(props.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = i + 1; j < n; ++j) {
      if (props.fixed[i] != 0 && props.fixed[j] != 0) continue;
      const double r = reach(i, j);
      if ((position.col(i) - position.col(j)).squaredNorm() <= r * r) visit(i, j);
    }
  }
}

}  // namespace dem
