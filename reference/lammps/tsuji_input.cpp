// SPDX-License-Identifier: MIT
#include "reference/lammps/tsuji_input.hpp"

#include "dem/contact/laws/nonlinear_dashpots.hpp"

namespace reference::lammps {

std::optional<double> tsuji_input_for_factor(double factor) {
  double low = 0.0;   // α_L(low) ≥ factor
  double high = 1.0;  // α_L(high) ≤ factor
  if (!(dem::laws::lammps_tsuji_factor(low) >= factor) ||
      !(dem::laws::lammps_tsuji_factor(high) <= factor)) {
    return std::nullopt;
  }
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

}  // namespace reference::lammps
