// SPDX-License-Identifier: MIT
#include "cases/core_wall.hpp"

#include <cstdint>
#include <limits>

namespace cases {
namespace {

dem::Vec3 to_vec(const Vector3& v) noexcept { return {v[0], v[1], v[2]}; }

}  // namespace

dem::Wall core_wall(const WallSpec& w) noexcept {
  dem::Wall out{to_vec(w.point), to_vec(w.normal), to_vec(w.velocity), static_cast<std::uint32_t>(w.material)};
  out.shape = w.shape;
  out.axis_u = to_vec(w.axis_u);
  out.size_u = w.size_u;
  out.size_v = w.size_v;
  out.length = w.length;
  out.removed_at = w.removed_at.value_or(std::numeric_limits<double>::infinity());
  return out;
}

}  // namespace cases
