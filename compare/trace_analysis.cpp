// SPDX-License-Identifier: MIT
#include "compare/trace_analysis.hpp"

#include <cmath>

namespace comparison {

double zero_crossing(double t0, double y0, double t1, double y1) noexcept {
  if (y1 == y0) return t0;
  return t0 + (0.0 - y0) * (t1 - t0) / (y1 - y0);
}

IntervalSearch first_contact(const std::vector<double>& time, const std::vector<double>& overlap) {
  IntervalSearch out;
  if (overlap.empty()) return out;
  if (overlap.front() > 0.0) {
    out.problem = IntervalProblem::starts_in_contact;
    return out;
  }
  std::size_t k = 1;
  while (k < overlap.size() && overlap[k] <= 0.0) ++k;
  if (k == overlap.size()) return out;  // no_contact
  ContactInterval c{};
  c.last_before = k - 1;
  c.start = zero_crossing(time[k - 1], overlap[k - 1], time[k], overlap[k]);
  while (k < overlap.size() && overlap[k] > 0.0) ++k;
  if (k == overlap.size()) {
    out.problem = IntervalProblem::never_ends;
    return out;
  }
  c.first_after = k;
  c.end = zero_crossing(time[k - 1], overlap[k - 1], time[k], overlap[k]);
  out.interval = c;
  return out;
}

double parabola_vertex_value(double y0, double y1, double y2) noexcept {
  const double curvature = y0 - 2.0 * y1 + y2;
  if (!(curvature < 0.0)) return y1;  // flat or not a maximum: keep the sample
  const double slope = y0 - y2;
  return y1 - slope * slope / (8.0 * curvature);
}

Peak peak(const std::vector<double>& time, const std::vector<double>& y,
          const std::vector<bool>& valid, std::size_t first, std::size_t last) {
  static_cast<void>(time);  // uniform sampling is assumed by the three-point vertex formula
  std::size_t best = first;
  for (std::size_t k = first + 1; k <= last; ++k) {
    if (y[k] > y[best]) best = k;
  }
  Peak p{best, y[best], y[best]};
  if (best > 0 && best + 1 < y.size() && valid[best - 1] && valid[best] && valid[best + 1]) {
    p.value = parabola_vertex_value(y[best - 1], y[best], y[best + 1]);
  }
  return p;
}

}  // namespace comparison
