// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "dem/core/vector.hpp"
#include "dem/domain/periodic_box.hpp"

namespace dem {

/// Interleaves the low 21 bits of three cell coordinates into a Morton (Z-order) key.
[[nodiscard]] std::uint64_t morton_key(std::uint32_t x, std::uint32_t y, std::uint32_t z) noexcept;

/// The order of the spheres along a Morton curve through cells of edge `cell` [m] (centres
/// wrapped into the box along periodic axes): element k is the current index of the sphere that
/// goes to place k. With `major` (one group per sphere, e.g. its slab), spheres are ordered by
/// group first and along the curve within a group. Spheres of one cell keep their relative
/// order, so the result is a function of the positions (and groups) alone. Neighbours in space
/// become neighbours in memory.
[[nodiscard]] std::vector<std::uint32_t> morton_order(const Vec3Array& position,
                                                      const PeriodicBox& box, double cell,
                                                      std::span<const std::uint32_t> major = {});

/// The inverse of a permutation: inverse[order[k]] = k.
[[nodiscard]] std::vector<std::uint32_t> inverse_permutation(std::span<const std::uint32_t> order);

}  // namespace dem
