// SPDX-License-Identifier: MIT
// The JKR law against its closed forms (thesis eq 3.34–3.35; docs/physics-cohesion.md), its
// hysteresis, and the energy of a damped adhesive collision.
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <numbers>
#include <utility>

#include <boost/math/tools/minima.hpp>
#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/hertz.hpp"
#include "dem/contact/laws/jkr.hpp"
#include "dem/contact/laws/nonlinear_dashpots.hpp"
#include "dem/simulation/simulation.hpp"

namespace cohesion_jkr_test {

using namespace dem::laws;
constexpr double kPi = std::numbers::pi;

/// The agglomerate-benchmark JKR pair (thesis table 5.1): E = 8.4e7 Pa, ν = 0.3, r = 5 mm.
JkrParameters benchmark() { return {8.4e7 / (2.0 * (1.0 - 0.09)), 2.5e-3, 121.5}; }
/// A stiff, weakly adhesive pair (a static LAMMPS probe: E = 1e7, ν = 0.3, γ = 0.1, r = 5 mm).
JkrParameters probe() { return {1e7 / (2.0 * (1.0 - 0.09)), 2.5e-3, 0.1}; }

TEST(JkrLaw, ContactRadiusInvertsTheOverlapTo1e10) {
  for (const JkrParameters& p : {benchmark(), probe()}) {
    const double dc = jkr_rupture_overlap(p);
    for (double f = -1.0; f <= 20.0; f += 0.0625) {
      const double delta = f * std::abs(dc);
      if (delta < dc) continue;
      const double a = jkr_contact_radius(delta, p);
      EXPECT_GE(a, jkr_critical_radius(p));
      EXPECT_NEAR(jkr_overlap(a, p), delta, 1e-10 * std::abs(dc)) << "δ = " << delta;
    }
    const double ac = jkr_critical_radius(p);
    for (double s = 1.01; s < 50.0; s *= 1.1) {
      EXPECT_NEAR(jkr_contact_radius(jkr_overlap(s * ac, p), p), s * ac, 1e-10 * s * ac) << s;
    }
  }
}

/// A pair nobody picked: E* over 4 decades (1e6–1e10 Pa), R* over 3 (10 µm–10 mm), γ over 5
/// (1e-3–1e2 J/m²), log-uniform.
JkrParameters random_pair(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double modulus = std::pow(10.0, 6.0 + 4.0 * u(rng));
  const double radius = std::pow(10.0, -5.0 + 3.0 * u(rng));
  return {modulus, radius, std::pow(10.0, -3.0 + 5.0 * u(rng))};
}

/// Calls check(p, a_c, u) for `count` random pairs from `seed`, u a uniform draw in [0, 1) from
/// the same stream.
template <class Check>
void for_random_pairs(std::uint64_t seed, int count, Check check) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int n = 0; n < count; ++n) {
    const JkrParameters p = random_pair(rng);
    check(p, jkr_critical_radius(p), [&] { return uniform(rng); });
  }
}

TEST(JkrLaw, ContactRadiusOnSeededRandomPairsInvertsTheOverlapToRounding) {
  // Pairs nobody picked: E* over 4 decades, R* over 3, γ over 5; overlaps from just above δ_c
  // to 10⁴ |δ_c|. a(δ) must lie on the stable branch and invert eq 3.35 to a few ulps of the
  // larger of its two terms; the radius ratio the contact loop solves gives the same radius.
  for_random_pairs(20261203, 2000, [](const JkrParameters& p, double ac, auto u) {
    const double dc = jkr_rupture_overlap(p);
    const double delta = dc + std::abs(dc) * std::pow(10.0, -8.0 + 12.0 * u());
    const double a = jkr_contact_radius(delta, p);
    const double y = jkr_radius_ratio(delta, p, ac);
    ASSERT_EQ(a, ac * y * y);
    ASSERT_GE(a, ac);
    const double scale = a * a / p.reduced_radius;  // the larger term of eq 3.35 near the root
    EXPECT_NEAR(jkr_overlap(a, p), delta, 64.0 * std::numeric_limits<double>::epsilon() * scale)
        << "E* " << p.effective_modulus << " R* " << p.reduced_radius << " γ " << p.surface_energy
        << " δ " << delta;
  });
}

