// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <variant>

#include "dem/contact/contact_geometry.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/model_choice.hpp"
#include "dem/contact/slots/cohesion_coulomb.hpp"
#include "dem/contact/slots/cohesion_dmt.hpp"
#include "dem/contact/slots/cohesion_jkr.hpp"
#include "dem/contact/slots/cohesion_linear.hpp"
#include "dem/contact/slots/damping_kuwabara_kono.hpp"
#include "dem/contact/slots/damping_lammps_mass_velocity.hpp"
#include "dem/contact/slots/damping_lammps_tsuji.hpp"
#include "dem/contact/slots/damping_lammps_velocity.hpp"
#include "dem/contact/slots/damping_lammps_viscoelastic.hpp"
#include "dem/contact/slots/damping_restitution.hpp"
#include "dem/contact/slots/damping_tsuji.hpp"
#include "dem/contact/slots/damping_yade_frictvisco.hpp"
#include "dem/contact/slots/damping_yade_mindlin.hpp"
#include "dem/contact/slots/damping_yade_viscel.hpp"
#include "dem/contact/slots/none.hpp"
#include "dem/contact/slots/normal_hertz.hpp"
#include "dem/contact/slots/normal_hysteretic.hpp"
#include "dem/contact/slots/normal_linear.hpp"
#include "dem/contact/slots/normal_potential.hpp"
#include "dem/contact/slots/responses.hpp"
#include "dem/contact/slots/rolling_constant_torque.hpp"
#include "dem/contact/slots/rolling_spring_dashpot_slider.hpp"
#include "dem/contact/slots/tangential_mindlin.hpp"
#include "dem/contact/slots/tangential_spring_coulomb.hpp"

