// SPDX-License-Identifier: MIT
#include "dem/particles/spatial_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace dem {
namespace {

/// Spreads the low 21 bits of v so that two zero bits follow each.
std::uint64_t spread(std::uint64_t v) noexcept {
  v &= 0x1fffffU;
  v = (v | v << 32U) & 0x1f00000000ffffULL;
  v = (v | v << 16U) & 0x1f0000ff0000ffULL;
  v = (v | v << 8U) & 0x100f00f00f00f00fULL;
  v = (v | v << 4U) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2U) & 0x1249249249249249ULL;
  return v;
}

}  // namespace

std::uint64_t morton_key(std::uint32_t x, std::uint32_t y, std::uint32_t z) noexcept {
  return spread(x) | spread(y) << 1U | spread(z) << 2U;
}

std::vector<std::uint32_t> morton_order(const Vec3Array& position, const PeriodicBox& box, double cell,
                                        std::span<const std::uint32_t> major) {
  const auto n = static_cast<std::size_t>(position.cols());
  Vec3Array wrapped = position;
  for (Eigen::Index i = 0; i < position.cols(); ++i) {
    const auto image = box.image_of(position.col(i));
    for (int k = 0; k < 3; ++k) wrapped(k, i) -= image[k] * (box.hi[k] - box.lo[k]);
  }
  const Vec3 lo = n > 0 ? Vec3(wrapped.rowwise().minCoeff()) : Vec3::Zero();
  constexpr double kLargest = static_cast<double>((1U << 21U) - 1U);
  std::vector<std::uint64_t> key(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t c[3];
    for (int k = 0; k < 3; ++k) {
      const double f = std::floor((wrapped(k, static_cast<Eigen::Index>(i)) - lo[k]) / cell);
      c[k] = !(f >= 0.0) ? 0U : static_cast<std::uint32_t>(std::min(f, kLargest));
    }
    key[i] = morton_key(c[0], c[1], c[2]);
  }
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0U);
  if (major.size() == n) {
    std::stable_sort(order.begin(), order.end(), [&key, major](std::uint32_t a, std::uint32_t b) {
      return major[a] != major[b] ? major[a] < major[b] : key[a] < key[b];
    });
  } else {
    std::stable_sort(order.begin(), order.end(), [&key](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  }
  return order;
}

std::vector<std::uint32_t> inverse_permutation(std::span<const std::uint32_t> order) {
  std::vector<std::uint32_t> inverse(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) inverse[order[k]] = static_cast<std::uint32_t>(k);
  return inverse;
}

}  // namespace dem