TEST(JkrLaw, ForceAndEnergyFromTheRadiusRatioEqualTheRadiusForms) {
  // F = πγR*(y⁶/3 − 2y³) and U = πγa_c²(2y¹⁰/15 − 4y⁷/3 + 2y⁴) are eq 3.34 and the energy with
  // a = a_c y², written without a square root: the contact loop's form.
  for_random_pairs(11, 2000, [](const JkrParameters& p, double ac, auto u) {
    const double y = 1.0 + 4.0 * u();
    const double a = ac * y * y;
    const double scale_f = jkr_pulloff_force(p) * std::pow(y, 6);
    EXPECT_NEAR(jkr_force_at_ratio(y, p), jkr_force(a, p), 1e-13 * scale_f);
    const double scale_u = kPi * p.surface_energy * ac * ac * std::pow(y, 10);
    EXPECT_NEAR(jkr_energy_at_ratio(y, ac, p), jkr_energy(a, p), 1e-13 * scale_u);
    const double delta = jkr_overlap(a, p);
    EXPECT_NEAR(jkr_radius_ratio(delta, p, ac), y, 1e-12 * y);
  });
  const JkrParameters p = benchmark();
  EXPECT_NEAR(jkr_force_at_ratio(1.0, p), -5.0 / 9.0 * jkr_pulloff_force(p), 1e-15 * jkr_pulloff_force(p));
  EXPECT_NEAR(jkr_force_at_ratio(std::cbrt(3.0), p), -jkr_pulloff_force(p), 1e-14 * jkr_pulloff_force(p));
}

TEST(JkrLaw, BreakOverlapsFromTheCriticalRadiusEqualTheCubeRootForms) {
  for_random_pairs(7, 1000, [](const JkrParameters& p, double ac, auto) {
    EXPECT_NEAR(jkr_rupture_overlap_at(ac, p), jkr_rupture_overlap(p), 1e-14 * std::abs(jkr_rupture_overlap(p)));
    EXPECT_NEAR(jkr_pulloff_overlap_at(ac, p), jkr_pulloff_overlap(p), 1e-13 * std::abs(jkr_pulloff_overlap(p)));
  });
}

TEST(JkrLaw, StableBranchIsTheLargerRootWhereTensionPeaksAtDeltaF) {
  const JkrParameters p = benchmark();
  const double dc = jkr_rupture_overlap(p), df = jkr_pulloff_overlap(p);
  double previous_force = 0.0;
  for (double f = -0.999; f <= 5.0; f += 0.01) {
    const double delta = f * std::abs(dc);
    const double a = jkr_contact_radius(delta, p);
    const double slope = 2.0 * a / p.reduced_radius -
                         0.5 * std::sqrt(4.0 * kPi * p.surface_energy / (p.effective_modulus * a));
    EXPECT_GT(slope, 0.0) << "dδ/da > 0 on the stable branch, δ = " << delta;
    const double force = jkr_force(a, p);
    if (f > -0.999) {
      // Tension grows from δ_c to δ_f, then the force rises with δ.
      if (delta < df) {
        EXPECT_LT(force, previous_force) << delta;
      }
      if (delta - 0.01 * std::abs(dc) > df) {
        EXPECT_GT(force, previous_force) << delta;
      }
    }
    previous_force = force;
  }
}

TEST(JkrLaw, PullOffIsThreePiGammaR) {
  for (const JkrParameters& p : {benchmark(), probe()}) {
    const double f_po = 3.0 * kPi * p.surface_energy * p.reduced_radius;
    EXPECT_NEAR(jkr_pulloff_force(p), f_po, 1e-15 * f_po);
    // The largest tension of the whole curve, found by Brent's method over a ≥ a_c.
    const double ac = jkr_critical_radius(p);
    const auto [a_min, f_min] = boost::math::tools::brent_find_minima(
        [&](double a) { return jkr_force(a, p); }, ac, 10.0 * ac, 52);
    EXPECT_NEAR(-f_min, f_po, 1e-10 * f_po);
    EXPECT_NEAR(a_min, jkr_pulloff_radius(p), 1e-5 * a_min);  // a flat minimum: √ε in a
    EXPECT_NEAR(jkr_force(jkr_pulloff_radius(p), p), -f_po, 1e-12 * f_po);
  }
}

