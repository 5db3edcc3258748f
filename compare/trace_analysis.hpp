// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

// Pure functions on sampled time series; every metric is built from these.
namespace comparison {

/// A contact found in a sampled overlap series: start and end times located by linear
/// interpolation of the overlap's sign changes, and the rows that bracket them.
struct ContactInterval {
  double start;             ///< time at which the overlap becomes > 0 [s]
  double end;               ///< time at which it returns to ≤ 0 [s]
  std::size_t last_before;  ///< last row with overlap ≤ 0 before the start
  std::size_t first_after;  ///< first row with overlap ≤ 0 after the end
};

/// Why no contact interval could be found.
enum class IntervalProblem { no_contact, starts_in_contact, never_ends };

/// The first contact in (time, overlap), or the problem. A contact is overlap > 0; the series
/// must begin out of contact (overlap ≤ 0 in the first row).
struct IntervalSearch {
  std::optional<ContactInterval> interval;
  IntervalProblem problem = IntervalProblem::no_contact;
};
IntervalSearch first_contact(const std::vector<double>& time, const std::vector<double>& overlap);

/// Time where the straight line through (t0, y0) and (t1, y1) crosses zero.
[[nodiscard]] double zero_crossing(double t0, double y0, double t1, double y1) noexcept;

/// A sampled maximum, refined by the vertex of the parabola through the peak sample and its
/// two neighbours when all three lie inside `valid` (e.g. the same contact).
struct Peak {
  std::size_t row;
  double value;      ///< refined value
  double sampled;    ///< value at the peak sample
};

/// Largest value of `y` over rows [first, last] (inclusive); refinement only where
/// valid[row-1..row+1] are all true. Requires first ≤ last < y.size().
Peak peak(const std::vector<double>& time, const std::vector<double>& y,
          const std::vector<bool>& valid, std::size_t first, std::size_t last);

/// Parabolic vertex value through three equally spaced samples with y1 the largest.
[[nodiscard]] double parabola_vertex_value(double y0, double y1, double y2) noexcept;

}  // namespace comparison
