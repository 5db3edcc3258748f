// SPDX-License-Identifier: MIT
#include "cases/suggestion.hpp"

#include <array>
#include <string_view>

#include <gtest/gtest.h>

namespace suggestion_test {

constexpr std::array<std::string_view, 3> kWords{"radius", "restitution", "density"};

TEST(Suggestion, EditDistanceCountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(cases::edit_distance("radius", "radius"), 0u);
  EXPECT_EQ(cases::edit_distance("radius", "radiu"), 1u);
  EXPECT_EQ(cases::edit_distance("radius", "radiuss"), 1u);
  EXPECT_EQ(cases::edit_distance("radius", "rodius"), 1u);
  EXPECT_EQ(cases::edit_distance("", "abc"), 3u);
}

TEST(Suggestion, SwapOfNeighbouringLettersCostsOneEdit) {
  EXPECT_EQ(cases::edit_distance("restitutoin", "restitution"), 1u);
  EXPECT_EQ(cases::edit_distance("raduis", "radius"), 1u);
}

TEST(Suggestion, SuggestsOnlyWithinTwoEdits) {
  EXPECT_EQ(cases::closest_match("densty", kWords), std::optional<std::string_view>("density"));
  EXPECT_FALSE(cases::closest_match("velocity", kWords).has_value());
  EXPECT_EQ(cases::did_you_mean("raduis", kWords), "; did you mean 'radius'?");
  EXPECT_EQ(cases::did_you_mean("gravity", kWords), "");
}

TEST(Suggestion, JoinSeparatesWithCommas) {
  EXPECT_EQ(cases::join(kWords), "radius, restitution, density");
}

}  // namespace
