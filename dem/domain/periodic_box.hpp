// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cmath>

#include "dem/core/vector.hpp"

namespace dem {

/// The simulation box along the periodic axes: bounds and which axes wrap. Along an axis that
/// is not periodic the bounds are unused (particles may go anywhere; walls confine them).
struct PeriodicBox {
  Vec3 lo = Vec3::Zero();  ///< lower corner [m]
  Vec3 hi = Vec3::Zero();  ///< upper corner [m]
  std::array<bool, 3> periodic{false, false, false};

  /// True when at least one axis wraps.
  [[nodiscard]] bool any() const noexcept { return periodic[0] || periodic[1] || periodic[2]; }
  /// Box length per axis [m].
  [[nodiscard]] Vec3 length() const noexcept { return hi - lo; }

  /// How many box lengths x lies past lo along each periodic axis: floor((x − lo)/L); 0 along
  /// the other axes. x − image·L lies in [lo, hi).
  [[nodiscard]] std::array<int, 3> image_of(const Vec3& x) const noexcept {
    std::array<int, 3> image{0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      if (periodic[k]) image[k] = static_cast<int>(std::floor((x[k] - lo[k]) / (hi[k] - lo[k])));
    }
    return image;
  }

  /// The shift s (a whole number of box lengths per periodic axis) that makes d + s the
  /// shortest periodic image of the displacement d (minimum image convention).
  [[nodiscard]] Vec3 minimum_image_shift(const Vec3& d) const noexcept {
    Vec3 s = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      if (periodic[k]) {
        const double l = hi[k] - lo[k];
        s[k] = -l * std::nearbyint(d[k] / l);
      }
    }
    return s;
  }
};

}  // namespace dem