namespace dem {

/// Run-time choice of the normal sub-model (one alternative per registry row).
using NormalModel = std::variant<LinearNormal, HertzNormal, HystereticNormal, PotentialNormal>;
/// Run-time choice of the normal damping sub-model.
using DampingModel =
    std::variant<NoDamping, RestitutionDamping, TsujiDamping, KuwabaraKonoDamping,
                 LammpsVelocityDamping, LammpsMassVelocityDamping, LammpsViscoelasticDamping,
                 LammpsTsujiDamping, YadeViscElDamping, YadeMindlinDamping,
                 YadeFrictViscoDamping>;
/// Run-time choice of the tangential sub-model.
using TangentialModel =
    std::variant<NoTangential, SpringCoulombTangential, MindlinTangential, Mindlin8GTangential>;
/// Run-time choice of the cohesion sub-model.
using CohesionModel =
    std::variant<NoCohesion, LinearCohesion, JkrCohesion, DmtCohesion, CoulombCohesion>;
/// Run-time choice of the rolling-resistance sub-model.
using RollingModel = std::variant<NoRolling, ConstantTorqueRolling, SpringDashpotSliderRolling>;

/// The contact law of one material pair: one sub-model per slot, each holding its mixed
/// parameters, plus the model's policies (docs/architecture.md, "The contact model").
struct PairLaw {
  NormalModel normal;
  DampingModel damping;
  TangentialModel tangential;
  CohesionModel cohesion;
  RollingModel rolling;
  ContactPolicies policies;
};

/// Result of evaluating one pair: forces, torques, energies and the proposed new history.
struct ContactOutcome {
  bool interacting = false;          ///< the pair interacts; its history must be kept
  bool contact = false;              ///< the bodies touch (δ > 0, or a JKR neck)
  double normal_force = 0.0;         ///< total normal force [N], repulsive positive
  double elastic_energy = 0.0;       ///< normal and tangential spring energy [J]
  double cohesive_energy = 0.0;      ///< cohesive potential energy [J]
  double damping_force = 0.0;        ///< dashpot force along the normal on p [N] (after the clamp)
  double dissipated_adhesion = 0.0;  ///< energy released by a JKR snap-in or rupture at this evaluation [J] (signed)
  double dissipated_plastic = 0.0;   ///< plastic work of a hysteretic normal law since the last commit [J]
  double dissipated_friction = 0.0;  ///< sliding and rolling work since the last commit [J], ≥ 0
  double stiffness_change = 0.0;     ///< TangentialResponse::stiffness_change [J], signed
  Vec3 force_on_p = Vec3::Zero();    ///< force on p [N]; q receives the opposite
  Vec3 torque_on_p = Vec3::Zero();   ///< torque on p about its centre [N·m]
  Vec3 torque_on_q = Vec3::Zero();   ///< torque on q about its centre [N·m]
  ContactHistory history;            ///< history after this evaluation
};

/// The normal force the Coulomb limit is based on, per policy (docs/physics-tangential.md, friction-limit basis).
[[nodiscard]] inline double friction_limit_basis(FrictionLimit policy, double elastic,
                                                 double damping, double cohesion,
                                                 double pulloff) noexcept {
  switch (policy) {
    case FrictionLimit::elastic: return std::abs(elastic);
    case FrictionLimit::elastic_damping: return std::abs(elastic + damping);
    case FrictionLimit::jkr_shifted:
      // LAMMPS' rule: an adhesive contact's limit is shifted by twice the pull-off force and
      // leaves the dashpot out; a contact without adhesion keeps elastic + damping.
      return pulloff > 0.0 ? std::abs(elastic + cohesion + 2.0 * pulloff) : std::abs(elastic + damping);
    case FrictionLimit::total_plus_pulloff:
      // YADE's Mindlin with adhesion: the whole normal force's magnitude plus the pull-off force.
      return std::abs(elastic + damping + cohesion) + pulloff;
    case FrictionLimit::total: break;
  }
  return std::abs(elastic + damping + cohesion);
}

/// A pair law whose sub-models are found at run time: each slot is one std::visit. What
/// evaluate_contact uses.
struct DynamicSlots {
  const PairLaw& law;
  template <class F> decltype(auto) normal(F&& f) const { return std::visit(f, law.normal); }
  template <class F> decltype(auto) damping(F&& f) const { return std::visit(f, law.damping); }
  template <class F> decltype(auto) tangential(F&& f) const { return std::visit(f, law.tangential); }
  template <class F> decltype(auto) cohesion(F&& f) const { return std::visit(f, law.cohesion); }
  template <class F> decltype(auto) rolling(F&& f) const { return std::visit(f, law.rolling); }
};

/// A pair law whose sub-model types N, D, T, C, R are known at compile time, so that the
/// evaluation compiles to straight-line code (the many-body pair loop's fast path). The caller
/// guarantees the law holds these alternatives (holds()).
template <class N, class D, class T, class C, class R>
struct StaticSlots {
  const PairLaw& law;
  template <class F> decltype(auto) normal(F&& f) const { return f(*std::get_if<N>(&law.normal)); }
  template <class F> decltype(auto) damping(F&& f) const { return f(*std::get_if<D>(&law.damping)); }
  template <class F> decltype(auto) tangential(F&& f) const { return f(*std::get_if<T>(&law.tangential)); }
  template <class F> decltype(auto) cohesion(F&& f) const { return f(*std::get_if<C>(&law.cohesion)); }
  template <class F> decltype(auto) rolling(F&& f) const { return f(*std::get_if<R>(&law.rolling)); }
  /// True when `l` holds exactly these sub-model types.
  [[nodiscard]] static bool holds(const PairLaw& l) noexcept {
    return std::holds_alternative<N>(l.normal) && std::holds_alternative<D>(l.damping) &&
           std::holds_alternative<T>(l.tangential) && std::holds_alternative<C>(l.cohesion) &&
           std::holds_alternative<R>(l.rolling);
  }
};

/// Evaluates the contact law of one pair through `slots` (DynamicSlots or StaticSlots: the same
/// arithmetic either way, the second without dispatch). The order reads top to bottom:
/// normal → cohesion → damping (→ clamp) → friction limit → tangential → rolling → assemble.
/// `committed` is the history at the last commit, `elapsed` the time since then [s].
template <class Slots>
[[nodiscard]] inline ContactOutcome evaluate_contact_in(const Slots& slots, const ContactGeometry& g,
                                                        const ContactHistory& committed,
                                                        double elapsed) noexcept {
  const ContactPolicies& policies = slots.law.policies;
  ContactOutcome out;
  out.history = committed;
  ContactHistory& next = out.history;
  const ContactInput in{g, committed, elapsed, policies};

  const NormalResponse elastic = slots.normal([&](const auto& m) { return m.evaluate(in, next); });
  const CohesionResponse cohesion = slots.cohesion([&](const auto& m) { return m.evaluate(in, elastic, next); });
  out.contact = g.overlap > 0.0 || (policies.contact_at_zero_overlap && g.overlap == 0.0) ||
                cohesion.contact;
  out.interacting = out.contact || elastic.active || cohesion.active;
  out.dissipated_adhesion = cohesion.released;
  out.dissipated_plastic = elastic.dissipated;
  if (!out.contact) {
    // Parted: the history goes, and with it what the tangential and rolling springs still held.
    const auto released = [&](const auto& m) {
      if constexpr (requires { m.released_at_separation(in); }) {
        return m.released_at_separation(in);
      } else {
        return 0.0;
      }
    };
    out.dissipated_friction = slots.tangential(released) + slots.rolling(released);
  }
  if (!out.interacting) return out;

  // Two infinite masses (a fixed sphere driven against another, m* = ∞): a dashpot scaled by m*
  // is undefined and could change no motion anyway, so such a contact reports no damping.
  const double eta = out.contact && std::isfinite(g.reduced_mass)
                         ? slots.damping([&](const auto& m) {
                             // A dashpot that reads the cohesion law's contact radius (LAMMPS' under JKR).
                             if constexpr (requires { m.coefficient(g, elastic, cohesion); }) {
                               return m.coefficient(g, elastic, cohesion);
                             } else {
                               return m.coefficient(g, elastic);
                             }
                           })
                         : 0.0;
  double damping = -eta * g.normal_speed;
  if (policies.adhesive_dashpot == AdhesiveDashpot::pulloff_cap && cohesion.pulloff_force > 0.0) {
    // YADE's Mindlin with adhesion: a dashpot that leaves the whole normal force tensile acts
    // with at most the pull-off force.
    if (elastic.force + cohesion.force + damping < 0.0 && std::abs(damping) > cohesion.pulloff_force) {
      damping = std::copysign(cohesion.pulloff_force, damping);
    }
  } else if (policies.clamp_tensile && elastic.force + damping < 0.0) {
    damping = -elastic.force;
  }
  out.normal_force = elastic.force + damping + cohesion.force;

  TangentialResponse tangential;
  RollingResponse rolling;
  if (out.contact) {
    const double basis = friction_limit_basis(policies.friction_limit, elastic.force, damping,
                                              cohesion.force, cohesion.pulloff_force);
    const TangentialInput t_in{elastic, eta, basis, cohesion.contact_radius};
    tangential = slots.tangential([&](const auto& m) { return m.evaluate(in, t_in, next); });
    const RollingInput r_in{basis, elastic.force};
    rolling = slots.rolling([&](const auto& m) { return m.evaluate(in, r_in, next); });
    next.max_overlap = std::max(committed.max_overlap, g.overlap);
    next.normal = g.normal;
  } else {
    // Apart (a long-range law may keep the pair interacting): the next touch is a new contact,
    // so its springs start unloaded and its largest overlap afresh (eq 3.20).
    next.tangential_slip.setZero();
    next.rolling_slip.setZero();
    next.max_overlap = 0.0;
    next.normal.setZero();
    next.tangential_stiffness = 0.0;
  }

  out.force_on_p = out.normal_force * g.normal + tangential.force;
  out.torque_on_p = g.branch_p.cross(tangential.force) + rolling.torque_p;
  out.torque_on_q = g.branch_q.cross(-tangential.force) + rolling.torque_q;
  out.elastic_energy = elastic.energy + tangential.energy + rolling.energy;
  out.cohesive_energy = cohesion.energy;
  out.damping_force = damping;
  out.dissipated_friction += tangential.dissipated + rolling.dissipated;
  out.stiffness_change = tangential.stiffness_change;
  return out;
}

/// Evaluates the contact law of one pair (the one per-pair evaluator: every engine path, every
/// pair and wall contact goes through evaluate_contact_in). See evaluate_contact_in. Defined
/// out of line: instantiating every std::visit of the dynamic dispatch is slow to compile, and
/// one translation unit does it for all.
[[nodiscard]] ContactOutcome evaluate_contact(const PairLaw& law, const ContactGeometry& g,
                                              const ContactHistory& committed, double elapsed) noexcept;

/// Largest centre distance at which the law of a pair with extent `e` acts (neighbour search).
[[nodiscard]] double interaction_range(const PairLaw& law, const PairExtent& e) noexcept;

/// Normal stiffness that sets the contact time scale of a collision of the given scale.
[[nodiscard]] double collision_stiffness(const PairLaw& law, const CollisionScale& s) noexcept;

/// Damping coefficient η [kg/s] of the law with tangent stiffness k and reduced mass m*.
[[nodiscard]] double damping_coefficient(const PairLaw& law, double reduced_mass, double stiffness) noexcept;

}  // namespace dem
