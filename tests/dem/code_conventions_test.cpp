// SPDX-License-Identifier: MIT
// The policies that replicate a reference code's contact conventions, against their formulas
// (docs/physics-tangential.md, docs/physics-cohesion.md): YADE's α-scaled incident velocity and
// first-order shear rotation, the incremental Mindlin spring, YADE's dashpot cap under adhesion
// and LAMMPS' unloaded slider.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/contact/contact_geometry.hpp"
#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/coulomb_friction.hpp"
#include "dem/contact/laws/dmt.hpp"
#include "dem/contact/laws/mindlin_stiffness.hpp"

namespace code_conventions_test {

using dem::Vec3;

/// Two spheres overlapping by 2e-6 m along a tilted line, moving and spinning.
void spinning_pair(dem::SphereState& p, dem::SphereState& q) {
  const Vec3 n = Vec3(0.3, -0.2, 0.9).normalized();
  q = {Vec3(0.001, 0.002, -0.003), Vec3(-0.2, 0.1, 0.05), Vec3(30.0, -70.0, 20.0), 1.2e-3, 1.2e-3, 1.0 / 3e-5};
  p = {q.position + (1.2e-3 + 0.8e-3 - 2e-6) * n, Vec3(0.4, -0.3, 0.2), Vec3(-50.0, 10.0, 90.0), 0.8e-3, 0.8e-3,
       1.0 / 1e-5};
}

TEST(YadeIncident, ScalesTheCentresTangentialVelocityByAlphaAndSpinsWithTheRadii) {
  dem::SphereState p, q;
  spinning_pair(p, q);
  const dem::ContactGeometry g = dem::pair_geometry(p, q, dem::PairLeverArm::yade_incident);
  const Vec3 n = g.normal;
  const double alpha = (p.radius + q.radius) / (p.radius + q.radius - g.overlap);
  // YADE: [α (u_p − u_q) − (r_p ω_p + r_q ω_q) × n]_t (its normal points the other way).
  const Vec3 incident = alpha * (p.velocity - q.velocity) - (p.radius * p.angular_velocity + q.radius * q.angular_velocity).cross(n);
  const Vec3 expected = incident - incident.dot(n) * n;
  EXPECT_LT((g.tangential_velocity - expected).norm(), 1e-15 * expected.norm());
  // The normal speed stays unscaled (the dashpots read it), and the torque arm is r − δ/2.
  EXPECT_DOUBLE_EQ(g.normal_speed, (p.velocity - q.velocity).dot(n));
  EXPECT_LT((g.branch_p + (p.radius - 0.5 * g.overlap) * n).norm(), 1e-18);
  EXPECT_GT(alpha, 1.0 + 1e-4);  // the scaling is really exercised
  const dem::ContactGeometry plain = dem::pair_geometry(p, q, dem::PairLeverArm::radius_velocity);
  EXPECT_GT((plain.tangential_velocity - g.tangential_velocity).norm(), 1e-5 * expected.norm());
}

TEST(YadeIncident, AgainstAWallScalesBy2rOver2rMinusDelta) {
  const double r = 1e-3, delta = 3e-6;
  const dem::SphereState p{Vec3(0, 0, r - delta), Vec3(0.3, -0.1, -0.2), Vec3(40.0, 20.0, -10.0), r, r, 1e5};
  const dem::Wall floor{Vec3::Zero(), Vec3::UnitZ()};
  const dem::ContactGeometry g = dem::wall_geometry(p, floor, 0.0, dem::WallLeverArm::yade_incident);
  const Vec3 n = Vec3::UnitZ();
  const double alpha = 2.0 * r / (2.0 * r - delta);
  const Vec3 incident = alpha * p.velocity - r * p.angular_velocity.cross(n);
  const Vec3 expected = incident - incident.dot(n) * n;
  EXPECT_LT((g.tangential_velocity - expected).norm(), 1e-15 * expected.norm());
  EXPECT_DOUBLE_EQ(g.normal_speed, p.velocity.z());
  EXPECT_DOUBLE_EQ(g.branch_p.z(), -(r - 0.5 * delta));
}

TEST(YadeIncident, AgainstAMeshFacetIsTheContactPointVelocityWithoutAlpha) {
  // YADE's Ig2_Facet_Sphere_ScGeom forms the slip from the velocity of the contact point
  // x − (r − δ/2) n, without α: the common-normal rule, unlike its plane wall.
  const double r = 1e-3, delta = 3e-6;
  const dem::SphereState p{Vec3(0.002, 0.001, r - delta), Vec3(0.3, -0.1, -0.2), Vec3(40.0, 20.0, -10.0), r, r, 1e5};
  const dem::Wall facet = dem::triangle_wall(Vec3::Zero(), Vec3(0.01, 0.0, 0.0), Vec3(0.0, 0.01, 0.0));
  const dem::ContactGeometry g = dem::wall_geometry(p, facet, 0.0, dem::WallLeverArm::yade_incident);
  const Vec3 n = Vec3::UnitZ();
  ASSERT_NEAR(g.overlap, delta, 1e-18);
  const Vec3 at_point = p.velocity + p.angular_velocity.cross(-(r - 0.5 * delta) * n);
  const Vec3 expected = at_point - at_point.dot(n) * n;
  EXPECT_LT((g.tangential_velocity - expected).norm(), 1e-15 * expected.norm());
  EXPECT_DOUBLE_EQ(g.branch_p.z(), -(r - 0.5 * delta));
  // Off the facet's edge y = 0 (the centre 0.3r beyond it): the edge contact takes the same rule,
  // along its own normal from the nearest point of the edge.
  dem::SphereState q = p;
  q.position = Vec3(0.004, -0.3 * r, 0.95 * r - delta);
  const dem::ContactGeometry edge = dem::wall_geometry(q, facet, 0.0, dem::WallLeverArm::yade_incident);
  ASSERT_GT(edge.overlap, 0.0);
  ASSERT_GT(std::abs(edge.normal.y()), 0.1);  // not the face's normal
  const Vec3 at_edge = q.velocity + q.angular_velocity.cross(-(r - 0.5 * edge.overlap) * edge.normal);
  const Vec3 expected_edge = at_edge - at_edge.dot(edge.normal) * edge.normal;
  EXPECT_LT((edge.tangential_velocity - expected_edge).norm(), 1e-15 * expected_edge.norm());
  // The same sphere on a plane wall takes YADE's α-scaled rule, which differs.
  const dem::ContactGeometry plane = dem::wall_geometry(p, dem::Wall{Vec3::Zero(), Vec3::UnitZ()}, 0.0,
                                                        dem::WallLeverArm::yade_incident);
  EXPECT_GT((plane.tangential_velocity - g.tangential_velocity).norm(), 1e-5 * expected.norm());
}

TEST(YadeRotate, TurnsTheSlipToFirstOrderWithoutReprojectingAndTwistsAboutTheOldNormal) {
  const Vec3 slip(2e-6, -1e-6, 0.0);
  const Vec3 n_old = Vec3::UnitZ();
  const Vec3 n = Vec3(0.0, 1e-3, 1.0).normalized();
  const Vec3 spin(5.0, -3.0, 400.0);
  const double dt = 1e-6;
  // A new contact (no previous normal) keeps its slip.
  EXPECT_EQ(dem::laws::yade_rotate(slip, Vec3::Zero(), n, spin, dt), slip);
  const Vec3 turned = slip - slip.cross(n_old.cross(n));
  const Vec3 twist = 0.5 * dt * n_old.dot(spin) * n_old;
  const Vec3 expected = turned - turned.cross(twist);
  const Vec3 got = dem::laws::yade_rotate(slip, n_old, n, spin, dt);
  EXPECT_LT((got - expected).norm(), 1e-15 * slip.norm());
  // First order only: the length changes, and the slip keeps a second-order part along the new
  // normal (θ = 1e-3) that the projecting rules remove.
  EXPECT_NE(got.norm(), slip.norm());
  EXPECT_GT(std::abs(got.dot(n)), 0.1 * 1e-6 * slip.norm());
  const Vec3 carried = dem::laws::carry_into_tangent_plane(slip, n);
  EXPECT_LT(std::abs(carried.dot(n)), 1e-20);
}

/// A Hertz pair with mindlin_8g friction under `form`, δ and the committed slip given.
dem::ContactOutcome mindlin_step(dem::MindlinForm form, double overlap, const dem::ContactHistory& committed,
                                 double dt) {
  dem::PairLaw law;
  law.normal = dem::HertzNormal{1e8};
  law.damping = dem::NoDamping{};
  law.tangential = dem::Mindlin8GTangential{{4e7, 0.9, 0.0}};
  law.cohesion = dem::NoCohesion{};
  law.rolling = dem::NoRolling{};
  law.policies.mindlin_form = form;
  const dem::SphereState q{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), 1e-3, 1e-3, 0.0};
  const dem::SphereState p{Vec3(0, 0, 2e-3 - overlap), Vec3(0.001, 0, 0), Vec3::Zero(), 1e-3, 1e-3, 1e5};
  return dem::evaluate_contact(law, dem::pair_geometry(p, q), committed, dt);
}

