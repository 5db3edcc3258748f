// SPDX-License-Identifier: MIT
// Tangential friction laws and sub-models against their formulas (thesis eq 3.22–3.26, 3.32):
// history carried into the tangent plane, Coulomb cap with Cundall–Strack truncation, Mindlin
// stiffness, tangential damping, friction-limit policies and the torque a_p × F_t.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/coulomb_friction.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/laws/mindlin_stiffness.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/contact/registry.hpp"

namespace tangential_laws_test {

using dem::Vec3;

constexpr double kRadius = 0.01;
const double kMass = 4.0 / 3.0 * std::numbers::pi * 1000.0 * std::pow(kRadius, 3);

/// A sphere touching the floor z = 0 with overlap δ, velocity v and spin w.
dem::ContactGeometry floor_contact(double overlap, const Vec3& v, const Vec3& w = Vec3::Zero(),
                                   bool lever_is_radius = false) {
  const dem::SphereState p{Vec3(0, 0, kRadius - overlap), v, w, kRadius, kRadius, 1.0 / kMass};
  const dem::Wall floor{Vec3::Zero(), Vec3::UnitZ()};
  return dem::wall_geometry(p, floor, 0.0, lever_is_radius ? dem::WallLeverArm::radius : dem::WallLeverArm::contact_point);
}

/// Pair properties of a linear spring–dashpot contact with spring–Coulomb friction.
dem::PairProperties friction_pair(double mu, double k_f, double ratio, double restitution = 1.0) {
  dem::PairProperties p;
  p.normal_stiffness = 1e5;
  p.restitution = restitution;
  p.tangential_stiffness = k_f;
  p.friction = mu;
  p.tangential_damping_ratio = ratio;
  return p;
}

dem::PairLaw friction_law(const dem::PairProperties& p, dem::FrictionLimit limit,
                          const char* damping = "none", const char* tangential = "spring_coulomb") {
  dem::ModelChoice c;
  c.damping = damping;
  c.tangential = tangential;
  c.friction_limit = limit;
  return dem::make_pair_law(c, p);
}

TEST(HistoryRotation, SlipStaysInTheTangentPlaneWithItsMagnitudeWhenTheNormalTurns) {
  const Vec3 slip(3e-6, -1e-6, 0.0);  // in the plane of n = z
  for (const double angle : {1e-6, 1e-3, 0.05, 0.3, 1.0}) {
    const Vec3 axis = Vec3(1.0, 2.0, 0.0).normalized();
    const Eigen::AngleAxisd turn(angle, axis);
    const Vec3 n = turn * Vec3::UnitZ();
    const Vec3 carried = dem::laws::carry_into_tangent_plane(slip, n);
    EXPECT_NEAR(carried.dot(n), 0.0, 1e-15 * slip.norm()) << "angle " << angle;
    EXPECT_NEAR(carried.norm(), slip.norm(), 1e-15 * slip.norm()) << "angle " << angle;
    // Equal to the rigid rotation of the slip to second order in the angle.
    EXPECT_LE((carried - turn * slip).norm(), 0.5 * angle * angle * slip.norm() + 1e-21)
        << "angle " << angle;
  }
}

TEST(HistoryRotation, UnchangedNormalLeavesTheSlipAloneAndSlipAlongTheNewNormalVanishes) {
  const Vec3 slip(1e-6, 2e-6, 0.0);
  EXPECT_EQ(dem::laws::carry_into_tangent_plane(slip, Vec3::UnitZ()), slip);
  EXPECT_EQ(dem::laws::carry_into_tangent_plane(Vec3(0, 0, 1e-6), Vec3::UnitZ()), Vec3::Zero());
}

TEST(SpringSlider, StuckForceIsMinusSpringMinusDashpotAndTheDashpotDissipates) {
  const Vec3 carried(2e-6, 0, 0), v(0.1, 0.2, 0);
  const double elapsed = 1e-6;
  const auto r = dem::laws::spring_slider(1e5, 3.0, 10.0, carried, v, elapsed, false);
  EXPECT_FALSE(r.sliding);
  EXPECT_TRUE(r.displacement.isApprox(carried + v * elapsed, 1e-15));
  EXPECT_TRUE(r.force.isApprox(-1e5 * r.displacement - 3.0 * v, 1e-15));
  EXPECT_NEAR(r.dissipated, 3.0 * v.squaredNorm() * elapsed, 1e-20);
}

TEST(SpringSlider, CoulombCapHoldsTheForceAtTheLimitAndTruncatesTheSlip) {
  const Vec3 xi(3e-4, -1.5e-4, 0), v(0.3, 0.0, 0);
  const double k = 2e4, limit = 3.0;
  const auto r = dem::laws::spring_slider(k, 0.0, limit, xi, v, 0.0, false);
  ASSERT_TRUE(r.sliding);
  EXPECT_NEAR(r.force.norm(), limit, 1e-14);
  EXPECT_NEAR(k * r.displacement.norm(), limit, 1e-14);  // k|ς| = μ·basis (Cundall–Strack)
  EXPECT_TRUE(r.displacement.normalized().isApprox(xi.normalized(), 1e-14));
  EXPECT_TRUE(r.force.normalized().isApprox(-xi.normalized(), 1e-14));
}

TEST(SpringSlider, SteadySlidingDissipatesLimitTimesSlipSpeedTimesElapsed) {
  const double k = 2e4, limit = 3.0, elapsed = 1e-6;
  const Vec3 v(0.3, 0.4, 0);
  const Vec3 at_cap = v.normalized() * (limit / k);
  const auto r = dem::laws::spring_slider(k, 0.0, limit, at_cap, v, elapsed, false);
  ASSERT_TRUE(r.sliding);
  EXPECT_TRUE(r.displacement.isApprox(at_cap, 1e-14));
  EXPECT_NEAR(r.dissipated, limit * v.norm() * elapsed, 1e-12 * limit * v.norm() * elapsed);
}

TEST(SpringSlider, TruncationKeepsTheDashpotPartAsLammpsDoes) {
  const Vec3 xi(1e-4, 0, 0), v(0.5, 0.5, 0);
  const double k = 2e4, gamma = 2.0, limit = 1.5;
  const auto r = dem::laws::spring_slider(k, gamma, limit, xi, v, 0.0, false);
  ASSERT_TRUE(r.sliding);
  const Vec3 trial = -k * xi - gamma * v;
  EXPECT_TRUE(r.force.isApprox(trial * (limit / trial.norm()), 1e-14));
  EXPECT_TRUE(r.displacement.isApprox(-(r.force + gamma * v) / k, 1e-14));
  // After the cut, spring and dashpot again add up to the force that acts.
  EXPECT_TRUE((-k * r.displacement - gamma * v).isApprox(r.force, 1e-13));
}

TEST(SpringSlider, DashpotAboveTheCapLeavesTheSpringPointingAlongTheSlipAsInLammps) {
  // γ|v| = 2 N > limit 0.5 N: the spring must push forwards so that spring + dashpot = F_capped.
  const Vec3 v(1.0, 0, 0);
  const auto r = dem::laws::spring_slider(2e4, 2.0, 0.5, Vec3(1e-5, 0, 0), v, 1e-6, false);
  ASSERT_TRUE(r.sliding);
  EXPECT_NEAR(r.force.x(), -0.5, 1e-15);
  EXPECT_LT(r.displacement.x(), 0.0);  // −(F + γv)/k = −1.5 N / k
  EXPECT_NEAR(r.displacement.x(), -1.5 / 2e4, 1e-18);
  EXPECT_GE(r.dissipated, 0.0);
}

TEST(SpringSlider, ZeroStiffnessStoresNoDisplacement) {
  const auto r = dem::laws::spring_slider(0.0, 1.0, 10.0, Vec3(1e-3, 0, 0), Vec3(0.1, 0, 0), 1e-6, false);
  EXPECT_EQ(r.displacement, Vec3::Zero());
  EXPECT_TRUE(r.force.isApprox(Vec3(-0.1, 0, 0)));
}

TEST(SpringSlider, UnloadedSliderOverTheCapDropsItsForceOnlyUnderTheZeroPolicy) {
  // ς = 0 at the first evaluation (elapsed 0) and a dashpot force γ|v| = 2 N above the 0.5 N cap.
  const Vec3 v(0.6, -0.8, 0);
  const auto capped = dem::laws::spring_slider(2e4, 2.0, 0.5, Vec3::Zero(), v, 0.0, false);
  ASSERT_TRUE(capped.sliding);
  EXPECT_NEAR(capped.force.norm(), 0.5, 1e-15);
  const auto dropped = dem::laws::spring_slider(2e4, 2.0, 0.5, Vec3::Zero(), v, 0.0, true);
  EXPECT_TRUE(dropped.sliding);
  EXPECT_EQ(dropped.force, Vec3::Zero());
  EXPECT_EQ(dropped.displacement, Vec3::Zero());
  EXPECT_EQ(dropped.dissipated, 0.0);
  // Below the cap, or once any displacement is stored, the policy changes nothing.
  const auto stuck = dem::laws::spring_slider(2e4, 2.0, 5.0, Vec3::Zero(), v, 0.0, true);
  EXPECT_EQ(stuck.force, -2.0 * v);
  const auto loaded_cap = dem::laws::spring_slider(2e4, 2.0, 0.5, Vec3::Zero(), v, 1e-9, false);
  const auto loaded_zero = dem::laws::spring_slider(2e4, 2.0, 0.5, Vec3::Zero(), v, 1e-9, true);
  EXPECT_EQ(loaded_zero.force, loaded_cap.force);
  EXPECT_EQ(loaded_zero.displacement, loaded_cap.displacement);
  EXPECT_NEAR(loaded_zero.force.norm(), 0.5, 1e-15);
}

TEST(SpringSlider, TheSpringTestCapsTheSpringAloneAndDropsTheDashpotWhileSliding) {
  // LIGGGHTS' rule (CoulombTest::spring). Stuck: k|ς| = 1 N below the 1.2 N limit, the dashpot
  // γ|v| = 1 N on top: |F| = √2 N > limit, kept (the whole-force test would have capped it).
  const Vec3 xi(5e-5, 0, 0), v(0, 0.5, 0);
  const double k = 2e4, gamma = 2.0, limit = 1.2;
  const auto stuck = dem::laws::spring_slider(k, gamma, limit, xi, v, 0.0, false, true);
  EXPECT_FALSE(stuck.sliding);
  EXPECT_TRUE(stuck.force.isApprox(-k * xi - gamma * v, 1e-15));
  EXPECT_GT(stuck.force.norm(), limit);
  EXPECT_TRUE(dem::laws::spring_slider(k, gamma, limit, xi, v, 0.0, false, false).sliding);
  // Sliding: k|ς| = 3 N over the limit: the spring's force scaled to it, no dashpot, ς = −F/k.
  const Vec3 far(1.5e-4, 0, 0);
  const auto sliding = dem::laws::spring_slider(k, gamma, limit, far, v, 0.0, false, true);
  ASSERT_TRUE(sliding.sliding);
  EXPECT_TRUE(sliding.force.isApprox(Vec3(-limit, 0, 0), 1e-15));
  EXPECT_TRUE(sliding.displacement.isApprox(Vec3(limit / k, 0, 0), 1e-15));
  EXPECT_GE(sliding.dissipated, 0.0);
  // No dashpot: both tests agree.
  const auto a = dem::laws::spring_slider(k, 0.0, limit, far, v, 1e-6, false, true);
  const auto b = dem::laws::spring_slider(k, 0.0, limit, far, v, 1e-6, false, false);
  EXPECT_TRUE(a.force.isApprox(b.force, 1e-15));
  EXPECT_TRUE(a.displacement.isApprox(b.displacement, 1e-15));
}

TEST(MindlinStiffness, ThesisFormHasPrefactorSixteenThirdsAndMindlinEight) {
  const double g = 3e9, r = 2e-3, d = 1e-6;
  EXPECT_NEAR(dem::laws::mindlin_thesis_stiffness(g, r, d), 16.0 / 3.0 * g * std::sqrt(r * d), 1e-6);
  EXPECT_NEAR(dem::laws::mindlin_stiffness(g, r, d), 8.0 * g * std::sqrt(r * d), 1e-6);
  EXPECT_EQ(dem::laws::mindlin_stiffness(g, r, -1e-6), 0.0);
}

TEST(MindlinStiffness, Mindlin8GReproducesTheLammpsProbeForce) {
  // Probe with LAMMPS 29 Sep 2021: hertz/material E = 1e7, ν = 0.3 on both spheres, r = 0.01
  // against r = 0.1, δ = 1e-4, slip 5e-6 m → LAMMPS F_t = 0.043143079 N.
  const double e = 1e7, nu = 0.3, g = e / (2.0 * (1.0 + nu));
  const double g_star = 1.0 / (2.0 * (2.0 - nu) / g);
  const double r_star = 0.01 * 0.1 / 0.11;
  const double k_t = dem::laws::mindlin_stiffness(g_star, r_star, 1e-4);
  // LAMMPS' δ had shrunk by ~1e-6 relative while the mover slid over the big sphere.
  EXPECT_NEAR(k_t * 5e-6, 0.043143079, 5e-8);
}

TEST(SpringCoulombModel, StuckContactGivesSpringPlusTangentialDashpotWithRatioOfNormalEta) {
  const double ratio = 0.5, e = 0.6;
  const dem::PairLaw law = friction_law(friction_pair(10.0, 2e4, ratio, e),
                                        dem::FrictionLimit::total, "restitution");
  const dem::ContactGeometry g = floor_contact(1e-4, Vec3(0.02, 0, 0));
  dem::ContactHistory committed;
  committed.tangential_slip = Vec3(3e-6, 0, 0);
  const double dt = 1e-6;
  const dem::ContactOutcome c = dem::evaluate_contact(law, g, committed, dt);
  const double eta_n = dem::laws::restitution_damping_coefficient(e, kMass, 1e5);
  const Vec3 slip = committed.tangential_slip + g.tangential_velocity * dt;
  const Vec3 expected = -2e4 * slip - ratio * eta_n * g.tangential_velocity;
  EXPECT_TRUE((c.force_on_p - c.normal_force * g.normal).isApprox(expected, 1e-13));
  EXPECT_TRUE(c.history.tangential_slip.isApprox(slip, 1e-15));
  EXPECT_NEAR(c.elastic_energy, 0.5 * 1e5 * 1e-8 + 0.5 * 2e4 * slip.squaredNorm(), 1e-16);
  EXPECT_NEAR(c.dissipated_friction, ratio * eta_n * g.tangential_velocity.squaredNorm() * dt, 1e-20);
}

TEST(SpringCoulombModel, SlidingForceIsMuTimesBasisAndStoredSlipIsTruncated) {
  const double mu = 0.3, k_f = 2e4;
  const dem::PairLaw law = friction_law(friction_pair(mu, k_f, 0.0), dem::FrictionLimit::total);
  const dem::ContactGeometry g = floor_contact(1e-4, Vec3(1.0, 0.5, 0));  // F_n = 10 N
  dem::ContactHistory committed;
  committed.tangential_slip = Vec3(1e-3, 0, 0);
  const dem::ContactOutcome c = dem::evaluate_contact(law, g, committed, 1e-5);
  const Vec3 f_t = c.force_on_p - c.normal_force * g.normal;
  EXPECT_NEAR(f_t.norm(), mu * 10.0, 1e-12);
  EXPECT_NEAR(k_f * c.history.tangential_slip.norm(), mu * 10.0, 1e-12);
  EXPECT_GT(c.dissipated_friction, 0.0);
  // The committed history is an input only.
  EXPECT_EQ(committed.tangential_slip, Vec3(1e-3, 0, 0));
}

TEST(SpringCoulombModel, SlipIsCommittedSlipCarriedIntoThePlanePlusVelocityTimesElapsed) {
  const dem::PairLaw law = friction_law(friction_pair(100.0, 2e4, 0.0), dem::FrictionLimit::total);
  const dem::ContactGeometry g = floor_contact(1e-4, Vec3(0.1, 0, 0));
  dem::ContactHistory committed;
  committed.tangential_slip = Vec3(2e-6, 0, 1e-6);  // left partly out of plane by a turned normal
  for (const double elapsed : {0.0, 1e-7, 5e-7, 1e-6}) {
    const dem::ContactOutcome c = dem::evaluate_contact(law, g, committed, elapsed);
    const Vec3 expected = Vec3(std::sqrt(5e-12), 0, 0) + g.tangential_velocity * elapsed;
    EXPECT_TRUE(c.history.tangential_slip.isApprox(expected, 1e-14)) << "elapsed " << elapsed;
  }
}

TEST(SpringCoulombModel, NoForceAndNoInteractionOnceTheBodiesSeparate) {
  const dem::PairLaw law = friction_law(friction_pair(0.3, 2e4, 0.0), dem::FrictionLimit::total);
  dem::ContactHistory committed;
  committed.tangential_slip = Vec3(1e-6, 0, 0);
  const dem::ContactOutcome c = dem::evaluate_contact(law, floor_contact(-1e-5, Vec3(1, 0, 0)), committed, 1e-6);
  EXPECT_FALSE(c.interacting);
  EXPECT_EQ(c.force_on_p, Vec3::Zero());
}

TEST(SpringCoulombModel, TorqueOnTheSphereIsBranchVectorCrossTangentialForce) {
  const dem::PairLaw law = friction_law(friction_pair(0.3, 2e4, 0.0), dem::FrictionLimit::total);
  for (const bool lever_is_radius : {false, true}) {
    const dem::ContactGeometry g = floor_contact(1e-4, Vec3(1.0, 0, 0), Vec3::Zero(), lever_is_radius);
    const dem::ContactOutcome c = dem::evaluate_contact(law, g, dem::ContactHistory{}, 1e-5);
    const Vec3 f_t = c.force_on_p - c.normal_force * g.normal;
    EXPECT_TRUE(c.torque_on_p.isApprox(g.branch_p.cross(f_t), 1e-15));
    // Friction against +x motion on a floor spins the sphere up about +y (rolling forwards).
    const double lever = lever_is_radius ? kRadius : kRadius - 0.5e-4;
    EXPECT_NEAR(c.torque_on_p.y(), lever * f_t.norm(), 1e-15);
  }
}

TEST(FrictionLimitPolicy, TotalElasticAndElasticDampingBasesAreThoseOfTheStyleTable) {
  const double mu = 0.2;
  // Approaching at 1 m/s: the dashpot adds η·1 N to the elastic 10 N.
  const dem::ContactGeometry g = floor_contact(1e-4, Vec3(5.0, 0, -1.0));
  const double eta = dem::laws::restitution_damping_coefficient(0.5, kMass, 1e5);
  dem::ContactHistory committed;
  committed.tangential_slip = Vec3(1.0, 0, 0);  // far beyond the cap: always sliding
  const auto sliding_force = [&](dem::FrictionLimit policy) {
    const dem::PairLaw law = friction_law(friction_pair(mu, 2e4, 0.0, 0.5), policy, "restitution");
    const dem::ContactOutcome c = dem::evaluate_contact(law, g, committed, 0.0);
    return (c.force_on_p - c.normal_force * g.normal).norm();
  };
  EXPECT_NEAR(sliding_force(dem::FrictionLimit::total), mu * (10.0 + eta), 1e-12);
  EXPECT_NEAR(sliding_force(dem::FrictionLimit::elastic_damping), mu * (10.0 + eta), 1e-12);
  EXPECT_NEAR(sliding_force(dem::FrictionLimit::elastic), mu * 10.0, 1e-12);
  // Separating fast enough that the unclamped total force is tensile: the basis is |F_n|.
  const dem::ContactGeometry pulling = floor_contact(1e-5, Vec3(5.0, 0, 3.0));
  const dem::PairLaw law = friction_law(friction_pair(mu, 2e4, 0.0, 0.5), dem::FrictionLimit::total, "restitution");
  const dem::ContactOutcome c = dem::evaluate_contact(law, pulling, committed, 0.0);
  ASSERT_LT(c.normal_force, 0.0);
  EXPECT_NEAR((c.force_on_p - c.normal_force * pulling.normal).norm(), mu * std::abs(c.normal_force), 1e-12);
}

TEST(MindlinModel, StiffnessFollowsTheOverlapAtConstantSlip) {
  dem::PairProperties p;
  p.normal_stiffness = 1e5;
  p.effective_shear_modulus = 1e8;
  p.friction = 10.0;
  p.tangential_damping_ratio = 0.0;
  dem::ContactHistory committed;
  committed.tangential_slip = Vec3(1e-7, 0, 0);
  for (const char* model : {"mindlin", "mindlin_8g"}) {
    const double prefactor = std::string_view(model) == "mindlin" ? 16.0 / 3.0 : 8.0;
    const dem::PairLaw law = friction_law(p, dem::FrictionLimit::total, "none", model);
    for (const double d : {1e-5, 4e-5}) {
      const dem::ContactGeometry g = floor_contact(d, Vec3::Zero());
      const dem::ContactOutcome c = dem::evaluate_contact(law, g, committed, 0.0);
      const double k = prefactor * 1e8 * std::sqrt(kRadius * d);
      EXPECT_NEAR(c.force_on_p.x(), -k * 1e-7, 1e-12) << model << " δ = " << d;
    }
  }
}

TEST(MindlinModel, StiffnessChangeAndPartingEnergyAreTheSpringsEnergyAtTheKeptStiffness) {
  // A contact committed at k_then with a slip σ, evaluated at rest (no slip increment) at a new
  // overlap: the spring's energy moved by k_t alone is E(σ, k_then) − E(σ, k_now); a contact
  // that parts takes E(σ, k_then) with it. Incremental form E = c²|σ|²/(2k) (c = 8 G*, k = c a),
  // total form ½ k |ς|². Without a kept stiffness (k_then = 0, no ledger) nothing is booked.
  dem::PairProperties p;
  p.normal_stiffness = 1e5;
  p.effective_shear_modulus = 1e8;
  p.friction = 10.0;  // stuck
  p.tangential_damping_ratio = 0.0;
  const double c = 8.0 * 1e8;
  const double d_then = 1e-5, d_now = 4e-5;
  const double k_then = c * std::sqrt(kRadius * d_then), k_now = c * std::sqrt(kRadius * d_now);
  for (const dem::MindlinForm form : {dem::MindlinForm::incremental, dem::MindlinForm::total}) {
    const bool incremental = form == dem::MindlinForm::incremental;
    SCOPED_TRACE(incremental ? "incremental" : "total");
    dem::ModelChoice choice;
    choice.damping = "none";
    choice.tangential = "mindlin_8g";
    choice.mindlin_form = form;
    choice.friction_limit = dem::FrictionLimit::total;
    const dem::PairLaw law = dem::make_pair_law(choice, p);
    dem::ContactHistory committed;
    committed.tangential_slip = incremental ? Vec3(2e-10, 0, 0) : Vec3(2e-8, 0, 0);  // σ [m²] or ς [m]
    committed.tangential_stiffness = k_then;
    const double s2 = committed.tangential_slip.squaredNorm();
    const auto energy = [&](double k) { return incremental ? 0.5 * c * c * s2 / k : 0.5 * k * s2; };
    const dem::ContactOutcome c_now = dem::evaluate_contact(law, floor_contact(d_now, Vec3::Zero()), committed, 1e-6);
    EXPECT_NEAR(c_now.stiffness_change, energy(k_then) - energy(k_now), 1e-12 * energy(k_then));
    EXPECT_NEAR(c_now.history.tangential_stiffness, k_now, 1e-9 * k_now);
    // The incremental spring keeps its force while k grows, so its energy falls (> 0 booked);
    // the total form's force grows with k, so its energy rises (< 0).
    EXPECT_EQ(c_now.stiffness_change > 0.0, incremental);
    const dem::ContactOutcome parted = dem::evaluate_contact(law, floor_contact(-1e-6, Vec3::Zero()), committed, 1e-6);
    EXPECT_FALSE(parted.contact);
    EXPECT_NEAR(parted.dissipated_friction, energy(k_then), 1e-12 * energy(k_then));
    EXPECT_FALSE(parted.interacting);  // its history is dropped
    dem::ContactHistory unkept = committed;
    unkept.tangential_stiffness = 0.0;
    EXPECT_EQ(dem::evaluate_contact(law, floor_contact(d_now, Vec3::Zero()), unkept, 1e-6).stiffness_change, 0.0);
    EXPECT_EQ(dem::evaluate_contact(law, floor_contact(-1e-6, Vec3::Zero()), unkept, 1e-6).dissipated_friction, 0.0);
  }
}

TEST(TangentialRegistry, EveryTangentialAndRollingModelIsRegisteredWithItsProperties) {
  const auto* sc = dem::find_sub_model(dem::Slot::tangential, "spring_coulomb");
  ASSERT_NE(sc, nullptr);
  EXPECT_EQ(sc->properties.size(), 3U);
  EXPECT_NE(dem::find_sub_model(dem::Slot::tangential, "mindlin"), nullptr);
  EXPECT_NE(dem::find_sub_model(dem::Slot::tangential, "mindlin_8g"), nullptr);
  EXPECT_NE(dem::find_sub_model(dem::Slot::rolling, "constant_torque"), nullptr);
  EXPECT_NE(dem::find_sub_model(dem::Slot::rolling, "spring_dashpot_slider"), nullptr);
}

TEST(TangentialRegistry, MissingDampingRatioIsAnErrorNotASilentZero) {
  dem::PairProperties p = friction_pair(0.3, 2e4, 0.0);
  p.tangential_damping_ratio.reset();
  EXPECT_THROW(static_cast<void>(friction_law(p, dem::FrictionLimit::total)), dem::ModelError);
}

}  // namespace
