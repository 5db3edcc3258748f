// SPDX-License-Identifier: MIT
// The analytic engine's Hertz building blocks: the closed-form elastic contact (inverse
// incomplete beta) and the high-accuracy contact ODE, against each other and against closed
// forms (linear dashpot, restitution-exact Tsuji, clipped dashpot, weak Kuwabara–Kono damping).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "dem/contact/laws/dashpot_restitution.hpp"
#include "dem/contact/laws/hertz.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "reference/analytic/hertz_elastic.hpp"
#include "reference/analytic/two_body_ode.hpp"

namespace analytic_hertz_ode_test {

using reference::analytic::HertzElasticContact;
using reference::analytic::NormalContactProblem;
using reference::analytic::solve_normal_contact;

// The pair of the Hertz impact measured with LAMMPS: m = 4.18879e-3 kg, E* = 5.4945e6 Pa,
// R* = 9.0909e-3 m.
const double kMass = 4.0 / 3.0 * std::numbers::pi * 1000.0 * 1e-6;
constexpr double kModulus = 1e7 / (2.0 * 0.91);
constexpr double kRadius = 0.01 * 0.1 / 0.11;
constexpr double kHertz = 4.0 / 3.0 * kModulus;  // k_n / √R*

/// Hertz with Tsuji's dashpot of factor α, optionally clipped at F ≥ 0.
NormalContactProblem hertz_tsuji(double alpha, double speed, bool clamp = false) {
  NormalContactProblem p;
  p.reduced_mass = kMass;
  p.approach_speed = speed;
  p.length_scale = dem::laws::hertz_max_overlap(kMass, kModulus, kRadius, speed);
  const double k_n = kHertz * std::sqrt(kRadius);
  p.force = [=](double d, double rate) {
    const double f = k_n * d * std::sqrt(d) + alpha * std::sqrt(kMass * k_n) * std::sqrt(std::sqrt(d)) * rate;
    return clamp ? std::max(f, 0.0) : f;
  };
  return p;
}

TEST(HertzElasticContact, DurationAndPeakAreTheClosedForms) {
  const HertzElasticContact c(kMass, kModulus, kRadius, 1.0);
  EXPECT_NEAR(c.duration(), dem::laws::hertz_contact_duration(kMass, kModulus, kRadius, 1.0), 1e-18);
  EXPECT_NEAR(c.max_overlap(), 5.622520e-4, 1e-10);
  const auto peak = c.at(0.5 * c.duration());
  EXPECT_NEAR(peak.overlap, c.max_overlap(), 1e-15);
  EXPECT_NEAR(peak.overlap_rate, 0.0, 1e-15);
  EXPECT_EQ(c.at(0.0).overlap, 0.0);
  EXPECT_NEAR(c.at(c.duration()).overlap_rate, -1.0, 1e-15);
}

TEST(HertzElasticContact, ConservesEnergyAndIsSymmetricAboutItsMiddle) {
  const double v = 2.0;
  const HertzElasticContact c(kMass, kModulus, kRadius, v);
  for (int k = 1; k < 40; ++k) {
    const double t = c.duration() * k / 40.0;
    const auto s = c.at(t);
    const double energy = 0.5 * kMass * s.overlap_rate * s.overlap_rate +
                          dem::laws::hertz_energy(kModulus, kRadius, s.overlap);
    EXPECT_NEAR(energy, 0.5 * kMass * v * v, 1e-13 * kMass * v * v) << "t = " << t;
    const auto mirror = c.at(c.duration() - t);
    EXPECT_NEAR(mirror.overlap, s.overlap, 1e-15);
    EXPECT_NEAR(mirror.overlap_rate, -s.overlap_rate, 1e-12);
  }
}

TEST(NormalContactOde, ReproducesTheElasticClosedFormTo1em10) {
  const double v = 1.0;
  const HertzElasticContact c(kMass, kModulus, kRadius, v);
  std::vector<double> times;
  for (int k = 0; k <= 100; ++k) times.push_back(c.duration() * k / 100.0);
  const auto s = solve_normal_contact(hertz_tsuji(0.0, v), times);
  EXPECT_NEAR(s.duration, c.duration(), 1e-10 * c.duration());
  EXPECT_NEAR(s.exit_rate, -v, 1e-10);
  EXPECT_NEAR(s.deepest.overlap, c.max_overlap(), 1e-10 * c.max_overlap());
  EXPECT_NEAR(s.strongest.force, c.max_force(), 1e-10 * c.max_force());
  ASSERT_GE(s.samples.size(), 100U);
  for (std::size_t k = 0; k < 100; ++k) {
    EXPECT_NEAR(s.samples[k].overlap, c.at(times[k]).overlap, 1e-10 * c.max_overlap()) << k;
    EXPECT_NEAR(s.samples[k].overlap_rate, c.at(times[k]).overlap_rate, 1e-9 * v) << k;
  }
}

TEST(NormalContactOde, ReproducesTheLinearSpringDashpotClosedForms) {
  // m δ'' + η δ' + k δ = 0 (eq 3.10–3.11, 3.40): table 4.2 with ε = 0.3.
  const double k = 1e5, eta = dem::laws::restitution_damping_coefficient(0.3, kMass, k);
  NormalContactProblem p;
  p.reduced_mass = kMass;
  p.approach_speed = 4.0;
  p.length_scale = 4.0 * std::sqrt(kMass / k);
  p.force = [=](double d, double rate) { return k * d + eta * rate; };
  const auto s = solve_normal_contact(p, {});
  const double tc = dem::laws::linear_contact_duration(k, kMass, eta);
  EXPECT_NEAR(s.duration, tc, 1e-10 * tc);
  EXPECT_NEAR(-s.exit_rate / 4.0, 0.3, 1e-10);
}

TEST(NormalContactOde, TsujiFactorGivesTheRequestedRestitutionTo1em9) {
  for (const double e : {0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
    for (const double v : {0.1, 3.0}) {
      const auto s = solve_normal_contact(hertz_tsuji(dem::laws::tsuji_factor(e), v), {});
      EXPECT_NEAR(-s.exit_rate / v, e, 1e-9) << "ε = " << e << " v = " << v;
    }
  }
}

TEST(NormalContactOde, ClippedTsujiIsTheClippedLinearOscillator) {
  for (const double alpha : {0.2, 1.0, 2.7785}) {  // 2.7785: YADE's β_n(0.1), overdamped
    const auto s = solve_normal_contact(hertz_tsuji(alpha, 1.0, true), {});
    EXPECT_NEAR(-s.exit_rate, dem::laws::hertz_tsuji_restitution(alpha, true), 1e-9) << "α = " << alpha;
  }
}

TEST(NormalContactOde, LammpsTsujiPolynomialReboundsAtPointSixOneSix) {
  const auto s = solve_normal_contact(hertz_tsuji(dem::laws::lammps_tsuji_factor(0.5), 1.0), {});
  EXPECT_NEAR(-s.exit_rate, 0.6160760, 1e-7);  // exact ODE 0.61608, measured LAMMPS 0.616090
}

TEST(NormalContactOde, SamplesAreReturnedInTimeOrderAndOnlyWithinTheContact) {
  const HertzElasticContact c(kMass, kModulus, kRadius, 1.0);
  const std::vector<double> times{0.7 * c.duration(), -1.0, 0.2 * c.duration(), 2.0 * c.duration()};
  const auto s = solve_normal_contact(hertz_tsuji(0.3, 1.0), times);
  ASSERT_EQ(s.samples.size(), 2U);
  EXPECT_LT(s.samples[0].time, s.samples[1].time);
  EXPECT_NEAR(s.samples[0].time, 0.2 * c.duration(), 1e-18);
}

TEST(NormalContactOde, OverdampedContactThatNeverEndsIsReported) {
  // Unclipped Tsuji with ζ = α/√5 > 1 creeps back towards δ = 0 without reaching it.
  EXPECT_THROW(static_cast<void>(solve_normal_contact(hertz_tsuji(3.0, 1.0), {})), std::runtime_error);
}

}  // namespace