TEST(MindlinForm, IncrementalLoadsEachIncrementAtTheStiffnessOfItsStep) {
  // Shear at 1 mm/s (sticking) while the overlap grows 1e-6 → 3e-6: the incremental spring force is
  // Σ k_t(δ_i) Δu (each step's stiffness), the total form k_t(δ_now) Σ Δu.
  const double dt = 1e-6, g_star = 4e7, r_star = 0.5e-3;
  dem::ContactHistory inc, tot;
  double sum = 0.0;
  dem::ContactOutcome o_inc, o_tot;
  for (int k = 0; k < 20; ++k) {
    const double overlap = 1e-6 + 1e-7 * k;
    o_inc = mindlin_step(dem::MindlinForm::incremental, overlap, inc, dt);
    o_tot = mindlin_step(dem::MindlinForm::total, overlap, tot, dt);
    inc = o_inc.history;
    tot = o_tot.history;
    sum += dem::laws::mindlin_stiffness_at_radius(g_star, std::sqrt(r_star * overlap)) * 0.001 * dt;
  }
  const double last = dem::laws::mindlin_stiffness_at_radius(g_star, std::sqrt(r_star * (1e-6 + 1.9e-6)));
  EXPECT_NEAR(o_inc.force_on_p.x(), -sum, 1e-12 * sum);
  EXPECT_NEAR(o_tot.force_on_p.x(), -last * 20 * 0.001 * dt, 1e-12 * sum);
  EXPECT_GT(std::abs(o_tot.force_on_p.x()) - std::abs(o_inc.force_on_p.x()), 0.1 * sum);  // really different
  // At constant overlap the two forms coincide.
  dem::ContactHistory a, b;
  for (int k = 0; k < 5; ++k) {
    a = mindlin_step(dem::MindlinForm::incremental, 2e-6, a, dt).history;
    b = mindlin_step(dem::MindlinForm::total, 2e-6, b, dt).history;
  }
  const double ka = dem::laws::mindlin_stiffness_at_radius(g_star, std::sqrt(r_star * 2e-6));
  EXPECT_NEAR(8.0 * g_star * a.tangential_slip.x(), ka * b.tangential_slip.x(), 1e-12 * ka * b.tangential_slip.x());
}

