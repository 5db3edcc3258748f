// SPDX-License-Identifier: MIT
// Sampled-series analysis: interpolated contact start/end and refined peaks.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "compare/trace_analysis.hpp"

namespace trace_analysis_test {

using comparison::first_contact;
using comparison::IntervalProblem;

TEST(ZeroCrossing, InterpolatesLinearly) {
  EXPECT_DOUBLE_EQ(comparison::zero_crossing(1.0, -1.0, 2.0, 3.0), 1.25);
}

TEST(FirstContact, LocatesStartAndEndBetweenSamples) {
  // δ(t) = sin(t − 0.3) for t in [0.3, 0.3 + π], −0.1 elsewhere; samples every 0.05.
  std::vector<double> t, d;
  for (int k = 0; k <= 100; ++k) {
    const double tk = 0.05 * k;
    t.push_back(tk);
    d.push_back(tk > 0.3 && tk < 0.3 + std::numbers::pi ? std::sin(tk - 0.3) : -0.1);
  }
  const auto found = first_contact(t, d);
  ASSERT_TRUE(found.interval.has_value());
  EXPECT_NEAR(found.interval->start, 0.3, 0.05);
  EXPECT_NEAR(found.interval->end - found.interval->start, std::numbers::pi, 0.1);
  EXPECT_LE(d[found.interval->last_before], 0.0);
  EXPECT_LE(d[found.interval->first_after], 0.0);
}

TEST(FirstContact, ReportsWhyThereIsNone) {
  const std::vector<double> t{0, 1, 2};
  EXPECT_EQ(first_contact(t, {-1, -1, -1}).problem, IntervalProblem::no_contact);
  EXPECT_EQ(first_contact(t, {1, 1, -1}).problem, IntervalProblem::starts_in_contact);
  EXPECT_EQ(first_contact(t, {-1, 1, 1}).problem, IntervalProblem::never_ends);
}

TEST(FirstContact, ZeroOverlapAtTheFirstSampleIsNotYetContact) {
  const auto found = first_contact({0, 1, 2, 3}, {0.0, 1.0, 1.0, -1.0});
  ASSERT_TRUE(found.interval.has_value());
  EXPECT_DOUBLE_EQ(found.interval->start, 0.0);
  EXPECT_DOUBLE_EQ(found.interval->end, 2.5);
}

TEST(Peak, ParabolicRefinementIsExactForAParabola) {
  std::vector<double> t, y;
  for (int k = 0; k < 10; ++k) {
    t.push_back(k);
    y.push_back(5.0 - (k - 4.3) * (k - 4.3));
  }
  const std::vector<bool> valid(10, true);
  const auto p = comparison::peak(t, y, valid, 0, 9);
  EXPECT_EQ(p.row, 4U);
  EXPECT_NEAR(p.value, 5.0, 1e-12);
  EXPECT_LT(p.sampled, 5.0);
}

TEST(Peak, NoRefinementAcrossInvalidNeighbours) {
  const std::vector<double> t{0, 1, 2}, y{1.0, 3.0, 2.0};
  const auto p = comparison::peak(t, y, {false, true, true}, 0, 2);
  EXPECT_DOUBLE_EQ(p.value, 3.0);
}

}  // namespace
