// SPDX-License-Identifier: MIT
// Tsuji's Hertz dashpot made restitution-exact: α(ε) = −√5 ln ε / √(π² + ln² ε), checked against
// an independent integration of the scale-free Hertz–dashpot ODE and through the whole core.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/dashpot_restitution.hpp"
#include "dem/contact/laws/hertz.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "dem/contact/registry.hpp"
#include "normal_hertz_fixture.hpp"

namespace damping_tsuji_test {

using dem::laws::hertz_tsuji_restitution;
using dem::laws::tsuji_factor;

/// Rebound speed of x'' = −x^{3/2} − α x^{1/4} x' from x = 0, x' = 1, by classical RK4 with a
/// fixed step h (the force is taken as zero once x < 0, so x' is then the rebound speed).
/// Written here, independently of the closed form and of the analytic engine.
double rk4_rebound(double alpha, double h) {
  const auto accel = [alpha](double x, double v) {
    const double y = std::max(x, 0.0);
    return -(y * std::sqrt(y) + alpha * std::sqrt(std::sqrt(y)) * v);
  };
  double x = 0.0, v = 1.0;
  for (int n = 0; n < 100'000'000 && x >= 0.0; ++n) {
    const double k1x = v, k1v = accel(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = accel(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = accel(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = accel(x + h * k3x, v + h * k3v);
    x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
  }
  return -v;
}

TEST(TsujiFactor, IsSqrtFiveTimesTheLinearDampingRatio) {
  EXPECT_NEAR(tsuji_factor(0.5), 0.4817692577654, 1e-12);
  for (const double e : {0.1, 0.5, 0.9}) {
    EXPECT_NEAR(tsuji_factor(e), std::sqrt(5.0) / 2.0 * dem::laws::restitution_damping_factor(e), 1e-15);
  }
  EXPECT_EQ(tsuji_factor(1.0), 0.0);
}

TEST(TsujiFactor, ClosedFormRestitutionInvertsIt) {
  for (const double e : {0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1.0}) {
    EXPECT_NEAR(hertz_tsuji_restitution(tsuji_factor(e), false), e, 1e-14) << "ε = " << e;
  }
}

TEST(TsujiFactor, ScaleFreeHertzDashpotOdeReboundsWithTheRequestedRestitution) {
  for (const double e : {0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
    EXPECT_NEAR(rk4_rebound(tsuji_factor(e), 2e-5), e, 1e-6) << "ε = " << e;
  }
}

TEST(TsujiFactor, ClippedContactIsTheClippedLinearOscillator) {
  // With F ≥ 0 the rebound is Schwager–Pöschel's clipped value for ζ = α/√5: 0.5503 for 0.5.
  const double alpha = tsuji_factor(0.5);
  EXPECT_NEAR(hertz_tsuji_restitution(alpha, true), 0.5502831696, 1e-9);
}

TEST(TsujiDamping, CoefficientIsAlphaSqrtMassTimesHertzConstantTimesOverlapToTheQuarter) {
  dem::ModelChoice choice;
  choice.normal = "hertz";
  choice.damping = "tsuji";
  dem::PairProperties p;
  p.effective_modulus = hertz_test::effective_modulus();
  p.restitution = 0.5;
  const dem::PairLaw law = dem::make_pair_law(choice, p);
  const double m = hertz_test::mover_mass(), r = hertz_test::reduced_radius(), delta = 3e-4;
  dem::SphereState a{dem::Vec3(0, 0, 0), dem::Vec3(1, 0, 0), dem::Vec3::Zero(), 0.01, 0.01, 1.0 / m};
  dem::SphereState b{dem::Vec3(0.11 - delta, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), 0.1, 0.1, 0.0};
  const dem::ContactGeometry g = dem::pair_geometry(a, b);
  const double k_n = 4.0 / 3.0 * p.effective_modulus.value() * std::sqrt(r);
  const double eta = tsuji_factor(0.5) * std::sqrt(m * k_n) * std::pow(delta, 0.25);
  const dem::ContactOutcome c = dem::evaluate_contact(law, g, {}, 1e-6);
  const double elastic = dem::laws::hertz_force(p.effective_modulus.value(), r, delta);
  EXPECT_NEAR(c.normal_force, elastic + eta * 1.0, 1e-12 * c.normal_force);
}

TEST(TsujiDamping, RegistryRowTellsLammpsWhichNominalRestitutionToPass) {
  const dem::SubModelInfo* row = dem::find_sub_model(dem::Slot::damping, "tsuji");
  ASSERT_NE(row, nullptr);
  EXPECT_NE(row->lammps.find("0.3666514"), std::string_view::npos);
}

/// Restitution of the Hertz impact measured with LAMMPS (hertz_test::impact) with damping
/// `keyword` through the core.
double core_restitution(dem::SchemeId scheme, double steps, double speed, const std::string& keyword,
                        double restitution, bool clamp = false) {
  const double tc = hertz_test::elastic_duration(speed);
  const double dt = tc / steps;
  dem::Simulation sim(hertz_test::impact(scheme, dt, keyword, [&](dem::SimulationSetup& s) {
    s.materials[0].restitution = restitution;
    s.model.clamp_tensile = clamp;
  }, speed));
  while (sim.time() < 12.0 * dt + 4.0 * tc) sim.step();  // a damped contact outlasts the elastic one
  return -sim.state().velocity(0, 0) / speed;
}

TEST(TsujiCollision, ReboundsWithTheRequestedRestitutionAtAnySpeedThroughTheCore) {
  for (const double e : {0.1, 0.5, 0.9}) {
    for (const double v : {0.1, 1.0, 4.0}) {
      EXPECT_NEAR(core_restitution(dem::SchemeId::rk4, 2000.0, v, "tsuji", e), e, 1e-4)
          << "ε = " << e << " v = " << v;
    }
    EXPECT_NEAR(core_restitution(dem::SchemeId::velocity_verlet, 4000.0, 1.0, "tsuji", e), e, 1e-4)
        << "velocity Verlet, ε = " << e;
  }
}

TEST(RestitutionDampingOnHertz, UsesTheTangentStiffnessAndSoReboundsBelowTheNominalValue) {
  // η = β(ε) √(m* 2E*√(R*δ)) is Tsuji's form with α = β √1.5: a speed-independent rebound
  // exp(−π ζ/√(1−ζ²)), ζ = β √(3/10), 0.4663 for a nominal 0.5.
  const double expected = hertz_tsuji_restitution(dem::laws::restitution_damping_factor(0.5) * std::sqrt(1.5), false);
  EXPECT_NEAR(expected, 0.46626, 1e-5);
  for (const double v : {0.3, 3.0}) {
    EXPECT_NEAR(core_restitution(dem::SchemeId::rk4, 2000.0, v, "restitution", 0.5), expected, 1e-4) << "v = " << v;
  }
}

/// The four δ^{1/4} dashpots (Tsuji's form with α = β√1.5, α(ε), α_L(ε), 2√1.5 β_n(ε)).
double tsuji_family_factor(const std::string& keyword, double e) {
  if (keyword == "restitution") return dem::laws::restitution_damping_factor(e) * std::sqrt(1.5);
  if (keyword == "tsuji") return tsuji_factor(e);
  if (keyword == "lammps_tsuji") return dem::laws::lammps_tsuji_factor(e);
  return 2.0 * std::sqrt(1.5) * dem::laws::thornton_damping_ratio(e);  // yade_mindlin
}

TEST(HertzDeltaQuarterDashpots, ReboundAsTheClosedFormClippedOrNotThroughTheCore) {
  for (const std::string keyword : {"restitution", "tsuji", "lammps_tsuji", "yade_mindlin"}) {
    for (const bool clamp : {false, true}) {
      const double expected = hertz_tsuji_restitution(tsuji_family_factor(keyword, 0.5), clamp);
      EXPECT_NEAR(core_restitution(dem::SchemeId::rk4, 2000.0, 1.0, keyword, 0.5, clamp), expected, 1e-4)
          << keyword << (clamp ? " clamped" : "");
    }
  }
}

}  // namespace
