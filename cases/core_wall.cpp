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

std::optional<WallOverlap> first_wall_overlap(const Scene& scene, const std::function<bool(const WallSpec&)>& counts,
                                              double share) {
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const ParticleSpec& p = scene.particles[i];
    if (p.fixed) continue;
    const dem::Vec3 x = to_vec(p.position);
    for (std::size_t w = 0; w < scene.walls.size(); ++w) {
      if (!counts(scene.walls[w])) continue;
      const double overlap = p.radius - dem::wall_frame(core_wall(scene.walls[w]), x, 0.0).distance;
      if (!(overlap <= share * p.radius)) return WallOverlap{i, w, overlap};  // NaN counts as inside
    }
  }
  return std::nullopt;
}

}  // namespace cases
