// SPDX-License-Identifier: MIT
#include "dem/contact/laws/jkr.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <limits>

namespace dem::laws {

namespace {

/// Grid of the start table: s = √(D + 3) from 0 to 8 in steps of 1/32 (D up to 61, a ≈ 8.4 a_c;
/// beyond it a bound starts the solve).
constexpr std::size_t kJkrStartSize = 257;
constexpr double kJkrStartStep = 8.0 / static_cast<double>(kJkrStartSize - 1);

/// t(s) and dt/ds at one grid point.
struct JkrStartNode {
  double t;      ///< root of 6t² + 4t³ + t⁴ = s²
  double slope;  ///< dt/ds = 2s / (12t + 12t² + 4t³)
};

/// t(s), the root of 6t² + 4t³ + t⁴ = s² (y = 1 + t solves eq 3.35 for D = s² − 3), and its
/// slope on the grid, computed by the compiler: Newton's method from the upper bound t = s,
/// until a step no longer lowers t. Cubic Hermite interpolation in s (smooth, unlike D near the
/// rupture point) then starts a(δ) within ~1e-9 of its root.
constexpr std::array<JkrStartNode, kJkrStartSize> jkr_start_table() {
  std::array<JkrStartNode, kJkrStartSize> table{};
  table[0] = {0.0, 1.0 / 2.449489742783178};  // t ≈ s/√6 at the rupture point
  for (std::size_t i = 1; i < kJkrStartSize; ++i) {
    const double s = static_cast<double>(i) * kJkrStartStep;
    double t = s;
    for (int k = 0; k < 200; ++k) {
      const double h = t * t * (6.0 + t * (4.0 + t)) - s * s;
      const double slope = t * (12.0 + t * (12.0 + 4.0 * t));
      const double next = t - h / slope;
      if (!(next < t)) break;
      t = next;
    }
    table[i] = {t, 2.0 * s / (t * (12.0 + t * (12.0 + 4.0 * t)))};
  }
  return table;
}

/// The start table itself (immutable, built at compile time).
constexpr std::array<JkrStartNode, kJkrStartSize> kJkrStartTable = jkr_start_table();

}  // namespace

double jkr_contact_radius(double overlap, const JkrParameters& p) noexcept {
  const double a_c = jkr_critical_radius(p);
  const double y = jkr_radius_ratio(overlap, p, a_c);
  return a_c * y * y;
}

double jkr_radius_ratio(double overlap, const JkrParameters& p, double critical_radius) noexcept {
  // Dimensionless form: with y = √(a/a_c) eq 3.35 reads g(y) = y⁴ − 4y − D = 0, D = δR*/a_c²,
  // and g is increasing on the stable branch y ≥ 1, with g(1) = −3 − D ≤ 0 whenever δ ≥ δ_c.
  // With y = 1 + t it reads 6t² + 4t³ + t⁴ = c, c = D + 3 ≥ 0.
  const double target = overlap * p.reduced_radius / (critical_radius * critical_radius);
  const auto g = [target](double y) { return y * y * y * y - 4.0 * y - target; };
  const auto newton = [&g](double y) { return y - g(y) / (4.0 * (y * y * y - 1.0)); };
  const double c = target + 3.0;
  if (!(c > 0.0)) return 1.0;  // at (or, by rounding, just below) the rupture point
  const double lo = 1.0;
  const double s = std::sqrt(c);
  const double x = s * (1.0 / kJkrStartStep);
  double y = 0.0;
  if (x >= 1.0 && x < static_cast<double>(kJkrStartTable.size() - 1)) {
    // Cubic Hermite start, within ~1e-9 of the root; one Newton step from any y > 1 lands at or
    // above the root (g is convex), at rounding distance from it.
    const auto i = static_cast<std::size_t>(x);
    const double f = x - static_cast<double>(i);
    const JkrStartNode& n0 = kJkrStartTable[i];
    const JkrStartNode& n1 = kJkrStartTable[i + 1];
    const double f2 = f * f;
    const double f3 = f2 * f;
    const double t = (2.0 * f3 - 3.0 * f2 + 1.0) * n0.t + (f3 - 2.0 * f2 + f) * kJkrStartStep * n0.slope +
                     (3.0 * f2 - 2.0 * f3) * n1.t + (f3 - f2) * kJkrStartStep * n1.slope;
    y = std::max(newton(lo + t), lo);
  } else if (x < 1.0) {
    y = lo + s / std::sqrt(6.0);  // 6t² = c alone: an upper bound, tight near the rupture point
  } else {
    y = std::sqrt(std::sqrt(2.0 * target));  // y⁴ = 2D: an upper bound once D ≥ 8 (here D > 60)
    if (!std::isfinite(y)) return y;  // not finite input
  }
  // Newton's method from above: g is increasing and convex on y ≥ 1 (g' = 4y³ − 4, g'' = 12y²),
  // so from a point with g ≥ 0 every iterate stays at or above the root and falls towards it,
  // quadratically (linearly only at the rupture point, where g' vanishes). Iterating until a
  // step no longer lowers y reaches the root to rounding, with no tolerance to choose.
  for (int k = 0; k < 200; ++k) {
    const double next = newton(y);
    if (!(next < y)) break;
    y = std::max(next, lo);
  }
  return y;
}

}  // namespace dem::laws
