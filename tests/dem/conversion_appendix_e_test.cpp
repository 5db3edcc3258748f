// SPDX-License-Identifier: MIT
// Thesis appendix E: linear ↔ JKR by equal work (eq E.3–E.8, listing E.1), round trips, the
// closed-form JKR work against quadrature, and the thesis' ch. 5 benchmark pairing.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <tuple>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>

#include "dem/contact/laws/jkr.hpp"
#include "dem/conversion/appendix_e.hpp"

namespace conversion_appendix_e_test {

using namespace dem::conversion;

/// Two benchmark spheres (thesis table 5.1): r = 5 mm, effect radius 1.5 r, δ_max = 2.5e-4 m.
PairGeometry benchmark_pair() { return {5e-3, 7.5e-3, 2.5e-4}; }

TEST(AppendixE, EquationE4EqualsTheElasticWorkUpToMaxOverlap) {
  const double e = 4.6e7, r = 2.5e-3, d = 2e-4;
  const double k = stiffness_from_modulus(e, r, d);
  EXPECT_NEAR(k, 16.0 / 15.0 * e * std::sqrt(r * d), 1e-9 * k);
  EXPECT_NEAR(0.5 * k * d * d, hertz_separation_work(e, r, d), 1e-15 * k * d * d);
  EXPECT_NEAR(modulus_from_stiffness(k, r, d), e, 1e-15 * e);
}

TEST(AppendixE, LinearWorkIsEquationE8WithTheListingsSign) {
  const LinearModel m{1e5, 1e2};
  const PairGeometry p = benchmark_pair();
  const double effect = 2.0 * (7.5e-3 - 5e-3) + 2.5e-4;
  EXPECT_NEAR(max_effect_overlap(p), effect, 1e-18);
  EXPECT_NEAR(linear_separation_work(m, p), 0.5 * 1e5 * 2.5e-4 * 2.5e-4 - 0.5 * 1e2 * effect * effect,
              1e-18);
}

TEST(AppendixE, ClosedFormJkrWorkMatchesGaussKronrodQuadrature) {
  // W = ∫ F dδ from δ_c to δ_max along the curve, integrated in the contact radius a (smooth,
  // unlike F(δ) at the fold): ∫_{a_c}^{a_max} F(a) dδ/da da.
  const dem::laws::JkrParameters p{4.6154e7, 2.5e-3, 121.5};
  for (const double d_max : {1e-5, 1e-4, 1e-3}) {
    for (const auto rupture : {dem::JkrRupture::displacement, dem::JkrRupture::load}) {
      const double a_end = rupture == dem::JkrRupture::load ? dem::laws::jkr_pulloff_radius(p)
                                                            : dem::laws::jkr_critical_radius(p);
      const double a_max = dem::laws::jkr_contact_radius(d_max, p);
      const auto integrand = [&](double a) {
        const double slope = 2.0 * a / p.reduced_radius -
                             0.5 * std::sqrt(4.0 * std::numbers::pi * p.surface_energy / (p.effective_modulus * a));
        return dem::laws::jkr_force(a, p) * slope;
      };
      const double quadrature =
          boost::math::quadrature::gauss_kronrod<double, 61>::integrate(integrand, a_end, a_max, 15, 1e-14);
      const double closed = jkr_separation_work(p, d_max, rupture);
      EXPECT_NEAR(closed, quadrature, 1e-10 * std::abs(quadrature)) << d_max;
    }
  }
}

TEST(AppendixE, JkrWorkFallsMonotonicallyWithSurfaceEnergyFromTheHertzWork) {
  const double e = 4.6154e7, r = 2.5e-3, d = 2e-4;
  double previous = hertz_separation_work(e, r, d);
  for (double gamma = 1e-6; gamma < 1e4; gamma *= 3.0) {
    const double w = jkr_separation_work({e, r, gamma}, d, dem::JkrRupture::displacement);
    EXPECT_LT(w, previous) << gamma;
    previous = w;
  }
  EXPECT_NEAR(jkr_separation_work({e, r, 1e-12}, d, dem::JkrRupture::displacement),
              hertz_separation_work(e, r, d), 1e-5 * hertz_separation_work(e, r, d));
}

TEST(AppendixE, LinearToJkrToLinearRoundTrips) {
  for (const auto convention : {Convention::workbench, Convention::thesis}) {
    for (const double k_c : {1.0, 1e2, 1e3}) {
      const LinearModel linear{1e5, k_c};
      const JkrModel jkr = linear_to_jkr(linear, benchmark_pair(), convention);
      const LinearModel back = jkr_to_linear(jkr, benchmark_pair(), convention);
      EXPECT_NEAR(back.normal_stiffness, 1e5, 1e-9 * 1e5);
      EXPECT_NEAR(back.cohesive_stiffness, k_c, 1e-9 * k_c);
    }
  }
}

TEST(AppendixE, JkrToLinearToJkrRoundTrips) {
  for (const double gamma : {0.1, 121.5, 1215.0}) {
    const JkrModel jkr{4.6154e7, gamma};
    const JkrModel back = linear_to_jkr(jkr_to_linear(jkr, benchmark_pair(), Convention::workbench),
                                        benchmark_pair(), Convention::workbench);
    EXPECT_NEAR(back.modulus, jkr.modulus, 1e-12 * jkr.modulus);
    EXPECT_NEAR(back.surface_energy, gamma, 1e-9 * gamma);
  }
}

TEST(AppendixE, ThesisConventionReproducesTheChapterFiveBenchmarkPairing) {
  // Table 5.1: linear k_e = 1e5, k_c = 1e2, effect diameter 1.5 d ↔ JKR E = 8.4e7 Pa,
  // γ = 121.5 J/m². Listing E.1 as run: r = 5 mm in eq E.4/E.6–E.7 and E unreduced; E.4 then
  // gives 8.4e7 Pa for δ_max = r/20 = 2.5e-4 m.
  const JkrModel jkr = linear_to_jkr({1e5, 1e2}, benchmark_pair(), Convention::thesis);
  EXPECT_NEAR(jkr.modulus, 8.4e7, 2e-3 * 8.4e7);
  EXPECT_NEAR(jkr.surface_energy, 121.5, 5e-3 * 121.5);
  const LinearModel linear = jkr_to_linear({8.4e7, 121.5}, benchmark_pair(), Convention::thesis);
  EXPECT_NEAR(linear.normal_stiffness, 1e5, 2e-3 * 1e5);
  EXPECT_NEAR(linear.cohesive_stiffness, 1e2, 5e-3 * 1e2);
}

TEST(AppendixE, ConventionsDescribeTheSameCurveWithDoubledSurfaceEnergy) {
  // R* = r/2 and E* = √2 E_thesis (from E.4) give the thesis' curve exactly when γ doubles.
  const JkrModel thesis = linear_to_jkr({1e5, 1e2}, benchmark_pair(), Convention::thesis);
  const JkrModel bench = linear_to_jkr({1e5, 1e2}, benchmark_pair(), Convention::workbench);
  EXPECT_NEAR(bench.modulus, std::sqrt(2.0) * thesis.modulus, 1e-12 * bench.modulus);
  EXPECT_NEAR(bench.surface_energy, 2.0 * thesis.surface_energy, 1e-9 * bench.surface_energy);
  EXPECT_NEAR(youngs_modulus(bench.modulus, 0.3, Convention::workbench), 2.0 * 0.91 * bench.modulus,
              1e-6);
  EXPECT_NEAR(formula_modulus(8.4e7, 0.3, Convention::workbench), 8.4e7 / 1.82, 1e-6);
}

TEST(AppendixE, RejectsNonPhysicalInputAndUnmatchableWork) {
  EXPECT_THROW(static_cast<void>(linear_to_jkr({-1.0, 1.0}, benchmark_pair(), Convention::workbench)),
               std::invalid_argument);
  EXPECT_THROW(static_cast<void>(linear_to_jkr({1e5, 1.0}, {5e-3, 4e-3, 1e-4}, Convention::workbench)),
               std::invalid_argument);
  EXPECT_THROW(static_cast<void>(linear_to_jkr({1e5, 1.0}, {5e-3, 6e-3, 0.0}, Convention::workbench)),
               std::invalid_argument);
  EXPECT_THROW(static_cast<void>(surface_energy_for_work(1.0, 1e7, 1e-3, 1e-4, dem::JkrRupture::displacement)),
               std::domain_error);
  EXPECT_EQ(linear_to_jkr({1e5, 0.0}, benchmark_pair(), Convention::workbench).surface_energy, 0.0);
}

TEST(AppendixE, LinearCohesiveWorkIsTheTensileAreaFromEquilibriumToTheEffectRange) {
  // Closed form: ½ k_c (δ_eq + Δ)² − ½ k_e δ_eq² with δ_eq = k_c Δ/(k_e − k_c) simplifies to
  // ½ k_c k_e Δ²/(k_e − k_c); table 5.1's linear pair (Δ = 2(7.5 − 5) mm) gives 1.25125e-3 J.
  for (const auto& [ke, kc, r, rhat] : {std::tuple{1e5, 1e2, 5e-3, 7.5e-3}, std::tuple{3e4, 5e3, 2e-3, 2.2e-3},
                                        std::tuple{1e6, 0.0, 1e-3, 1.5e-3}}) {
    const double reach = 2.0 * (rhat - r);
    const double expected = 0.5 * kc * ke * reach * reach / (ke - kc);
    EXPECT_NEAR(linear_cohesive_work({ke, kc}, r, rhat), expected, 1e-12 * std::max(expected, 1e-12));
  }
  EXPECT_NEAR(linear_cohesive_work({1e5, 1e2}, 5e-3, 7.5e-3), 1.2512512512512513e-3, 1e-15);
  EXPECT_THROW(static_cast<void>(linear_cohesive_work({1e2, 1e3}, 5e-3, 7.5e-3)), std::invalid_argument);
  EXPECT_THROW(static_cast<void>(linear_cohesive_work({1e5, 1e2}, 5e-3, 4e-3)), std::invalid_argument);
}

TEST(AppendixE, JkrCohesiveWorkIsTheTensileAreaFromZeroLoadToRupture) {
  // −∫ F dδ from the zero-load contact to rupture, by quadrature along the curve in a
  // (δ(a), F(a) of eq 3.34–3.35): the closed-form energy difference must agree.
  const dem::laws::JkrParameters p{8.4e7 / 1.82, 2.5e-3, 121.5};
  for (const dem::JkrRupture rupture : {dem::JkrRupture::displacement, dem::JkrRupture::load}) {
    const double end = rupture == dem::JkrRupture::load ? dem::laws::jkr_pulloff_radius(p)
                                                        : dem::laws::jkr_critical_radius(p);
    const double a0 = dem::laws::jkr_zero_load_radius(p);
    const auto integrand = [&](double a) {
      const double h = 1e-6 * a;
      const double slope = (dem::laws::jkr_overlap(a + h, p) - dem::laws::jkr_overlap(a - h, p)) / (2.0 * h);
      return -dem::laws::jkr_force(a, p) * slope;
    };
    // Work supplied = ∫ F dδ from δ_0 down to δ_end = −∫_{end}^{a_0} F δ'(a) da: F < 0 and δ' > 0
    // on the stable branch, so it is positive.
    const double expected = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(integrand, end, a0);
    const double work = jkr_cohesive_work(p, rupture);
    EXPECT_GT(work, 0.0);
    EXPECT_NEAR(work, expected, 1e-6 * work);
  }
}

}  // namespace
