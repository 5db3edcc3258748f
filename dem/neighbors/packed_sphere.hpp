// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>

namespace dem {

/// A sphere's centre, wrapped into the periodic box at the last list build, and its half reach
/// (neighbors/interaction_reach.hpp), packed as one 32-byte record: the pair loop's distance test
/// reads exactly one record per partner.
struct PackedSphere {
  double x;
  double y;
  double z;
  double half_reach;  ///< h [m]: two spheres may interact only within h_i + h_j
};

/// Partner index bits of a list entry; the five bits above hold the periodic shift code.
inline constexpr std::uint32_t kPartnerBits = 27;
/// Mask of the partner index in a list entry.
inline constexpr std::uint32_t kPartnerMask = (std::uint32_t{1} << kPartnerBits) - 1;
/// Largest number of spheres a neighbour list can index.
inline constexpr std::uint32_t kMaxSpheres = kPartnerMask;
/// Shift code of a partner seen without a periodic shift: (0+1) + 3·(0+1) + 9·(0+1).
inline constexpr std::uint32_t kNoShift = 13;

}  // namespace dem