TEST(JkrLaw, DisplacementControlledRuptureIsAtDeltaCWithFiveNinthsOfPullOff) {
  for (const JkrParameters& p : {benchmark(), probe()}) {
    const double gamma_w = 2.0 * p.surface_energy;  // Γ
    const double r = p.reduced_radius, e = p.effective_modulus;
    const double ac = jkr_critical_radius(p);
    EXPECT_NEAR(std::pow(ac, 3), kPi * gamma_w * r * r / (8.0 * e), 1e-13 * std::pow(ac, 3));
    const double dc = -0.75 * std::cbrt(kPi * kPi * gamma_w * gamma_w * r / (e * e));
    EXPECT_NEAR(jkr_rupture_overlap(p), dc, 1e-14 * std::abs(dc));
    EXPECT_NEAR(jkr_overlap(ac, p), dc, 1e-12 * std::abs(dc));  // δ(a_c) is the minimum of δ(a)
    EXPECT_NEAR(jkr_force(ac, p), -5.0 / 9.0 * jkr_pulloff_force(p), 1e-12 * jkr_pulloff_force(p));
    // δ_c is a fold of δ(a) (dδ/da = 0 at a_c): with y = 1 + t, D + 3 = 6t² + O(t³), so an input
    // δ that carries a few roundings (|D + 3| ≲ 12·2⁻⁵³) moves the root by t ≲ √(2·2⁻⁵³) ≈ 1.5e-8,
    // and the force, dF/dy = −4πγR* at y = 1, by (4/3)F_po·t. The solve at δ_c can be no closer
    // than that; the closed form above holds at a_c itself to 1e-12.
    const double fold = 4.0 / 3.0 * std::sqrt(2.0 * std::numeric_limits<double>::epsilon() / 2.0);
    EXPECT_NEAR(jkr_force(jkr_contact_radius(dc, p), p), -5.0 / 9.0 * jkr_pulloff_force(p),
                2.0 * fold * jkr_pulloff_force(p));
    EXPECT_GE(jkr_contact_radius(dc, p), ac);
  }
}

TEST(JkrLaw, ZeroLoadAndFirstTouchRadii) {
  for (const JkrParameters& p : {benchmark(), probe()}) {
    const double r = p.reduced_radius, e = p.effective_modulus, g = p.surface_energy;
    const double a0 = jkr_zero_load_radius(p);
    EXPECT_NEAR(std::pow(a0, 3), 9.0 * kPi * g * r * r / e, 1e-13 * std::pow(a0, 3));
    EXPECT_NEAR(jkr_force(a0, p), 0.0, 1e-12 * jkr_pulloff_force(p));
    const double touch = jkr_contact_radius(0.0, p);
    EXPECT_NEAR(touch, jkr_touch_radius(p), 1e-12 * touch);
    EXPECT_NEAR(jkr_force(touch, p), -8.0 / 9.0 * jkr_pulloff_force(p), 1e-12 * jkr_pulloff_force(p));
    EXPECT_NEAR(jkr_pulloff_overlap(p) / jkr_rupture_overlap(p),
                (4.0 * std::pow(9.0, 1.0 / 6.0) - std::pow(9.0, 2.0 / 3.0)) / 3.0, 1e-12);
  }
}

