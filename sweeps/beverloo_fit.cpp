// SPDX-License-Identifier: MIT
#include "sweeps/beverloo_fit.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/line_fit.hpp"

namespace sweeps {

double beverloo_rate(double c, double k, double bulk_density, double g, double orifice, double grain) noexcept {
  const double free = orifice - k * grain;
  if (!(free > 0.0)) return 0.0;
  return c * bulk_density * std::sqrt(g) * std::pow(free, 2.5);
}

std::optional<BeverlooFit> fit_beverloo(std::span<const double> orifice, std::span<const double> rate,
                                        double bulk_density, double g, double grain) {
  const std::size_t n = std::min(orifice.size(), rate.size());
  if (!(bulk_density > 0.0) || !(g > 0.0) || !(grain > 0.0)) return std::nullopt;
  std::vector<double> y(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!(rate[i] > 0.0) || !std::isfinite(orifice[i])) return std::nullopt;
    y[i] = std::pow(rate[i], 0.4);
  }
  const std::optional<support::LineFit> line = support::least_squares_line(orifice.first(n), y);
  if (!line || !(line->slope > 0.0)) return std::nullopt;
  const double a = line->slope;
  BeverlooFit fit;
  fit.c = std::pow(a, 2.5) / (bulk_density * std::sqrt(g));
  fit.k = -line->intercept / (a * grain);
  fit.points = n;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = beverloo_rate(fit.c, fit.k, bulk_density, g, orifice[i], grain);
    fit.largest_misfit = std::max(fit.largest_misfit, std::abs(w / rate[i] - 1.0));
  }
  return fit;
}

}  // namespace sweeps
