// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

namespace bench {

/// Median of a non-empty list (the mean of the middle two when the count is even): what a bench
/// reports of repeated, noisy measurements.
[[nodiscard]] inline double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

/// Median over a non-empty list of `items` of one figure of each (`figure(item)`, a double).
template <class Items, class Figure>
[[nodiscard]] double median_by(const Items& items, Figure figure) {
  std::vector<double> v;
  v.reserve(items.size());
  for (const auto& item : items) v.push_back(figure(item));
  return median_of(std::move(v));
}

}  // namespace bench