TEST(JkrLaw, EnergyIsTheIntegralOfForceAlongTheCurve) {
  const JkrParameters p = benchmark();
  const double ac = jkr_critical_radius(p);
  for (double s = 1.05; s < 20.0; s *= 1.3) {
    const double a = s * ac, h = 1e-5 * a;
    const double dU = jkr_energy(a + h, p) - jkr_energy(a - h, p);
    const double dd = jkr_overlap(a + h, p) - jkr_overlap(a - h, p);
    const double f = jkr_force(a, p);
    EXPECT_NEAR(dU / dd, f, 1e-7 * (jkr_pulloff_force(p) + std::abs(f))) << "a/a_c = " << s;
  }
  const double touch = jkr_touch_radius(p);
  EXPECT_NEAR(jkr_energy(touch, p), -1.2 * kPi * p.surface_energy * touch * touch,
              1e-12 * kPi * p.surface_energy * touch * touch);
  EXPECT_NEAR(jkr_energy(ac, p), 0.8 * kPi * p.surface_energy * ac * ac,
              1e-12 * kPi * p.surface_energy * ac * ac);
}

TEST(JkrLaw, AgreesWithLammpsProbeValues) {
  // Static probe with LAMMPS 29 Sep 2021 `jkr 1e7 0 0.3 0.1`, r = 5 mm: the pull-off curve matched
  // the JKR F(a(δ)) to 1e-17 N.
  const JkrParameters p = probe();
  EXPECT_NEAR(jkr_force(jkr_contact_radius(1e-6, p), p), -1.55948894744e-3, 1e-13);
  EXPECT_NEAR(jkr_force(jkr_contact_radius(1e-5, p), p), 9.88559898967e-3, 1e-13);
  EXPECT_NEAR(jkr_force(jkr_contact_radius(1e-4, p), p), 0.364702666794, 1e-11);
  EXPECT_NEAR(-jkr_pulloff_overlap(p), 1.152908e-6, 1e-12);
  EXPECT_NEAR(-jkr_rupture_overlap(p), 2.398145e-6, 1e-12);
}

/// Geometry of a head-on pair of 5 mm spheres at overlap δ (normal +x).
dem::ContactGeometry pair_at(double overlap) {
  dem::ContactGeometry g{};
  g.normal = dem::Vec3::UnitX();
  g.overlap = overlap;
  g.distance = 0.01 - overlap;
  g.effect_overlap = overlap;
  g.reduced_radius = 2.5e-3;
  g.reduced_mass = 4.0e-3;
  g.contact_distance = 0.01;
  g.effect_distance = 0.01;
  g.branch_p = -(0.005 - 0.5 * overlap) * g.normal;
  g.branch_q = (0.005 - 0.5 * overlap) * g.normal;
  g.contact_velocity = dem::Vec3::Zero();
  g.tangential_velocity = dem::Vec3::Zero();
  g.relative_angular_velocity = dem::Vec3::Zero();
  g.normal_speed = 0.0;
  g.charge_product = 0.0;
  return g;
}

/// The Hertz response the normal slot gives at δ.
dem::NormalResponse hertz_at(const JkrParameters& p, double overlap) {
  if (overlap <= 0.0) return {};
  return {hertz_force(p.effective_modulus, p.reduced_radius, overlap),
          hertz_stiffness(p.effective_modulus, p.reduced_radius, overlap),
          hertz_energy(p.effective_modulus, p.reduced_radius, overlap), true};
}

/// One evaluation of the `jkr` slot: (response, attached afterwards).
std::pair<dem::CohesionResponse, bool> jkr_step(double overlap, bool attached,
                                                dem::JkrRupture policy = dem::JkrRupture::displacement) {
  const JkrParameters p = benchmark();
  const dem::JkrCohesion model{p.effective_modulus, p.surface_energy};
  const dem::ContactGeometry g = pair_at(overlap);
  dem::ContactHistory committed;
  committed.attached = attached;
  dem::ContactPolicies policies;
  policies.jkr_rupture = policy;
  const dem::ContactInput in{g, committed, 1e-6, policies};
  dem::ContactHistory next = committed;
  const dem::CohesionResponse r = model.evaluate(in, hertz_at(p, overlap), next);
  return {r, next.attached};
}

