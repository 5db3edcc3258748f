// SPDX-License-Identifier: MIT
#include "reference/lammps/tsuji_input.hpp"

#include <cmath>

#include "dem/contact/laws/nonlinear_dashpots.hpp"

namespace reference::lammps {
namespace {

/// Bisection to the last bit for the e in [low, high] where α_L(e) = factor, given
/// α_L(low) ≥ factor ≥ α_L(high) and α_L falling on the interval.
double bisect(double low, double high, double factor) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (low + high);
    if (mid <= low || mid >= high) break;
    if (dem::laws::lammps_tsuji_factor(mid) >= factor) {
      low = mid;
    } else {
      high = mid;
    }
  }
  return 0.5 * (low + high);
}

}  // namespace

double tsuji_input_zero() {
  // α_L(1) = 3e-4 > 0 and α_L'(1) ≈ −0.46: the zero lies within [1, 1.01].
  return bisect(1.0, 1.01, 0.0);
}

std::optional<double> tsuji_input_for_factor(double factor) {
  const double low = kTsujiInputLowest;
  const double high = tsuji_input_zero();
  if (!std::isfinite(factor) || !(dem::laws::lammps_tsuji_factor(low) >= factor) ||
      !(dem::laws::lammps_tsuji_factor(high) <= factor)) {
    return std::nullopt;
  }
  return bisect(low, high, factor);
}

}  // namespace reference::lammps
