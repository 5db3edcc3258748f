// SPDX-License-Identifier: MIT
// The batched contact kernel against evaluate_contact, bit for bit, on seeded random pairs under
// every policy it accepts: the pair loop swaps one for the other depending on whether a run keeps
// an energy ledger, so any difference would make a ledger change a trajectory.
#include "dem/forces/contact_batch.hpp"
#include "dem/forces/pair_loop.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <iostream>
#include <memory>
#include <vector>
#include <cstdint>
#include <random>
#include <string>

#include "dem/contact/contact_geometry.hpp"
#include "dem/contact/contact_model.hpp"
#include "dem/contact/laws/dashpot_restitution.hpp"
#include "dem/contact/laws/hertz.hpp"

namespace {

/// One combination of the policies the kernel reads.
struct Case {
  dem::BatchLawKind normal;
  dem::PairLeverArm arm;
  dem::TangentialHistory history;
  dem::FrictionLimit limit;
  bool clamp;
  bool zero_overlap;
  dem::UnloadedSlider unloaded;
  dem::MindlinForm form = dem::MindlinForm::incremental;  ///< of the hertz_mindlin family
};

/// Bits of a double, so that −0 and +0 (and the payload of a NaN) count as different.
std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

/// A random pair and its committed slip, covering the kernel's branches: touching, apart,
/// exactly touching, fixed partners, a new contact (zero slip), slips that slide and that stick,
/// and slips with a part along the normal.
struct RandomPair {
  dem::SphereState p, q;
  dem::Vec3 slip;
};

/// `slip_scale` sets the committed slips' size: 1 for a displacement [m], smaller for Mindlin's
/// incremental history σ = −F/c [m²].
RandomPair random_pair(std::mt19937_64& rng, double slip_scale) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> size(0.5e-3, 2.0e-3);
  std::uniform_int_distribution<int> pick(0, 9);
  const auto vec = [&](double scale) { return dem::Vec3(dem::Vec3(unit(rng), unit(rng), unit(rng)) * scale); };
  RandomPair r;
  r.p.radius = size(rng);
  r.q.radius = size(rng);
  r.p.effect_radius = r.p.radius;
  r.q.effect_radius = r.q.radius;
  r.p.inverse_mass = pick(rng) == 0 ? 0.0 : 1.0 / (1e-6 * size(rng) / 1e-3);
  r.q.inverse_mass = pick(rng) <= 1 ? 0.0 : 1.0 / (1e-6 * size(rng) / 1e-3);
  dem::Vec3 direction = vec(1.0);
  direction.normalize();
  const int kind = pick(rng);
  const double contact = r.p.radius + r.q.radius;
  double distance = contact * (1.0 - 0.05 * std::abs(unit(rng)));  // touching
  if (kind == 0) distance = contact * (1.0 + 0.05 * std::abs(unit(rng)));  // apart
  r.q.position = vec(1e-2);
  r.p.position = r.q.position + distance * direction;
  if (kind == 1) {  // exactly touching along an axis
    r.q.position = dem::Vec3(0.0, 0.0, 0.0);
    r.p.position = dem::Vec3(0.0, 0.0, contact);
  }
  r.p.velocity = vec(2.0);
  r.q.velocity = vec(2.0);
  r.p.angular_velocity = vec(500.0);
  r.q.angular_velocity = vec(500.0);
  const int slip_kind = pick(rng);
  r.slip = slip_kind == 0 ? dem::Vec3(dem::Vec3::Zero()) : dem::Vec3(vec(slip_scale * (slip_kind <= 4 ? 1e-7 : 1e-4)));
  return r;
}

dem::PairLaw law_for(const Case& c, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  dem::PairLaw law;
  const double ratio = unit(rng) < 0.3 ? 0.0 : unit(rng);
  if (c.normal == dem::BatchLawKind::hertz_mindlin) {
    const double modulus = 1e8 + 1e9 * unit(rng);
    law.normal = dem::HertzNormal{modulus};
    const double e = 0.05 + 0.95 * unit(rng);
    law.damping = dem::TsujiDamping{e, dem::laws::tsuji_factor(e)};
    const double shear = unit(rng) < 0.1 ? 0.0 : modulus / (2.0 + unit(rng));
    law.tangential = dem::Mindlin8GTangential{{shear, unit(rng) < 0.1 ? 0.0 : unit(rng), ratio}};
    law.policies.mindlin_form = c.form;
  } else {
    if (c.normal == dem::BatchLawKind::linear) {
      law.normal = dem::LinearNormal{1e4 + 1e5 * unit(rng)};
    } else {
      law.normal = dem::HertzNormal{1e8 + 1e9 * unit(rng)};
    }
    law.damping = dem::LammpsMassVelocityDamping{100.0 * unit(rng)};
    const double kt = unit(rng) < 0.1 ? 0.0 : 1e4 * unit(rng);
    law.tangential = dem::SpringCoulombTangential{kt, unit(rng) < 0.1 ? 0.0 : unit(rng), ratio};
  }
  law.cohesion = dem::NoCohesion{};
  law.rolling = dem::NoRolling{};
  law.policies.tangential_history = c.history;
  law.policies.friction_limit = c.limit;
  law.policies.clamp_tensile = c.clamp;
  law.policies.contact_at_zero_overlap = c.zero_overlap;
  law.policies.unloaded_slider = c.unloaded;
  return law;
}