TEST(JkrHysteresis, ApproachWithoutContactGivesNoForce) {
  const auto [r, attached] = jkr_step(-1e-6, false);
  EXPECT_FALSE(attached);
  EXPECT_FALSE(r.active);
  EXPECT_FALSE(r.contact);
  EXPECT_EQ(r.force, 0.0);
}

TEST(JkrHysteresis, ContactFormsWhenTheOverlapReachesZeroWithEightNinthsOfPullOff) {
  const double f_po = jkr_pulloff_force(benchmark());
  const auto [r, attached] = jkr_step(0.0, false);
  EXPECT_TRUE(attached);
  EXPECT_TRUE(r.active);
  EXPECT_TRUE(r.contact);
  EXPECT_NEAR(r.force, -8.0 / 9.0 * f_po, 1e-12 * f_po);
  EXPECT_NEAR(r.pulloff_force, f_po, 1e-15 * f_po);
}

TEST(JkrHysteresis, ForceReplacesHertzInContact) {
  const JkrParameters p = benchmark();
  for (const double delta : {1e-6, 8e-5, 3e-4}) {
    const auto [r, attached] = jkr_step(delta, false);
    EXPECT_TRUE(attached);
    const dem::NormalResponse hertz = hertz_at(p, delta);
    const double jkr = jkr_force(jkr_contact_radius(delta, p), p);
    EXPECT_NEAR(r.force + hertz.force, jkr, 1e-12 * std::abs(jkr) + 1e-15);
    EXPECT_NEAR(r.energy + hertz.energy, jkr_energy(jkr_contact_radius(delta, p), p), 1e-15);
  }
}

TEST(JkrHysteresis, AttachedNeckPersistsBelowZeroUntilDeltaC) {
  const JkrParameters p = benchmark();
  const double dc = jkr_rupture_overlap(p);
  const auto [held, still] = jkr_step(0.999 * dc, true);
  EXPECT_TRUE(still);
  EXPECT_TRUE(held.contact);
  EXPECT_NEAR(held.force, jkr_force(jkr_contact_radius(0.999 * dc, p), p), 1e-12);
  EXPECT_LT(held.force, -5.0 / 9.0 * jkr_pulloff_force(p));
  const auto [at_dc, at] = jkr_step(dc * (1.0 - 1e-12), true);  // δ_c itself is one rounding away
  EXPECT_TRUE(at);
  EXPECT_NEAR(at_dc.force, -5.0 / 9.0 * jkr_pulloff_force(p), 1e-5 * jkr_pulloff_force(p));  // F − F_c ∝ √(δ − δ_c)
  const auto [broken, gone] = jkr_step(1.0001 * dc, true);
  EXPECT_FALSE(gone);
  EXPECT_FALSE(broken.active);
  EXPECT_EQ(broken.force, 0.0);
}

TEST(JkrHysteresis, LoadPolicyBreaksAtThePullOffPointLikeLammps) {
  const JkrParameters p = benchmark();
  const double df = jkr_pulloff_overlap(p);
  const auto [held, still] = jkr_step(0.999 * df, true, dem::JkrRupture::load);
  EXPECT_TRUE(still);
  EXPECT_NEAR(held.force, -jkr_pulloff_force(p), 1e-5 * jkr_pulloff_force(p));
  const auto [broken, gone] = jkr_step(1.001 * df, true, dem::JkrRupture::load);
  EXPECT_FALSE(gone);
  EXPECT_EQ(broken.force, 0.0);
  // The displacement policy still holds there.
  EXPECT_TRUE(jkr_step(1.001 * df, true).second);
}

TEST(JkrHysteresis, ReapproachAfterRuptureNeedsContactAgain) {
  const double dc = jkr_rupture_overlap(benchmark());
  EXPECT_FALSE(jkr_step(1.01 * dc, true).second);       // breaks
  EXPECT_FALSE(jkr_step(0.5 * dc, false).second);       // coming back: no neck at δ < 0
  EXPECT_EQ(jkr_step(0.5 * dc, false).first.force, 0.0);
  EXPECT_TRUE(jkr_step(1e-9, false).second);            // touches: forms again
}

