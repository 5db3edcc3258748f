// SPDX-License-Identifier: MIT
// The restitution dashpot through YADE's FrictViscoPhys: exactly eq 3.10 except the documented
// factor α = (r_p + r_q)/(r_p + r_q − δ) on the normal velocity.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/particles/particles.hpp"
#include "reference/inhouse/inhouse_engine.hpp"
#include "reference/matching.hpp"
#include "yade_test_support.hpp"

namespace yade_damping_test {

using namespace demwb_yade_test;

/// The canonical single collision with restitution ε = 0.5.
cases::Scene damped_collision() {
  cases::Scene scene = canonical("single_collision.toml");
  scene.model.damping = "restitution";
  scene.materials[0].restitution = 0.5;
  return scene;
}

TEST(YadeDamping, NormalForceIsSpringPlusAlphaScaledDashpot) {
  DEMWB_REQUIRE_YADE();
  const cases::Scene scene = reference::matched_scene(damped_collision(), "yade");
  const auto yade = reference::run_engine(reference::YadeEngine{}, scene, {scratch("damped"), 120.0});
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  ASSERT_FALSE(yade.warnings.empty());

  const auto& p = scene.particles;
  const double k = *scene.materials[0].normal_stiffness;
  const double m = dem::sphere_mass(scene.materials[0].density, p[0].radius);
  // the matched scene carries the restitution ε' of the calibrated betan (β(ε')/2)
  const double eta = dem::laws::restitution_damping_coefficient(*scene.materials[0].restitution, m, k);
  const double contact = p[0].radius + p[1].radius;
  const auto& overlap = *yade.trace.column("c0-1.overlap");
  const auto& fn = *yade.trace.column("c0-1.fn");
  const auto& vx = *yade.trace.column("p0.vx");  // v(n−½), the velocity the dashpot saw
  const double scale = max_abs(fn);
  int in_contact = 0;
  for (std::size_t r = 0; r < fn.size(); ++r) {
    if (!(overlap[r] > 0.0)) continue;
    ++in_contact;
    const double alpha = contact / (contact - overlap[r]);
    // p approaches q along +x, so u_c·n = −vx with n from q to p; eq 3.10: kδ − η u_c·n.
    EXPECT_NEAR(fn[r], k * overlap[r] + alpha * eta * vx[r], 1e-13 * scale) << "row " << r;
  }
  EXPECT_GT(in_contact, 100);
}

TEST(YadeDamping, MatchedRestitutionDiffersFromTheTextbookDashpotByTheAlphaFactorOnly) {
  // The matched core (damping 'yade_frictvisco', with α) reproduces YADE's restitution; the
  // same leapfrog run with the textbook dashpot (no α) rebounds higher, by at most the α bound.
  DEMWB_REQUIRE_YADE();
  cases::Scene fine = damped_collision();
  fine.integration.timestep = 5e-7;
  fine.particles[1].position[0] = 4.0 * 10.37 * 5e-7 + 0.11;
  const cases::Scene scene = reference::matched_scene(fine, "yade");
  ASSERT_EQ(scene.model.damping, "yade_frictvisco");
  cases::Scene textbook = scene;
  textbook.model.damping = "restitution";
  const auto inhouse = reference::run_engine(reference::InhouseEngine{}, scene, {});
  const auto plain = reference::run_engine(reference::InhouseEngine{}, textbook, {});
  const auto yade = reference::run_engine(reference::YadeEngine{}, scene, {scratch("damped-matched"), 120.0});
  ASSERT_EQ(inhouse.status, cases::RunStatus::ok) << inhouse.reason;
  ASSERT_EQ(plain.status, cases::RunStatus::ok) << plain.reason;
  ASSERT_EQ(yade.status, cases::RunStatus::ok) << yade.reason << "\n" << yade.log_tail;
  const ColumnScales scales = collision_scales(scene, inhouse);
  for (const auto& [column, diff] : column_differences(inhouse, yade, scales)) {
    std::printf("  %-14s max |inhouse - yade| / scale = %.3g\n", column.c_str(), diff);
    EXPECT_LE(diff, 1e-12) << column;
  }
  const double e_inhouse = -inhouse.trace.column("p0.vx")->back() / 4.0;
  const double e_plain = -plain.trace.column("p0.vx")->back() / 4.0;
  const double e_yade = -yade.trace.column("p0.vx")->back() / 4.0;
  std::printf("  restitution: textbook dashpot %.9f, matched (α) %.9f, YADE %.9f\n", e_plain,
              e_inhouse, e_yade);
  EXPECT_NEAR(e_inhouse, e_yade, 1e-12);
  // YADE's dashpot is stronger by α − 1 ≤ δmax/(r_p + r_q − δmax): ln e drops by at most
  // |ln ε|·that.
  const double d_max = max_abs(*inhouse.trace.column("c0-1.overlap"));
  const double bound = 0.5 * std::log(2.0) * d_max / (0.11 - d_max);
  EXPECT_LT(e_yade, e_plain);
  EXPECT_LT(e_plain - e_yade, bound);
}

}  // namespace
