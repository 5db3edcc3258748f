// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <vector>

#include "dem/core/vector.hpp"

namespace dem {

/// One stretch of a prescribed motion: a constant velocity for a duration (the last stretch
/// lasts forever).
struct MotionSegment {
  double duration;  ///< [s]
  Vec3 velocity;    ///< [m/s]
};

/// Displacement-controlled motion of an infinite-mass sphere: piecewise-constant velocity from
/// its initial position (e.g. approach then retract in a JKR pull-off test). Position is
/// continuous, velocity jumps between segments.
struct PrescribedMotion {
  std::uint32_t particle;
  Vec3 start;                           ///< position at t = 0 [m]
  std::vector<MotionSegment> segments;  ///< at least one

  /// Position at time t ≥ 0 [m].
  [[nodiscard]] Vec3 position(double t) const noexcept {
    Vec3 x = start;
    double begin = 0.0;
    for (std::size_t k = 0; k < segments.size(); ++k) {
      const bool last = k + 1 == segments.size();
      const double end = begin + segments[k].duration;
      if (last || t < end) return x + (t - begin) * segments[k].velocity;
      x += segments[k].duration * segments[k].velocity;
      begin = end;
    }
    return x;
  }
  /// Velocity at time t [m/s] (the velocity of the segment t lies in).
  [[nodiscard]] Vec3 velocity(double t) const noexcept {
    double end = 0.0;
    for (std::size_t k = 0; k + 1 < segments.size(); ++k) {
      end += segments[k].duration;
      if (t < end) return segments[k].velocity;
    }
    return segments.back().velocity;
  }
};

}  // namespace dem