TEST(JkrHysteresis, RangeReachesTheRuptureSeparation) {
  const JkrParameters p = benchmark();
  const dem::JkrCohesion model{p.effective_modulus, p.surface_energy};
  EXPECT_NEAR(model.range({0.01, 0.01, 2.5e-3}), 0.01 - jkr_rupture_overlap(p), 1e-18);
}

TEST(JkrContactModel, TotalNormalForceIsTheJkrForceWithHertz) {
  const JkrParameters p = benchmark();
  dem::PairLaw law{dem::HertzNormal{p.effective_modulus}, dem::NoDamping{}, dem::NoTangential{},
                   dem::JkrCohesion{p.effective_modulus, p.surface_energy}, dem::NoRolling{}, {}};
  dem::ContactHistory attached;
  attached.attached = true;
  for (const double delta : {-5e-5, -1e-5, 0.0, 2e-5, 2e-4}) {
    const dem::ContactOutcome c = dem::evaluate_contact(law, pair_at(delta), attached, 1e-6);
    EXPECT_TRUE(c.interacting);
    EXPECT_TRUE(c.contact);
    EXPECT_TRUE(c.history.attached);
    const double jkr = jkr_force(jkr_contact_radius(delta, p), p);
    EXPECT_NEAR(c.normal_force, jkr, 1e-12 * jkr_pulloff_force(p)) << delta;
    EXPECT_NEAR(c.elastic_energy + c.cohesive_energy, jkr_energy(jkr_contact_radius(delta, p), p),
                1e-15);
  }
  const dem::ContactOutcome apart = dem::evaluate_contact(law, pair_at(-1e-5), {}, 1e-6);
  EXPECT_FALSE(apart.interacting);
  EXPECT_EQ(apart.normal_force, 0.0);
}

TEST(JkrHysteresis, ReportsTheContactRadiusForTheDashpots) {
  const JkrParameters p = benchmark();
  for (const double delta : {-1e-5, 2e-5, 2e-4}) {
    const auto [r, attached] = jkr_step(delta, true);
    ASSERT_TRUE(attached);
    const double a = jkr_contact_radius(delta, p);
    EXPECT_EQ(r.contact_radius, a);
    EXPECT_DOUBLE_EQ(r.radius_stiffness, 4.0 / 3.0 * p.effective_modulus * a);
    // a exceeds the Hertz √(R*δ) at every overlap: adhesion widens the contact.
    if (delta > 0.0) {
      EXPECT_GT(a, std::sqrt(p.reduced_radius * delta));
    }
  }
  EXPECT_EQ(jkr_step(-1e-5, false).first.contact_radius, 0.0);  // no neck, no radius
}

TEST(JkrContactModel, ZeroSurfaceEnergyIsHertz) {
  const JkrParameters p = benchmark();
  const dem::PairLaw jkr{dem::HertzNormal{p.effective_modulus}, dem::LammpsTsujiDamping{0.5, dem::laws::lammps_tsuji_factor(0.5)},
                         dem::NoTangential{}, dem::JkrCohesion{p.effective_modulus, 0.0}, dem::NoRolling{}, {}};
  const dem::PairLaw hertz{dem::HertzNormal{p.effective_modulus}, dem::LammpsTsujiDamping{0.5, dem::laws::lammps_tsuji_factor(0.5)},
                           dem::NoTangential{}, dem::NoCohesion{}, dem::NoRolling{}, {}};
  for (const double delta : {-1e-5, 0.0, 2e-5, 2e-4}) {
    dem::ContactGeometry g = pair_at(delta);
    g.normal_speed = -0.3;
    const dem::ContactOutcome a = dem::evaluate_contact(jkr, g, {}, 1e-6);
    const dem::ContactOutcome b = dem::evaluate_contact(hertz, g, {}, 1e-6);
    EXPECT_EQ(a.interacting, b.interacting) << delta;
    EXPECT_EQ(a.normal_force, b.normal_force) << delta;
    EXPECT_FALSE(a.history.attached);
  }
  const dem::JkrCohesion flat{p.effective_modulus, 0.0};
  EXPECT_FALSE(flat.adhesive());
  EXPECT_EQ(flat.range({0.01, 0.01, 2.5e-3}), 0.01);
}

