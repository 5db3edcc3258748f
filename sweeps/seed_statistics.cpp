// SPDX-License-Identifier: MIT
#include "sweeps/seed_statistics.hpp"

#include <cmath>

namespace sweeps {

SeedStatistics seed_statistics(std::span<const double> values) noexcept {
  SeedStatistics s;
  s.count = values.size();
  if (s.count == 0) return s;
  double sum = 0.0;
  for (const double v : values) sum += v;
  s.mean = sum / static_cast<double>(s.count);
  if (s.count < 2) return s;
  double squares = 0.0;
  for (const double v : values) squares += (v - s.mean) * (v - s.mean);
  const double sd = std::sqrt(squares / static_cast<double>(s.count - 1));
  s.standard_error = sd / std::sqrt(static_cast<double>(s.count));
  return s;
}

std::optional<double> separation(const SeedStatistics& a, const SeedStatistics& b) noexcept {
  if (!a.standard_error || !b.standard_error) return std::nullopt;
  const double combined = std::hypot(*a.standard_error, *b.standard_error);
  if (!(combined > 0.0)) return std::nullopt;
  return std::abs(a.mean - b.mean) / combined;
}

}  // namespace sweeps