/// Tallies of the branches the random pairs reached.
struct Reached {
  int sliding = 0;
  int sticking = 0;
  int apart = 0;
  int dropped = 0;  ///< an unloaded slider over the cap whose force UnloadedSlider::zero removed
};

/// Evaluates `lanes` random pairs of one case both ways and compares every output bit. With
/// `elapsed` 0 a pair with no committed slip is a first evaluation (what UnloadedSlider is about).
void check_case(const Case& c, std::uint64_t seed, std::uint32_t lanes, double elapsed, Reached& reached) {
  std::mt19937_64 rng(seed);
  auto batch = std::make_unique<dem::ContactBatch>();
  std::vector<RandomPair> pairs;
  std::vector<dem::PairLaw> laws;
  // The kernel's policies and parameters as the pair loop gives them (every law of a case has its
  // policies); the comparison with evaluate_contact below checks that mapping too.
  dem::BatchPolicies policies;
  for (std::uint32_t g = 0; g < lanes; ++g) {
    const bool incremental = c.normal == dem::BatchLawKind::hertz_mindlin && c.form == dem::MindlinForm::incremental;
    pairs.push_back(random_pair(rng, incremental ? 1e-5 : 1.0));
    laws.push_back(law_for(c, rng));
    policies = dem::batch_policies(c.normal, laws.back().policies, c.arm);
    const RandomPair& r = pairs.back();
    dem::ContactBatch& b = *batch;
    const dem::Vec3 d = r.p.position - r.q.position;
    dem::set_lane(b.dx, b.dy, b.dz, g, d.data());
    b.rp[g] = r.p.radius;
    b.rq[g] = r.q.radius;
    b.mp[g] = r.p.inverse_mass;
    b.mq[g] = r.q.inverse_mass;
    dem::set_lane(b.upx, b.upy, b.upz, g, r.p.velocity.data());
    dem::set_lane(b.uqx, b.uqy, b.uqz, g, r.q.velocity.data());
    dem::set_lane(b.wpx, b.wpy, b.wpz, g, r.p.angular_velocity.data());
    dem::set_lane(b.wqx, b.wqy, b.wqz, g, r.q.angular_velocity.data());
    dem::set_lane(b.sx, b.sy, b.sz, g, r.slip.data());
    dem::set_law(b, g, dem::batch_law_of(laws.back()));
  }
  dem::evaluate_contact_batch(*batch, lanes, policies, elapsed);
  for (std::uint32_t g = 0; g < lanes; ++g) {
    const RandomPair& r = pairs[g];
    dem::ContactHistory committed;
    committed.tangential_slip = r.slip;
    const dem::ContactGeometry geometry = dem::pair_geometry(r.p, r.q, c.arm);
    const dem::ContactOutcome o = dem::evaluate_contact(laws[g], geometry, committed, elapsed);
    const dem::ContactBatch& b = *batch;
    SCOPED_TRACE("seed " + std::to_string(seed) + " lane " + std::to_string(g));
    ASSERT_EQ(dem::batch_contact(b, g, policies), o.contact);
    ASSERT_EQ(o.contact, o.interacting);
    EXPECT_EQ(bits(b.overlap[g]), bits(geometry.overlap));
    if (!o.contact) {
      ++reached.apart;
      continue;
    }
    // Sliding when the tangential force sits at the Coulomb cap μ·basis.
    const double elastic = c.normal == dem::BatchLawKind::linear
                               ? std::get<dem::LinearNormal>(laws[g].normal).stiffness * geometry.overlap
                               : dem::laws::hertz_force(std::get<dem::HertzNormal>(laws[g].normal).effective_modulus,
                                                        geometry.reduced_radius, geometry.overlap);
    const double basis = c.limit == dem::FrictionLimit::elastic ? std::abs(elastic) : std::abs(elastic + o.damping_force);
    const double friction = std::visit(
        [](const auto& t) {
          if constexpr (requires { t.p.friction; }) {
            return t.p.friction;
          } else if constexpr (requires { t.friction; }) {
            return t.friction;
          } else {
            return 0.0;
          }
        },
        laws[g].tangential);
    const double cap = friction * basis;
    const double tangential = (o.force_on_p - o.normal_force * geometry.normal).norm();
    const bool slid = cap > 0.0 && tangential >= cap * (1.0 - 1e-9);
    (slid ? reached.sliding : reached.sticking) += 1;
    if (c.unloaded == dem::UnloadedSlider::zero && tangential == 0.0) {
      dem::PairLaw capping = laws[g];
      capping.policies.unloaded_slider = dem::UnloadedSlider::cap;
      const dem::ContactOutcome o_cap = dem::evaluate_contact(capping, geometry, committed, elapsed);
      if ((o_cap.force_on_p - o_cap.normal_force * geometry.normal).norm() > 0.0) ++reached.dropped;
    }
    EXPECT_EQ(bits(b.fx[g]), bits(o.force_on_p[0]));
    EXPECT_EQ(bits(b.fy[g]), bits(o.force_on_p[1]));
    EXPECT_EQ(bits(b.fz[g]), bits(o.force_on_p[2]));
    EXPECT_EQ(bits(b.tpx[g]), bits(o.torque_on_p[0]));
    EXPECT_EQ(bits(b.tpy[g]), bits(o.torque_on_p[1]));
    EXPECT_EQ(bits(b.tpz[g]), bits(o.torque_on_p[2]));
    EXPECT_EQ(bits(b.tqx[g]), bits(o.torque_on_q[0]));
    EXPECT_EQ(bits(b.tqy[g]), bits(o.torque_on_q[1]));
    EXPECT_EQ(bits(b.tqz[g]), bits(o.torque_on_q[2]));
    EXPECT_EQ(bits(b.sx[g]), bits(o.history.tangential_slip[0]));
    EXPECT_EQ(bits(b.sy[g]), bits(o.history.tangential_slip[1]));
    EXPECT_EQ(bits(b.sz[g]), bits(o.history.tangential_slip[2]));
  }
}

