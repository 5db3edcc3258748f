// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>
#include <span>

namespace support {

/// A straight line y = slope·x + intercept fitted by least squares to `points` samples.
struct LineFit {
  double slope = 0.0;
  double intercept = 0.0;
  std::size_t points = 0;
};

/// The least-squares line through (x_i, y_i), slope = Σ(x − x̄)(y − ȳ) / Σ(x − x̄)²; empty with
/// fewer than two samples or when every x is the same.
[[nodiscard]] inline std::optional<LineFit> least_squares_line(std::span<const double> x,
                                                               std::span<const double> y) noexcept {
  const std::size_t n = x.size() < y.size() ? x.size() : y.size();
  if (n < 2) return std::nullopt;
  double x_mean = 0.0;
  double y_mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    x_mean += x[i];
    y_mean += y[i];
  }
  x_mean /= static_cast<double>(n);
  y_mean /= static_cast<double>(n);
  double sxx = 0.0;
  double sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - x_mean) * (x[i] - x_mean);
    sxy += (x[i] - x_mean) * (y[i] - y_mean);
  }
  if (!(sxx > 0.0)) return std::nullopt;
  const double slope = sxy / sxx;
  return LineFit{slope, y_mean - slope * x_mean, n};
}

}  // namespace support
