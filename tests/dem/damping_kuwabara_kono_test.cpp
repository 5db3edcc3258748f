// SPDX-License-Identifier: MIT
// The Kuwabara–Kono viscoelastic dashpot (thesis eq 3.14) with Hertz: its coefficient, and the
// small-dissipation closed form of the restitution, 1 − e = c γ with γ ∝ v^{1/5}.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/hertz.hpp"
#include "normal_hertz_fixture.hpp"

namespace damping_kuwabara_kono_test {

TEST(KuwabaraKonoDamping, CoefficientIsTwoEPrimeSqrtRStarDelta) {
  dem::PairProperties p;
  p.viscous_modulus = 250.0;  // E' [Pa·s]
  const dem::KuwabaraKonoDamping d = dem::KuwabaraKonoDamping::from_pair(p);
  dem::ContactGeometry g{};
  g.reduced_radius = 5e-3;
  g.overlap = 1e-4;
  EXPECT_NEAR(d.coefficient(g, {}), 2.0 * 250.0 * std::sqrt(5e-3 * 1e-4), 1e-14);
  g.overlap = 0.0;
  EXPECT_EQ(d.coefficient(g, {}), 0.0);
}

/// First-order loss 1 − e ≈ ΔE / (2 E_kin) of the Hertz–Kuwabara–Kono impact at `speed`, with
/// the dashpot work ΔE = ∫ c √δ δ'² dt = 2 c v δ_max^{3/2} (2/5) B(3/5, 3/2) taken along the
/// elastic trajectory δ'² = v² (1 − (δ/δ_max)^{5/2}), c = 2 E' √R*.
double first_order_loss(double viscous_modulus, double speed) {
  const double m = hertz_test::mover_mass(), r = hertz_test::reduced_radius();
  const double peak = dem::laws::hertz_max_overlap(m, hertz_test::effective_modulus(), r, speed);
  const double c = 2.0 * viscous_modulus * std::sqrt(r);
  const double dissipated = 2.0 * c * speed * std::pow(peak, 1.5) * 0.4 * std::beta(0.6, 1.5);
  return 0.5 * dissipated / (0.5 * m * speed * speed);  // 1 − e ≈ ΔE / (2 E_kin)
}

TEST(KuwabaraKonoCollision, WeakDampingLosesTheWorkOfTheDashpotAlongTheElasticPath) {
  for (const double v : {0.5, 2.0}) {
    const double tc = hertz_test::elastic_duration(v);
    const double dt = tc / 2000.0;
    dem::Simulation sim(hertz_test::impact(dem::SchemeId::rk4, dt, "kuwabara_kono",
                                           [](dem::SimulationSetup& s) { s.materials[0].viscous_modulus = 20.0; },
                                           v));
    while (sim.time() < 12.0 * dt + 1.5 * tc) sim.step();
    const double loss = 1.0 + sim.state().velocity(0, 0) / v;
    EXPECT_NEAR(loss, first_order_loss(20.0, v), 2e-2 * loss) << "v = " << v;  // O(γ²) rest
  }
}

TEST(KuwabaraKonoCollision, LossGrowsAsTheFifthRootOfTheImpactSpeed) {
  EXPECT_NEAR(first_order_loss(20.0, 4.0) / first_order_loss(20.0, 1.0), std::pow(4.0, 0.2), 1e-12);
}

}  // namespace
