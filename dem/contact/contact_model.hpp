// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <variant>

#include "dem/contact/contact_geometry.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/model_choice.hpp"
#include "dem/contact/slots/damping_restitution.hpp"
#include "dem/contact/slots/none.hpp"
#include "dem/contact/slots/normal_linear.hpp"

namespace dem {

/// Run-time choice of the normal sub-model (one alternative per registry row).
using NormalModel = std::variant<LinearNormal>;
/// Run-time choice of the normal damping sub-model.
using DampingModel = std::variant<NoDamping, RestitutionDamping>;
/// Run-time choice of the tangential sub-model.
using TangentialModel = std::variant<NoTangential>;
/// Run-time choice of the cohesion sub-model.
using CohesionModel = std::variant<NoCohesion>;
/// Run-time choice of the rolling-resistance sub-model.
using RollingModel = std::variant<NoRolling>;

/// The contact law of one material pair: one sub-model per slot, each holding its mixed
/// parameters (STYLE.md "a contact model is a composition of named slots").
struct PairLaw {
  NormalModel normal;
  DampingModel damping;
  TangentialModel tangential;
  CohesionModel cohesion;
  RollingModel rolling;
};

/// Result of evaluating one pair: forces, torques and the proposed new history.
struct ContactOutcome {
  bool interacting = false;  ///< the pair is in contact; its history must be kept
  double normal_force = 0.0; ///< total normal force [N], repulsive positive
  double elastic_energy = 0.0; ///< energy stored in the contact [J]
  Vec3 force_on_p = Vec3::Zero();   ///< force on p [N]; q receives the opposite
  Vec3 torque_on_p = Vec3::Zero();  ///< torque on p about its centre [N·m]
  Vec3 torque_on_q = Vec3::Zero();  ///< torque on q about its centre [N·m]
  ContactHistory history;           ///< history after this evaluation
};

/// Evaluates the contact law of one pair. The order reads top to bottom:
/// normal → damping → (cohesion, friction limit, tangential, rolling: none yet) → assemble.
/// `committed` is the history at the last commit, `elapsed` the time since then [s].
[[nodiscard]] inline ContactOutcome evaluate_contact(const PairLaw& law, const ContactGeometry& g,
                                                     const ContactHistory& committed,
                                                     double elapsed) noexcept {
  static_cast<void>(elapsed);  // read by history-carrying tangential sub-models (issue #3)
  ContactOutcome out;
  if (g.overlap <= 0.0) return out;  // a contact exists only while δ > 0 strictly

  const NormalResponse elastic =
      std::visit([&](const auto& m) { return m.evaluate(g); }, law.normal);
  const double damping =
      std::visit([&](const auto& m) { return m.force(g, elastic); }, law.damping);

  out.interacting = true;
  out.normal_force = elastic.force + damping;
  out.elastic_energy = elastic.energy;
  out.force_on_p = out.normal_force * g.normal;
  out.history = committed;
  out.history.max_overlap = std::max(committed.max_overlap, g.overlap);
  return out;
}

/// Damping coefficient η [kg/s] of the pair law at overlap δ (for time-step control and reports).
[[nodiscard]] inline double damping_coefficient(const PairLaw& law, const ContactGeometry& g) {
  const NormalResponse elastic =
      std::visit([&](const auto& m) { return m.evaluate(g); }, law.normal);
  return std::visit([&](const auto& m) { return m.coefficient(g, elastic); }, law.damping);
}

}  // namespace dem
