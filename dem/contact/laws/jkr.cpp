// SPDX-License-Identifier: MIT
#include "dem/contact/laws/jkr.hpp"

#include <algorithm>
#include <limits>

namespace dem::laws {

double jkr_contact_radius(double overlap, const JkrParameters& p) noexcept {
  // Dimensionless form: with y = √(a/a_c) eq 3.35 reads g(y) = y⁴ − 4y − D = 0, D = δR*/a_c²,
  // and g is increasing on the stable branch y ≥ 1, with g(1) = −3 − D ≤ 0 whenever δ ≥ δ_c.
  const double a_c = jkr_critical_radius(p);
  const double target = overlap * p.reduced_radius / (a_c * a_c);
  const auto g = [target](double y) { return y * y * y * y - 4.0 * y - target; };
  const double lo = 1.0;
  if (!(g(lo) < 0.0)) return a_c;  // at (or, by rounding, just below) the rupture point
  double hi = std::max(2.0, std::sqrt(std::sqrt(2.0 * std::abs(target))));
  while (!(g(hi) > 0.0) && hi < 1e300) hi *= 2.0;  // y ≥ 2 and y⁴ ≥ 2D guarantee g > 0
  if (!(g(hi) > 0.0)) return a_c * hi * hi;          // not finite input: no bracket
  // Newton's method from hi: g is increasing and convex on y ≥ 1 (g' = 4y³ − 4, g'' = 12y²), so
  // from a point with g > 0 every iterate stays at or above the root and falls towards it,
  // quadratically (linearly only at the rupture point, where g' vanishes). Iterating until a
  // step no longer lowers y reaches the root to rounding, with no tolerance to choose.
  double y = hi;
  for (int k = 0; k < 200; ++k) {
    const double next = y - g(y) / (4.0 * (y * y * y - 1.0));
    if (!(next < y)) break;
    y = std::max(next, lo);
  }
  return a_c * y * y;
}

}  // namespace dem::laws
