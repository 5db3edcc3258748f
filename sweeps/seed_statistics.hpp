// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>
#include <span>

namespace sweeps {

/// Mean and standard error of one metric over the seeds of a sweep point.
struct SeedStatistics {
  std::size_t count = 0;                  ///< values (runs that gave one)
  double mean = 0.0;                      ///< arithmetic mean (0 when count = 0)
  std::optional<double> standard_error;   ///< s/√n with the sample s.d. (n − 1); empty for n < 2
};

/// Statistics of `values` (each one seed's value), summed in the given order.
SeedStatistics seed_statistics(std::span<const double> values) noexcept;

/// Difference of two ensemble means in units of their combined standard error,
/// |m_a − m_b| / √(se_a² + se_b²); empty when either standard error is missing or both are 0
/// (then the means are compared as they are).
std::optional<double> separation(const SeedStatistics& a, const SeedStatistics& b) noexcept;

}  // namespace sweeps
