// SPDX-License-Identifier: MIT
#include "sweeps/beverloo_fit.hpp"

#include <algorithm>
#include <cmath>

namespace sweeps {

double beverloo_rate(double c, double k, double bulk_density, double g, double orifice, double grain) noexcept {
  const double free = orifice - k * grain;
  if (!(free > 0.0)) return 0.0;
  return c * bulk_density * std::sqrt(g) * std::pow(free, 2.5);
}

std::optional<BeverlooFit> fit_beverloo(std::span<const double> orifice, std::span<const double> rate,
                                        double bulk_density, double g, double grain) {
  const std::size_t n = std::min(orifice.size(), rate.size());
  if (n < 2 || !(bulk_density > 0.0) || !(g > 0.0) || !(grain > 0.0)) return std::nullopt;
  double x_mean = 0.0;
  double y_mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(rate[i] > 0.0) || !std::isfinite(orifice[i])) return std::nullopt;
    x_mean += orifice[i];
    y_mean += std::pow(rate[i], 0.4);
  }
  x_mean /= static_cast<double>(n);
  y_mean /= static_cast<double>(n);
  double sxx = 0.0;
  double sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (orifice[i] - x_mean) * (orifice[i] - x_mean);
    sxy += (orifice[i] - x_mean) * (std::pow(rate[i], 0.4) - y_mean);
  }
  if (!(sxx > 0.0)) return std::nullopt;
  const double a = sxy / sxx;
  if (!(a > 0.0)) return std::nullopt;
  const double b = y_mean - a * x_mean;
  BeverlooFit fit;
  fit.c = std::pow(a, 2.5) / (bulk_density * std::sqrt(g));
  fit.k = -b / (a * grain);
  fit.points = n;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = beverloo_rate(fit.c, fit.k, bulk_density, g, orifice[i], grain);
    fit.largest_misfit = std::max(fit.largest_misfit, std::abs(w / rate[i] - 1.0));
  }
  return fit;
}

}  // namespace sweeps