TEST(JkrContactModel, LammpsDashpotsUseTheJkrContactRadiusLikeLammps) {
  // pair_granular.cpp (2021) under jkr: knfac = (4/3) E* a; tsuji η = α √(m* knfac), viscoelastic
  // η = η₀ a m*, a the JKR contact radius — also in a neck at δ < 0, where Hertz gives none.
  const JkrParameters p = benchmark();
  const double alpha = dem::laws::lammps_tsuji_factor(0.5);
  const dem::PairLaw tsuji{dem::HertzNormal{p.effective_modulus}, dem::LammpsTsujiDamping{0.5, alpha},
                           dem::NoTangential{}, dem::JkrCohesion{p.effective_modulus, p.surface_energy},
                           dem::NoRolling{}, {}};
  const dem::PairLaw visco{dem::HertzNormal{p.effective_modulus}, dem::LammpsViscoelasticDamping{1e4},
                           dem::NoTangential{}, dem::JkrCohesion{p.effective_modulus, p.surface_energy},
                           dem::NoRolling{}, {}};
  dem::ContactHistory attached;
  attached.attached = true;
  for (const double delta : {-1e-5, 2e-5, 2e-4}) {
    dem::ContactGeometry g = pair_at(delta);
    g.normal_speed = -0.2;
    const double a = jkr_contact_radius(delta, p);
    const double f_jkr = jkr_force(a, p);
    const double eta_tsuji = alpha * std::sqrt(g.reduced_mass * 4.0 / 3.0 * p.effective_modulus * a);
    const dem::ContactOutcome t = dem::evaluate_contact(tsuji, g, attached, 1e-6);
    EXPECT_NEAR(t.normal_force, f_jkr + eta_tsuji * 0.2, 1e-12 * std::abs(f_jkr)) << delta;
    const double eta_visco = 1e4 * a * g.reduced_mass;
    const dem::ContactOutcome v = dem::evaluate_contact(visco, g, attached, 1e-6);
    EXPECT_NEAR(v.normal_force, f_jkr + eta_visco * 0.2, 1e-12 * std::abs(f_jkr)) << delta;
  }
}

TEST(JkrContactModel, ShiftedFrictionLimitLeavesTheDashpotOutOfAnAdhesiveContact) {
  const double elastic = 2.0;
  const double damping = 0.5;
  const double cohesion = -0.7;
  EXPECT_EQ(dem::friction_limit_basis(dem::FrictionLimit::jkr_shifted, elastic, damping, cohesion, 0.4),
            std::abs(elastic + cohesion + 0.8));
  // Without adhesion (a γ = 0 wall): LAMMPS' hertz/material limit, elastic + damping.
  EXPECT_EQ(dem::friction_limit_basis(dem::FrictionLimit::jkr_shifted, elastic, -3.0, 0.0, 0.0), 1.0);
}

/// Two 5 mm benchmark spheres, one fixed, the other approaching at `speed`: JKR + Hertz with
/// restitution damping ε = 0.5.
dem::SimulationSetup adhesive_collision(double speed) {
  dem::SimulationSetup s;
  dem::MaterialProperties m;
  m.name = "jkr";
  m.density = 8000.0;
  m.youngs_modulus = 8.4e7;
  m.poisson_ratio = 0.3;
  m.surface_energy = 121.5;
  m.restitution = 0.5;
  s.materials = {m};
  s.model.normal = "hertz";
  s.model.damping = "restitution";
  s.model.cohesion = "jkr";
  s.particles = {
      dem::ParticleInit{0.005, 0.005, 8000.0, 0, dem::Vec3(0, 0, 0), dem::Vec3(speed, 0, 0), dem::Vec3::Zero(), false},
      dem::ParticleInit{0.005, 0.005, 8000.0, 0, dem::Vec3(0.01 + 1e-4, 0, 0), dem::Vec3::Zero(), dem::Vec3::Zero(), true}};
  s.scheme = dem::SchemeId::velocity_verlet;
  s.scheme_settings.rotation = false;
  s.scheme_settings.length_scale = 0.005;
  s.timestep = 2e-7;
  return s;
}

