// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <functional>
#include <optional>

#include "cases/scene.hpp"
#include "dem/contact/wall.hpp"

namespace cases {

/// The core's wall for a case wall: the same shape, place, velocity, material and removal time.
[[nodiscard]] dem::Wall core_wall(const WallSpec& w) noexcept;

/// A mobile sphere inside a wall: the sphere, the wall (indices into the scene) and the overlap [m].
struct WallOverlap {
  std::size_t particle = 0;
  std::size_t wall = 0;
  double overlap = 0.0;
};

/// The first mobile sphere of `scene` (then the first wall, in order) among the walls `counts` picks
/// that overlaps the wall by more than `share` of its radius, measured at t = 0 to the wall's
/// nearest surface point (dem::wall_frame); empty when there is none.
[[nodiscard]] std::optional<WallOverlap> first_wall_overlap(const Scene& scene,
                                                            const std::function<bool(const WallSpec&)>& counts,
                                                            double share);

}  // namespace cases
