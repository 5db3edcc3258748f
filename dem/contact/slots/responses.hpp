// SPDX-License-Identifier: MIT
#pragma once

#include "dem/contact/contact_geometry.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/model_choice.hpp"

// What the sub-models of each slot receive and return. Every sub-model of a slot offers the
// same member functions (see contact_model.hpp for the order they are called in):
//   normal:     NormalResponse evaluate(const ContactInput&, ContactHistory& next) const noexcept
//               double range(const PairExtent&) const noexcept          (largest centre distance)
//               double collision_stiffness(const CollisionScale&) const noexcept
//   cohesion:   CohesionResponse evaluate(const ContactInput&, const NormalResponse&,
//                                         ContactHistory& next) const noexcept
//               double range(const PairExtent&) const noexcept
//   damping:    double coefficient(const ContactGeometry&, const NormalResponse&) const noexcept
//   tangential: TangentialResponse evaluate(const ContactInput&, const TangentialInput&,
//                                           ContactHistory& next) const noexcept
//   rolling:    RollingResponse evaluate(const ContactInput&, const RollingInput&,
//                                        ContactHistory& next) const noexcept
namespace dem {

/// The named policies of a contact model that sub-models may consult (from ModelChoice).
struct ContactPolicies {
  bool clamp_tensile = false;
  FrictionLimit friction_limit = FrictionLimit::total;
  JkrRupture jkr_rupture = JkrRupture::displacement;
  bool contact_at_zero_overlap = false;  ///< δ = 0 counts as contact (ModelChoice)
  TangentialHistory tangential_history = TangentialHistory::project_rescale;
  MindlinRadius mindlin_radius = MindlinRadius::overlap;
  UnloadedSlider unloaded_slider = UnloadedSlider::cap;
  AdhesiveDashpot adhesive_dashpot = AdhesiveDashpot::clamp;
  MindlinForm mindlin_form = MindlinForm::total;
  CoulombTest coulomb_test = CoulombTest::total;
  ConstantTorqueForm constant_torque_form = ConstantTorqueForm::tangent;
};

/// Everything a sub-model may read about one contact at one evaluation.
struct ContactInput {
  const ContactGeometry& g;
  const ContactHistory& committed;  ///< history at the last commit
  double elapsed;                   ///< time since that commit [s]
  const ContactPolicies& policies;
};

/// What a normal sub-model returns.
struct NormalResponse {
  double force = 0.0;      ///< elastic normal force [N], repulsive positive
  double stiffness = 0.0;  ///< dF/dδ at this overlap [N/m], used by damping sub-models
  double energy = 0.0;     ///< elastic energy stored in the contact [J]
  bool active = false;     ///< the law acts at this distance (δ > 0 for contact laws)
  double dissipated = 0.0; ///< plastic work since the last commit [J], ≥ 0 (hysteretic laws)
};

/// What a cohesion sub-model returns.
struct CohesionResponse {
  double force = 0.0;          ///< cohesive normal force [N], attractive negative
  double energy = 0.0;         ///< cohesive potential energy [J] (≤ 0 when attracting)
  bool active = false;         ///< the pair still interacts (keeps its history)
  bool contact = false;        ///< a physical contact exists (e.g. a JKR neck at δ < 0)
  double pulloff_force = 0.0;  ///< magnitude of the pull-off force, for FrictionLimit::jkr_shifted
  /// Radius a of the contact area when the cohesion law sets it (an attached JKR contact), else
  /// 0. LAMMPS' dashpots read it under JKR (docs/physics-cohesion.md).
  double contact_radius = 0.0;
  /// (4/3) E* a: the Hertz secant stiffness of a contact of radius a, LAMMPS' `knfac` under JKR
  /// [N/m] (0 when contact_radius is 0).
  double radius_stiffness = 0.0;
  /// Energy released by a jump of the potential at this evaluation [J]: a JKR neck that snaps
  /// in (−U(0) > 0) or breaks (U at the break overlap: > 0 at δ_c, < 0 at the load-controlled
  /// δ_f, where breaking puts |U| back).
  double released = 0.0;
};

/// Normal-force information the tangential sub-model uses.
struct TangentialInput {
  const NormalResponse& elastic;
  double damping_coefficient;  ///< normal dashpot η_n [kg/s] of this contact
  double limit_basis;          ///< the normal force the Coulomb limit is based on [N], ≥ 0
  double contact_radius = 0.0; ///< the cohesion law's contact radius a [m], 0 when it sets none
};

/// Normal-force information the rolling sub-model uses.
struct RollingInput {
  double limit_basis;    ///< the normal force the Coulomb limit is based on [N], ≥ 0
  double elastic_force;  ///< the elastic normal force [N] (ConstantTorqueForm::projected)
};

/// What a tangential sub-model returns.
struct TangentialResponse {
  Vec3 force = Vec3::Zero();  ///< tangential force on p [N]
  double energy = 0.0;        ///< elastic energy of the tangential spring [J]
  double dissipated = 0.0;    ///< energy dissipated since the last commit [J], ≥ 0
  /// Energy the spring lost since the last commit because its stiffness changed (a Mindlin k_t
  /// following the overlap): E(carried slip, k_t then) − E(carried slip, k_t now) [J], signed.
  double stiffness_change = 0.0;
};

/// What a rolling sub-model returns.
struct RollingResponse {
  Vec3 torque_p = Vec3::Zero();  ///< rolling-resistance torque on p [N·m]
  Vec3 torque_q = Vec3::Zero();  ///< on q
  double dissipated = 0.0;       ///< energy dissipated since the last commit [J], ≥ 0
  double energy = 0.0;           ///< energy stored in a rolling spring [J]
};

/// The scale of a collision, for time-step control: a Hertz contact stiffens with overlap.
struct CollisionScale {
  double reduced_mass;    ///< m* [kg]
  double reduced_radius;  ///< R* [m]
  double impact_speed;    ///< largest expected normal approach speed [m/s]
};

}  // namespace dem