/// A DMT pair with a velocity dashpot η separating at speed `speed` with overlap δ.
dem::ContactOutcome dmt_parting(dem::AdhesiveDashpot policy, bool clamp, double overlap, double speed) {
  dem::PairLaw law;
  law.normal = dem::HertzNormal{1e6};
  law.damping = dem::LammpsVelocityDamping{2.0};
  law.tangential = dem::NoTangential{};
  law.cohesion = dem::DmtCohesion{0.05};
  law.rolling = dem::NoRolling{};
  law.policies.adhesive_dashpot = policy;
  law.policies.clamp_tensile = clamp;
  const dem::SphereState q{Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), 1e-3, 1e-3, 0.0};
  const dem::SphereState p{Vec3(0, 0, 2e-3 - overlap), Vec3(0, 0, speed), Vec3::Zero(), 1e-3, 1e-3, 1e5};
  return dem::evaluate_contact(law, dem::pair_geometry(p, q), dem::ContactHistory{}, 1e-6);
}

TEST(AdhesiveDashpot, PulloffCapLimitsATensileDashpotToThePulloffForceAsYadeDoes) {
  const double f_po = dem::laws::dmt_pulloff_force(0.05, 0.5e-3);  // R* of two 1 mm spheres
  // Fast parting: the dashpot 2·0.5 = 1 N would leave the force far tensile.
  const auto capped = dmt_parting(dem::AdhesiveDashpot::pulloff_cap, true, 1e-7, 0.5);
  EXPECT_NEAR(capped.damping_force, -f_po, 1e-15 * f_po);
  // clamp_tensile instead keeps F_el + F_d ≥ 0: the dashpot is cut to −F_el, far below F_po here.
  const auto clamped = dmt_parting(dem::AdhesiveDashpot::clamp, true, 1e-7, 0.5);
  EXPECT_LT(clamped.damping_force, 0.0);
  EXPECT_GT(clamped.damping_force, -1e-2 * f_po);
  // A dashpot below F_po, or one that leaves the force compressive, acts in full.
  const auto small = dmt_parting(dem::AdhesiveDashpot::pulloff_cap, true, 1e-7, 0.1 * f_po / 2.0);
  EXPECT_NEAR(small.damping_force, -0.1 * f_po, 1e-12 * f_po);
  const auto loaded = dmt_parting(dem::AdhesiveDashpot::pulloff_cap, true, 5e-5, 1e-3);
  EXPECT_NEAR(loaded.damping_force, -2e-3, 1e-15);
}

}  // namespace code_conventions_test