TEST(ContactBatch, MatchesEvaluateContactBitForBitUnderEveryPolicy) {
  Reached reached;  // the spring–Coulomb families
  Reached mindlin;  // Hertz with Tsuji's dashpot and incremental Mindlin friction
  Reached total;    // the same with Mindlin friction in the total form
  std::uint64_t seed = 20261204;
  for (const auto& [normal, form] : {std::pair{dem::BatchLawKind::linear, dem::MindlinForm::incremental},
                                    std::pair{dem::BatchLawKind::hertz, dem::MindlinForm::incremental},
                                    std::pair{dem::BatchLawKind::hertz_mindlin, dem::MindlinForm::incremental},
                                    std::pair{dem::BatchLawKind::hertz_mindlin, dem::MindlinForm::total}}) {
    for (const auto arm : {dem::PairLeverArm::contact_point, dem::PairLeverArm::radius,
                           dem::PairLeverArm::radius_velocity}) {
      // The r contact velocity with r − δ/2 lever arms: the Mindlin family's only.
      if (arm == dem::PairLeverArm::radius_velocity && normal != dem::BatchLawKind::hertz_mindlin) continue;
      for (const auto history : {dem::TangentialHistory::project_rescale, dem::TangentialHistory::increment_project}) {
        for (const auto limit : {dem::FrictionLimit::total, dem::FrictionLimit::elastic,
                                 dem::FrictionLimit::elastic_damping, dem::FrictionLimit::jkr_shifted,
                                 dem::FrictionLimit::total_plus_pulloff}) {
          for (const bool clamp : {false, true}) {
            for (const bool zero_overlap : {false, true}) {
              for (const auto unloaded : {dem::UnloadedSlider::cap, dem::UnloadedSlider::zero}) {
                const Case c{normal, arm, history, limit, clamp, zero_overlap, unloaded, form};
                // Batches of every length up to a full one, so the vector loops' tails run too;
                // one step into the contact, and at its first evaluation (elapsed 0).
                const auto lanes = static_cast<std::uint32_t>(1 + seed % dem::kContactBatch);
                Reached& tally = normal != dem::BatchLawKind::hertz_mindlin ? reached
                                 : form == dem::MindlinForm::total                ? total
                                                                                  : mindlin;
                check_case(c, seed++, lanes, 1e-6, tally);
                check_case(c, seed++, dem::kContactBatch, 1e-6, tally);
                check_case(c, seed++, dem::kContactBatch, 0.0, tally);
              }
            }
          }
        }
      }
    }
  }
  // The random pairs reached every branch the comparison is about.
  EXPECT_GT(reached.sliding, 1000);
  EXPECT_GT(reached.sticking, 1000);
  EXPECT_GT(reached.apart, 1000);
  EXPECT_GT(reached.dropped, 20);
  EXPECT_GT(mindlin.sliding, 1000);
  EXPECT_GT(mindlin.sticking, 1000);
  EXPECT_GT(mindlin.apart, 1000);
  EXPECT_GT(mindlin.dropped, 20);
  EXPECT_GT(total.sliding, 1000);
  EXPECT_GT(total.sticking, 1000);
  EXPECT_GT(total.apart, 1000);
  EXPECT_GT(total.dropped, 20);
  std::cout << "spring-Coulomb: " << reached.sliding << " sliding, " << reached.sticking << " sticking, " << reached.apart
            << " apart, " << reached.dropped << " dropped; Mindlin: " << mindlin.sliding << ", " << mindlin.sticking
            << ", " << mindlin.apart << ", " << mindlin.dropped << "; total-form Mindlin: " << total.sliding << ", "
            << total.sticking << ", " << total.apart << ", " << total.dropped << "\n";
}

}  // namespace
