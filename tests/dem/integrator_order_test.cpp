// SPDX-License-Identifier: MIT
// Every scheme's convergence order on a harmonic oscillator x'' = −ω² x, whose exact solution
// is known; the scheme registry drives the parameterisation.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "dem/integrators/scheme.hpp"

namespace integrator_order_test {

constexpr double kOmega = 3.0;     // rad/s
constexpr double kAmplitude = 0.5; // m
constexpr double kPhase = 0.7;     // rad: a(0) ≠ 0, so start-up errors are not hidden

/// A force model with a closed-form trajectory: one particle on a linear spring along x, and a
/// torque-free spin so orientations are exercised too.
class Oscillator final : public dem::ForceEvaluator {
 public:
  void trial(const dem::KinematicState& s, double, dem::Accelerations& out) override { eval(s, out); }
  void commit(const dem::KinematicState& s, double, dem::Accelerations& out) override { eval(s, out); }
  int commits = 0;

 private:
  void eval(const dem::KinematicState& s, dem::Accelerations& out) {
    out.linear = -kOmega * kOmega * s.position;
    out.angular = dem::Vec3Array::Zero(3, s.angular_velocity.cols());
  }
};

double exact_x(double t) { return kAmplitude * std::sin(kOmega * t + kPhase); }
double exact_u(double t) { return kAmplitude * kOmega * std::cos(kOmega * t + kPhase); }

dem::KinematicState state_at(double t) {
  dem::KinematicState s;
  s.position = dem::Vec3Array::Zero(3, 1);
  s.velocity = dem::Vec3Array::Zero(3, 1);
  s.angular_velocity = dem::Vec3Array::Zero(3, 1);
  s.angular_velocity(2, 0) = 1.0;
  s.orientation.assign(1, dem::Quat::Identity());
  s.position(0, 0) = exact_x(t);
  s.velocity(0, 0) = exact_u(t);
  return s;
}

/// Position error at t = 1 s after integrating with n steps.
double position_error(dem::SchemeId id, dem::StartupPolicy startup, int n) {
  dem::SchemeSettings settings;
  settings.startup = startup;
  settings.length_scale = kAmplitude;
  const auto scheme = dem::make_scheme(id, settings);
  Oscillator f;
  const double dt = 1.0 / n;
  dem::KinematicState s = state_at(0.0);
  if (startup == dem::StartupPolicy::exact) {
    std::vector<dem::KinematicState> past;
    for (std::size_t k = 1; k <= scheme->past_states_needed(); ++k) past.push_back(state_at(-static_cast<double>(k) * dt));
    scheme->set_past(past, f, dt);
  }
  dem::Accelerations acc;
  f.commit(s, 0.0, acc);
  for (int i = 0; i < n; ++i) scheme->step(s, acc, dt, f);
  return std::abs(s.position(0, 0) - exact_x(1.0));
}

/// Expected global order of position on a smooth problem.
int expected_order(dem::SchemeId id) {
  switch (id) {
    case dem::SchemeId::velocity_verlet:
    case dem::SchemeId::leapfrog: return 2;
    default: return dem::scheme_info(id).local_order;
  }
}

class SchemeOrder : public ::testing::TestWithParam<std::tuple<dem::SchemeId, dem::StartupPolicy>> {};

TEST_P(SchemeOrder, ConvergesAtItsLocalOrderOnAHarmonicOscillator) {
  const auto [id, startup] = GetParam();
  const double coarse = position_error(id, startup, 200);
  const double fine = position_error(id, startup, 400);
  const double order = std::log2(coarse / fine);
  const int p = expected_order(id);
  EXPECT_GT(order, p - 0.15) << dem::scheme_info(id).keyword << " errors " << coarse << " " << fine;
  EXPECT_LT(order, p + 0.3) << dem::scheme_info(id).keyword << " errors " << coarse << " " << fine;
}

std::string name_of(const ::testing::TestParamInfo<SchemeOrder::ParamType>& info) {
  const auto [id, startup] = info.param;
  return std::string(dem::scheme_info(id).keyword) +
         (startup == dem::StartupPolicy::exact ? "_exact_start" : "_rk4_start");
}

std::vector<SchemeOrder::ParamType> all_schemes() {
  std::vector<SchemeOrder::ParamType> out;
  for (const auto& info : dem::scheme_infos()) {
    out.emplace_back(info.id, dem::StartupPolicy::rk4);
    if (info.memory_points > 1) out.emplace_back(info.id, dem::StartupPolicy::exact);
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Registry, SchemeOrder, ::testing::ValuesIn(all_schemes()), name_of);

TEST(SchemeRegistry, EverySchemeHasAUniqueKeywordThatParsesBack) {
  for (const auto& info : dem::scheme_infos()) {
    const auto parsed = dem::parse_scheme(info.keyword);
    ASSERT_TRUE(parsed.has_value()) << info.keyword;
    EXPECT_EQ(*parsed, info.id);
  }
  EXPECT_FALSE(dem::parse_scheme("rk3").has_value());
  EXPECT_EQ(dem::thesis_schemes().size(), 9U);
}

TEST(SchemeRotation, OrientationTurnsByTheIntegratedSpin) {
  // Constant spin of 1 rad/s about z for 1 s turns the orientation by 1 rad, for every scheme.
  for (const auto& info : dem::scheme_infos()) {
    dem::SchemeSettings settings;
    settings.length_scale = kAmplitude;
    const auto scheme = dem::make_scheme(info.id, settings);
    Oscillator f;
    dem::KinematicState s = state_at(0.0);
    dem::Accelerations acc;
    f.commit(s, 0.0, acc);
    for (int i = 0; i < 100; ++i) scheme->step(s, acc, 0.01, f);
    const Eigen::AngleAxisd turn(s.orientation[0]);
    EXPECT_NEAR(turn.angle(), 1.0, 1e-12) << info.keyword;
    EXPECT_NEAR(std::abs(turn.axis().z()), 1.0, 1e-12) << info.keyword;
  }
}

TEST(ImplicitSchemes, IterateToTheTolerance) {
  for (const auto id : {dem::SchemeId::bd1, dem::SchemeId::bd2}) {
    dem::SchemeSettings settings;
    settings.length_scale = kAmplitude;
    const auto scheme = dem::make_scheme(id, settings);
    Oscillator f;
    dem::KinematicState s = state_at(0.0);
    dem::Accelerations acc;
    f.commit(s, 0.0, acc);
    for (int i = 0; i < 50; ++i) scheme->step(s, acc, 0.01, f);
    EXPECT_EQ(scheme->diagnostics().unconverged_steps, 0U);
    EXPECT_GT(scheme->diagnostics().implicit_iterations, 50U * 3U);
  }
}

TEST(ImplicitSchemes, ReportStepsThatDoNotConverge) {
  // ωΔt = 3 > 1: the fixed-point iteration diverges and every step must be counted.
  dem::SchemeSettings settings;
  settings.length_scale = kAmplitude;
  settings.implicit_max_iterations = 5;
  const auto scheme = dem::make_scheme(dem::SchemeId::bd1, settings);
  Oscillator f;
  dem::KinematicState s = state_at(0.0);
  dem::Accelerations acc;
  f.commit(s, 0.0, acc);
  for (int i = 0; i < 3; ++i) scheme->step(s, acc, 1.0, f);
  EXPECT_EQ(scheme->diagnostics().unconverged_steps, 3U);
}

}  // namespace