TEST(JkrSimulation, MechanicalEnergyNeverRisesInADampedAdhesiveCollision) {
  // 0.05 and 0.5 m/s: the pair sticks; 2 m/s: it rebounds and the neck breaks. Kinetic + elastic
  // + cohesive energy drops at the snap-in and the rupture, and in the dashpot; RK4 at Δt = 0.2 µs
  // (some 1000 steps per contact) never raises it by more than rounding.
  for (const double speed : {0.05, 0.5, 2.0}) {
    dem::SimulationSetup setup = adhesive_collision(speed);
    setup.scheme = dem::SchemeId::rk4;
    dem::Simulation sim(setup);
    const auto mechanical = [&] {
      const dem::EnergyLedger e = sim.energy();
      return e.kinetic + e.elastic + e.cohesive;
    };
    const double start = mechanical();
    double previous = start;
    bool touched = false;
    for (int n = 0; n < 50000; ++n) {
      sim.step();
      const double now = mechanical();
      ASSERT_LE(now, previous + 1e-9 * start) << "step " << n << ", speed " << speed;
      previous = now;
      touched = touched || sim.energy().cohesive != 0.0;
    }
    EXPECT_TRUE(touched);
    EXPECT_LT(previous, 0.5 * start);
  }
}

}  // namespace

namespace cohesion_jkr_mindlin_radius {

using namespace cohesion_jkr_test;

/// Tangential force of an attached JKR contact at overlap δ with a stored slip along y, for a
/// Mindlin law (friction high enough never to cap) under the given Mindlin-radius policy.
double mindlin_force(double delta, dem::MindlinRadius policy, bool thesis) {
  const JkrParameters p = benchmark();
  dem::PairLaw law{dem::HertzNormal{p.effective_modulus}, dem::NoDamping{}, dem::NoTangential{},
                   dem::JkrCohesion{p.effective_modulus, p.surface_energy}, dem::NoRolling{}, {}};
  const dem::MindlinParameters m{1e8, 1e6, 0.0};
  if (thesis) {
    law.tangential = dem::MindlinTangential{m};
  } else {
    law.tangential = dem::Mindlin8GTangential{m};
  }
  law.policies.mindlin_radius = policy;
  dem::ContactHistory attached;
  attached.attached = true;
  attached.tangential_slip = dem::Vec3(0.0, 1e-7, 0.0);
  return dem::evaluate_contact(law, pair_at(delta), attached, 0.0).force_on_p[1];
}

TEST(JkrMindlinRadius, ContactRadiusPolicyPutsTheJkrRadiusIntoTheStiffness) {
  const JkrParameters p = benchmark();
  for (const double delta : {-5e-7, 1e-6, 2e-5, 2e-4}) {
    const double a = jkr_contact_radius(delta, p);
    // k = 8 G* a (mindlin_8g) or 16/3 G* a (mindlin) with a the JKR radius; F = −k ς.
    EXPECT_NEAR(mindlin_force(delta, dem::MindlinRadius::contact_radius, false), -8.0 * 1e8 * a * 1e-7,
                1e-9 * 8.0 * 1e8 * a * 1e-7) << delta;
    EXPECT_NEAR(mindlin_force(delta, dem::MindlinRadius::contact_radius, true), -16.0 / 3.0 * 1e8 * a * 1e-7,
                1e-9 * 8.0 * 1e8 * a * 1e-7) << delta;
    // The default takes the Hertz radius of the body overlap: none at δ ≤ 0.
    const double hertz = delta > 0.0 ? std::sqrt(2.5e-3 * delta) : 0.0;
    EXPECT_DOUBLE_EQ(mindlin_force(delta, dem::MindlinRadius::overlap, false), -8.0 * 1e8 * hertz * 1e-7) << delta;
  }
}

}  // namespace cohesion_jkr_mindlin_radius
