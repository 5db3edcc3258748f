// SPDX-License-Identifier: MIT
#include "dem/contact/laws/jkr.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include <boost/math/tools/toms748_solve.hpp>

namespace dem::laws {

double jkr_contact_radius(double overlap, const JkrParameters& p) noexcept {
  // Dimensionless form: with y = √(a/a_c) eq 3.35 reads g(y) = y⁴ − 4y − D = 0, D = δR*/a_c²,
  // and g is increasing on the stable branch y ≥ 1, with g(1) = −3 − D ≤ 0 whenever δ ≥ δ_c.
  const double a_c = jkr_critical_radius(p);
  const double target = overlap * p.reduced_radius / (a_c * a_c);
  const auto g = [target](double y) { return y * y * y * y - 4.0 * y - target; };
  double lo = 1.0;
  if (!(g(lo) < 0.0)) return a_c;  // at (or, by rounding, just below) the rupture point
  double hi = std::max(2.0, std::sqrt(std::sqrt(2.0 * std::abs(target))));
  while (!(g(hi) > 0.0) && hi < 1e300) hi *= 2.0;  // y ≥ 2 and y⁴ ≥ 2D guarantee g > 0
  if (!(g(hi) > 0.0)) return a_c * hi * hi;          // not finite input: no bracket
  try {
    std::uintmax_t iterations = 200;
    const auto bracket = boost::math::tools::toms748_solve(
        g, lo, hi, boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits - 2),
        iterations);
    lo = bracket.first;
    hi = bracket.second;
  } catch (...) {
    return a_c * lo * lo;  // unreachable with a valid bracket; keeps the hot loop noexcept
  }
  const double y = 0.5 * (lo + hi);
  return a_c * y * y;
}

}  // namespace dem::laws
