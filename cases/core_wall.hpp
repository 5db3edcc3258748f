// SPDX-License-Identifier: MIT
#pragma once

#include "cases/scene.hpp"
#include "dem/contact/wall.hpp"

namespace cases {

/// The core's wall for a case wall: the same shape, place, velocity, material and removal time.
[[nodiscard]] dem::Wall core_wall(const WallSpec& w) noexcept;

}  // namespace cases
