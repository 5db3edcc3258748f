// SPDX-License-Identifier: MIT
// dem::cube_root against a long-double reference on seeded random arguments over the whole
// normal range, and its fallbacks.
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "dem/core/cube_root.hpp"

namespace cube_root_test {

/// Distance of `value` from the exact cube root of x, in units of the last place of `value`.
double ulps_from_exact(double value, double x) {
  const long double exact = std::cbrt(static_cast<long double>(x));
  const double ulp = std::nextafter(std::abs(value), std::numeric_limits<double>::infinity()) - std::abs(value);
  return static_cast<double>(std::abs(static_cast<long double>(value) - exact) / ulp);
}

TEST(CubeRoot, FaithfulOnSeededRandomNormalArguments) {
  std::mt19937_64 rng(20261203);
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  std::uniform_int_distribution<int> exponent(-1022, 1023);
  double worst = 0.0;
  for (int n = 0; n < 2'000'000; ++n) {
    const double x = std::ldexp(mantissa(rng), exponent(rng));
    const double y = dem::cube_root(x);
    worst = std::max(worst, ulps_from_exact(y, x));
    ASSERT_LT(ulps_from_exact(y, x), 1.0) << "x = " << x;
  }
  EXPECT_GT(worst, 0.0);  // the reference is longer than a double: some distance is expected
}

TEST(CubeRoot, ExactCubesAndPowersOfTwoComeBackWithinAnUlp) {
  for (double k = 1.0; k < 2000.0; k += 1.0) {
    EXPECT_LT(ulps_from_exact(dem::cube_root(k * k * k), k * k * k), 1.0) << k;
  }
  for (int e = -1020; e <= 1020; ++e) {
    const double x = std::ldexp(1.0, e);
    EXPECT_LT(ulps_from_exact(dem::cube_root(x), x), 1.0) << e;
  }
  EXPECT_EQ(dem::cube_root(8.0), 2.0);
  EXPECT_EQ(dem::cube_root(27.0), 3.0);
}

TEST(CubeRoot, ArgumentsOffTheFastPathFollowTheLibrary) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double subnormal = std::numeric_limits<double>::denorm_min() * 12345.0;
  for (double x : {0.0, -0.0, -8.0, -1e-300, subnormal, inf, -inf}) {
    EXPECT_EQ(dem::cube_root(x), std::cbrt(x)) << x;
  }
  EXPECT_TRUE(std::isnan(dem::cube_root(std::numeric_limits<double>::quiet_NaN())));
}

}  // namespace
