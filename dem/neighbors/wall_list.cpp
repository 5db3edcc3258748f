// SPDX-License-Identifier: MIT
#include "dem/neighbors/wall_list.hpp"

#include <algorithm>

namespace dem {

void WallList::build(std::span<const PackedSphere> spheres, std::span<const std::uint8_t> still,
                     const std::vector<Wall>& walls, double t, double skin,
                     const std::function<double(std::uint32_t, std::uint32_t)>& reach,
                     bool extended_history, std::span<const std::uint32_t> new_of_old) {
  carried_.clear();
  const auto old_n = static_cast<std::uint32_t>(offsets_.empty() ? 0 : offsets_.size() - 1);
  for (std::uint32_t i = 0; i < old_n; ++i) {
    for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      if (entries_[k].active == 0) continue;
      carried_.push_back({i, entries_[k].wall, entries_[k].slip,
                          extended_.empty() ? ExtendedHistory{} : extended_[k]});
    }
  }

  // A triangle (a mesh facet) lies within the sphere about its centroid through its corners: a
  // centre farther than that sphere's radius plus the reach skips the exact test.
  bounds_.resize(walls.size());
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const Wall& wall = walls[w];
    if (wall.shape != WallShape::triangle) continue;  // other shapes go straight to the exact test
    const Vec3 v = wall.normal.cross(wall.axis_u);
    const Vec3 c1 = wall.length * wall.axis_u;
    const Vec3 c2 = wall.size_u * wall.axis_u + wall.size_v * v;
    const Vec3 centroid = (c1 + c2) / 3.0;
    const double radius = std::max({centroid.norm(), (c1 - centroid).norm(), (c2 - centroid).norm()});
    bounds_[w] = {wall.point + t * wall.velocity + centroid, radius * (1.0 + 1e-12)};
  }
  const auto n = static_cast<std::uint32_t>(spheres.size());
  offsets_.resize(n + 1);
  entries_.clear();
  offsets_[0] = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (still[i] == 0) {
      const Vec3 x(spheres[i].x, spheres[i].y, spheres[i].z);
      for (std::uint32_t w = 0; w < walls.size(); ++w) {
        const Wall& wall = walls[w];
        if (!wall.present(t)) continue;
        const double within = reach(i, w) + skin;
        if (wall.shape == WallShape::triangle && (x - bounds_[w].centre).norm() >= bounds_[w].radius + within) continue;
        if (wall_frame(wall, x, t).distance < within) entries_.push_back({w, 0, Vec3::Zero()});
      }
    }
    offsets_[i + 1] = static_cast<std::uint32_t>(entries_.size());
  }
  if (extended_history) {
    extended_.assign(entries_.size(), ExtendedHistory{});
  } else {
    extended_.clear();
  }

  if (old_n != n || (!new_of_old.empty() && new_of_old.size() != n)) return;
  for (const Carried& c : carried_) {
    const std::uint32_t i = new_of_old.empty() ? c.sphere : new_of_old[c.sphere];
    const std::int64_t k = find(i, c.wall);
    if (k < 0) continue;  // out of reach now: its history would reset anyway
    entries_[static_cast<std::size_t>(k)].active = 1;
    entries_[static_cast<std::size_t>(k)].slip = c.slip;
    if (!extended_.empty()) extended_[static_cast<std::size_t>(k)] = c.extended;
  }
}

std::int64_t WallList::find(std::uint32_t i, std::uint32_t w) const noexcept {
  if (i + 1 >= offsets_.size()) return -1;
  for (std::uint32_t k = offsets_[i]; k < offsets_[i + 1]; ++k) {
    if (entries_[k].wall == w) return k;
  }
  return -1;
}

ContactHistory WallList::history(std::size_t k) const noexcept {
  if (entries_[k].active == 0) return {};
  return history_of(entries_[k].slip, extended_.empty() ? nullptr : &extended_[k]);
}

std::size_t WallList::bytes() const noexcept {
  return offsets_.capacity() * sizeof(std::uint32_t) + entries_.capacity() * sizeof(WallEntry) +
         extended_.capacity() * sizeof(ExtendedHistory) + carried_.capacity() * sizeof(Carried) +
         bounds_.capacity() * sizeof(Bounds);
}

}  // namespace dem
