// SPDX-License-Identifier: MIT
#include "dem/neighbors/slab_partition.hpp"

#include <algorithm>
#include <cmath>

namespace dem {

void SlabPartition::assign(std::span<const PackedSphere> spheres, const Vec3& lo, const Vec3& hi,
                           const PeriodicBox& box, double min_width) {
  int axis = 0;
  double best = -1.0;
  for (int k = 0; k < 3; ++k) {
    const double extent = box.periodic[k] ? box.hi[k] - box.lo[k] : hi[k] - lo[k];
    if (extent > best) {
      best = extent;
      axis = k;
    }
  }
  const bool ring = box.periodic[axis];
  const double origin = ring ? box.lo[axis] : lo[axis];
  double slabs = min_width > 0.0 ? std::floor(best / min_width) : 1.0;
  if (!(slabs >= 1.0)) slabs = 1.0;
  // Never more slabs than spheres: a sphere flung far off would otherwise stretch the extent into
  // tens of thousands of empty slabs that every step walks (a fuzz input at 1e8 m/s spent a
  // second on them in 174 steps).
  slabs = std::min({slabs, 65536.0, std::max(1.0, static_cast<double>(spheres.size()))});
  auto count = static_cast<std::uint32_t>(slabs);
  if (ring) {
    count -= count % 2;  // a ring of slabs needs an even count to alternate colours
    if (count < 4) count = 1;
  } else if (count < 2) {
    count = 1;
  }
  count_ = count;
  ring_ = ring && count_ > 1;
  const double width = best / count_;

  const auto n = static_cast<std::uint32_t>(spheres.size());
  slab_of_.resize(n);
  start_.assign(count_ + 1, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    const double x = axis == 0 ? spheres[i].x : (axis == 1 ? spheres[i].y : spheres[i].z);
    const double f = count_ == 1 ? 0.0 : std::floor((x - origin) / width);
    const std::uint32_t s = !(f >= 0.0) ? 0 : (f >= count_ ? count_ - 1 : static_cast<std::uint32_t>(f));
    slab_of_[i] = s;
    ++start_[s + 1];
  }
  for (std::uint32_t s = 0; s < count_; ++s) start_[s + 1] += start_[s];
  members_.resize(n);
  cursor_.assign(start_.begin(), start_.end() - 1);
  for (std::uint32_t i = 0; i < n; ++i) members_[cursor_[slab_of_[i]]++] = i;
}

}  // namespace dem
