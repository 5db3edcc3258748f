// SPDX-License-Identifier: MIT
#include "dem/forces/contact_force_field.hpp"

#include "dem/contact/contact_geometry.hpp"
#include "dem/contact/contact_model.hpp"
#include "dem/neighbors/all_pairs.hpp"

namespace dem {
namespace {

SphereState sphere(const ParticleProperties& props, const KinematicState& s, std::uint32_t i) {
  const auto c = static_cast<Eigen::Index>(i);
  return SphereState{s.position.col(c),       s.velocity.col(c),     s.angular_velocity.col(c),
                     props.radius[c],         props.effect_radius[c], props.inverse_mass[c]};
}

}  // namespace

ContactForceField::ContactForceField(const ParticleProperties& props, const PairTable& table,
                                     const Vec3& gravity)
    : props_(props), table_(table), gravity_(gravity) {
  const auto n = static_cast<Eigen::Index>(props.size());
  committed_force_ = Vec3Array::Zero(3, n);
  committed_torque_ = Vec3Array::Zero(3, n);
}

void ContactForceField::evaluate(const KinematicState& state, double elapsed,
                                 Accelerations& out, bool record) {
  const auto n = static_cast<Eigen::Index>(props_.size());
  force_.setZero(3, n);
  torque_.setZero(3, n);
  elastic_energy_ = 0.0;
  next_history_.clear();
  if (record) {
    // Watched pairs out of reach keep this: apart, no force, overlap from the centre distance.
    for (auto& o : observations_) {
      const auto p = static_cast<Eigen::Index>(o.p);
      const auto q = static_cast<Eigen::Index>(o.q);
      o.overlap = props_.radius[p] + props_.radius[q] -
                  (state.position.col(p) - state.position.col(q)).norm();
      o.normal_force = 0.0;
      o.in_contact = false;
    }
  }
  static const ContactHistory kFresh{};
  for_each_candidate_pair(props_, state.position, [&](std::uint32_t i, std::uint32_t j) {
    const ContactGeometry g = pair_geometry(sphere(props_, state, i), sphere(props_, state, j));
    const std::uint64_t key = pair_key(i, j);
    const auto found = history_.find(key);
    const ContactHistory& committed = found == history_.end() ? kFresh : found->second;
    const ContactOutcome c = evaluate_contact(
        table_.law(props_.material[i], props_.material[j]), g, committed, elapsed);
    if (record) observe(i, j, g, c);
    if (!c.interacting) return;
    force_.col(i) += c.force_on_p;
    force_.col(j) -= c.force_on_p;
    torque_.col(i) += c.torque_on_p;
    torque_.col(j) += c.torque_on_q;
    elastic_energy_ += c.elastic_energy;
    next_history_.insert_or_assign(key, c.history);
  });
  out.linear.resize(3, n);
  out.angular.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (props_.fixed[static_cast<std::size_t>(i)] != 0) {
      out.linear.col(i).setZero();
      out.angular.col(i).setZero();
      continue;
    }
    force_.col(i) += props_.mass[i] * gravity_;
    out.linear.col(i) = props_.inverse_mass[i] * force_.col(i);
    out.angular.col(i) = props_.inverse_inertia[i] * torque_.col(i);
  }
}

void ContactForceField::trial(const KinematicState& state, double elapsed, Accelerations& out) {
  evaluate(state, elapsed, out, false);
}

void ContactForceField::commit(const KinematicState& state, double elapsed, Accelerations& out) {
  evaluate(state, elapsed, out, true);
  std::swap(history_, next_history_);
  committed_force_ = force_;
  committed_torque_ = torque_;
  committed_elastic_energy_ = elastic_energy_;
}

void ContactForceField::watch_pairs(
    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) {
  observations_.clear();
  for (const auto& [p, q] : pairs) {
    observations_.push_back(PairObservation{p, q, 0.0, 0.0, false});
  }
}

void ContactForceField::observe(std::uint32_t i, std::uint32_t j, const ContactGeometry& g,
                                const ContactOutcome& c) {
  for (auto& o : observations_) {
    if ((o.p == i && o.q == j) || (o.p == j && o.q == i)) {
      o.overlap = g.overlap;
      o.normal_force = c.interacting ? c.normal_force : 0.0;
      o.in_contact = c.interacting;
    }
  }
}

}  // namespace dem
