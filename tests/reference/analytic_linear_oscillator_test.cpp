// SPDX-License-Identifier: MIT
// The closed form of one regime, m y'' + C y' + K y = 0, in every damping class.
#include <cmath>
#include <algorithm>
#include <limits>
#include <string>
#include <numbers>

#include <gtest/gtest.h>

#include "reference/analytic/linear_oscillator.hpp"

namespace analytic_linear_oscillator_test {

using reference::analytic::LinearOscillator;

constexpr double kMass = 2.0;
constexpr double kStiffness = 50.0;  // ω = 5 rad/s
constexpr double kY0 = 0.3;
constexpr double kV0 = -1.7;

struct Case {
  const char* name;
  double damping;
};

class AnalyticLinearOscillator : public ::testing::TestWithParam<Case> {};

TEST_P(AnalyticLinearOscillator, StartsFromTheInitialState) {
  const LinearOscillator o(kMass, GetParam().damping, kStiffness, kY0, kV0);
  EXPECT_DOUBLE_EQ(o.at(0.0).position, kY0);
  EXPECT_DOUBLE_EQ(o.at(0.0).velocity, kV0);
}

TEST_P(AnalyticLinearOscillator, SatisfiesTheEquationOfMotionForwardsAndBackwards) {
  const double c = GetParam().damping;
  const LinearOscillator o(kMass, c, kStiffness, kY0, kV0);
  const double h = 1e-5;
  for (const double tau : {-0.7, -0.05, 0.02, 0.4, 1.3}) {
    const auto k = o.at(tau);
    const double velocity = (o.at(tau + h).position - o.at(tau - h).position) / (2 * h);
    const double acceleration =
        (o.at(tau + h).position - 2 * k.position + o.at(tau - h).position) / (h * h);
    const double scale = std::abs(k.velocity) + std::abs(k.position) * 5.0 + 1e-3;
    EXPECT_NEAR(velocity, k.velocity, 1e-8 * scale) << "τ = " << tau;
    EXPECT_NEAR(acceleration, k.acceleration, 1e-4 * scale * 5.0) << "τ = " << tau;
    EXPECT_NEAR(kMass * k.acceleration + c * k.velocity + kStiffness * k.position, 0.0,
                1e-12 * kStiffness * scale);
  }
}

TEST_P(AnalyticLinearOscillator, StaysFiniteFarFromTheStart) {
  const LinearOscillator o(kMass, GetParam().damping, kStiffness, kY0, kV0);
  EXPECT_TRUE(std::isfinite(o.at(-5.0).position));  // grows backwards, at most e^{12.5·5}
  for (const double tau : {1e3, 1e6}) {
    EXPECT_TRUE(std::isfinite(o.at(tau).position));
    if (GetParam().damping > 0.0) {
      EXPECT_NEAR(o.at(tau).position, 0.0, 1e-12);
    }
  }
}

// ω = 5, so C = 2 m ω = 20 is critical.
INSTANTIATE_TEST_SUITE_P(DampingClasses, AnalyticLinearOscillator,
                         ::testing::Values(Case{"undamped", 0.0}, Case{"underdamped", 6.0},
                                           Case{"critical", 20.0}, Case{"overdamped", 29.0},
                                           Case{"nearly_critical_over", 20.0 * (1 + 1e-12)},
                                           Case{"nearly_critical_under", 20.0 * (1 - 1e-12)}),
                         [](const ::testing::TestParamInfo<Case>& p) {
                           return std::string(p.param.name);
                         });

TEST(AnalyticLinearOscillatorClosedForms, UndampedIsCosinePlusSine) {
  const LinearOscillator o(kMass, 0.0, kStiffness, kY0, kV0);
  const double w = 5.0;
  for (const double tau : {-1.1, 0.3, 2.9}) {
    EXPECT_NEAR(o.at(tau).position, kY0 * std::cos(w * tau) + kV0 / w * std::sin(w * tau), 1e-15);
  }
  EXPECT_NEAR(o.natural_period(), 2 * std::numbers::pi / w, 1e-15);
}

TEST(AnalyticLinearOscillatorClosedForms, CriticalIsLinearTimesExponential) {
  const LinearOscillator o(kMass, 20.0, kStiffness, kY0, kV0);
  for (const double tau : {-0.4, 0.3, 2.9}) {
    EXPECT_NEAR(o.at(tau).position, (kY0 + (kV0 + 5.0 * kY0) * tau) * std::exp(-5.0 * tau),
                1e-15);
  }
}

TEST(AnalyticLinearOscillatorClosedForms, OverdampedIsTwoExponentials) {
  const double c = 26.0;  // γ = 6.5, μ = √(6.5² − 25) = √17.25
  const LinearOscillator o(kMass, c, kStiffness, kY0, kV0);
  const double mu = std::sqrt(17.25);
  const double l1 = -6.5 + mu;
  const double l2 = -6.5 - mu;
  const double c1 = (kV0 - l2 * kY0) / (l1 - l2);
  const double c2 = kY0 - c1;
  for (const double tau : {-0.4, 0.3, 2.9}) {
    EXPECT_NEAR(o.at(tau).position, c1 * std::exp(l1 * tau) + c2 * std::exp(l2 * tau),
                1e-14 * std::max(1.0, std::abs(o.at(tau).position)));
  }
}

TEST(AnalyticLinearOscillatorClosedForms, FreeFlightIsUniform) {
  const LinearOscillator o(kMass, 0.0, 0.0, kY0, kV0);
  EXPECT_TRUE(o.free());
  EXPECT_EQ(o.at(2.0).position, kY0 + 2.0 * kV0);
  EXPECT_EQ(o.at(2.0).acceleration, 0.0);
  EXPECT_EQ(o.natural_period(), std::numeric_limits<double>::infinity());
}

}  // namespace
