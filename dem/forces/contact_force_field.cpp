// SPDX-License-Identifier: MIT
#include "dem/forces/contact_force_field.hpp"

#include <cmath>
#include <numbers>

#include "dem/neighbors/all_pairs.hpp"

namespace dem {

ContactForceField::ContactForceField(const ParticleProperties& props, const PairTable& table,
                                     ForceFieldSetup setup)
    : props_(props), table_(table), setup_(std::move(setup)), motion_of_(props.size(), -1) {
  moving_.assign(props.size(), 0);
  for (std::size_t k = 0; k < setup_.motions.size(); ++k) {
    motion_of_[setup_.motions[k].particle] = static_cast<std::int32_t>(k);
    moving_[setup_.motions[k].particle] = 1;
  }
  const auto n = static_cast<Eigen::Index>(props.size());
  committed_force_ = Vec3Array::Zero(3, n);
  committed_torque_ = Vec3Array::Zero(3, n);
}

SphereState ContactForceField::sphere(const KinematicState& s, std::uint32_t i) const {
  const auto c = static_cast<Eigen::Index>(i);
  SphereState out{s.position.col(c),    s.velocity.col(c),      s.angular_velocity.col(c),
                  props_.radius[c],     props_.effect_radius[c], props_.inverse_mass[c],
                  props_.charge[c]};
  if (const std::int32_t m = motion_of_[i]; m >= 0) {
    // A sphere under prescribed motion is where its motion says, whatever the integrator did.
    const PrescribedMotion& motion = setup_.motions[static_cast<std::size_t>(m)];
    out.position = motion.position(s.time);
    out.velocity = motion.velocity(s.time);
  }
  return out;
}

void ContactForceField::add_contact(std::uint32_t i, std::uint32_t j, const ContactOutcome& c) {
  force_.col(i) += c.force_on_p;
  force_.col(j) -= c.force_on_p;
  torque_.col(i) += c.torque_on_p;
  torque_.col(j) += c.torque_on_q;
  totals_.elastic += c.elastic_energy;
  totals_.cohesive += c.cohesive_energy;
  totals_.damping += c.dissipated_damping;
  totals_.friction += c.dissipated_friction;
}

void ContactForceField::evaluate(const KinematicState& state, double elapsed, Accelerations& out,
                                 bool record) {
  const auto n = static_cast<Eigen::Index>(props_.size());
  force_.setZero(3, n);
  torque_.setZero(3, n);
  totals_ = Totals{};
  next_history_.clear();
  next_wall_history_.clear();
  if (record) {
    for (auto& o : observations_) {
      o.normal_force = 0.0;
      o.interacting = false;
      const SphereState p = sphere(state, o.p);
      o.overlap = o.wall ? wall_geometry(p, setup_.walls[o.q], state.time, false).overlap
                         : pair_geometry(p, sphere(state, o.q)).overlap;
    }
  }
  static const ContactHistory kFresh{};

  // Sphere–sphere contacts: every pair within reach of its law.
  for_each_candidate_pair(props_, moving_, state.position, [&](std::uint32_t i, std::uint32_t j) {
    const PairLaw& law = table_.law(props_.material[i], props_.material[j]);
    const ContactGeometry g = pair_geometry(sphere(state, i), sphere(state, j));
    const std::uint64_t key = pair_key(i, j);
    const auto found = history_.find(key);
    const ContactOutcome c = evaluate_contact(law, g, found == history_.end() ? kFresh : found->second,
                                              elapsed);
    if (record) record_observation(i, j, false, g, c);
    if (!c.interacting) return;
    add_contact(i, j, c);
    next_history_.insert_or_assign(key, c.history);
  }, [&](std::uint32_t i, std::uint32_t j) {
    const PairLaw& law = table_.law(props_.material[i], props_.material[j]);
    const double r_p = props_.radius[i], r_q = props_.radius[j];
    return interaction_range(law, {r_p + r_q, props_.effect_radius[i] + props_.effect_radius[j],
                                   r_p * r_q / (r_p + r_q)});
  });

  // Sphere–wall contacts: the wall is an infinite-mass partner (m* = m, R* = r).
  for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
    if (props_.fixed[i] != 0) continue;
    const SphereState p = sphere(state, i);
    for (std::uint32_t w = 0; w < setup_.walls.size(); ++w) {
      const PlaneWall& wall = setup_.walls[w];
      const PairLaw& law = table_.law(props_.material[i], wall.material);
      const ContactGeometry g = wall_geometry(p, wall, state.time, setup_.wall_lever_arm_is_radius);
      const double r = props_.radius[i];
      if (g.distance > interaction_range(law, {r, props_.effect_radius[i], r})) continue;
      const std::uint64_t key = pair_key(i, w);
      const auto found = wall_history_.find(key);
      const ContactOutcome c = evaluate_contact(
          law, g, found == wall_history_.end() ? kFresh : found->second, elapsed);
      if (record) record_observation(i, w, true, g, c);
      if (!c.interacting) continue;
      force_.col(i) += c.force_on_p;
      torque_.col(i) += c.torque_on_p;
      totals_.elastic += c.elastic_energy;
      totals_.cohesive += c.cohesive_energy;
      totals_.damping += c.dissipated_damping;
      totals_.friction += c.dissipated_friction;
      next_wall_history_.insert_or_assign(key, c.history);
    }
  }

  // External fields and accelerations of the mobile spheres.
  out.linear.resize(3, n);
  out.angular.resize(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (props_.fixed[static_cast<std::size_t>(i)] != 0) {
      out.linear.col(i).setZero();
      out.angular.col(i).setZero();
      continue;
    }
    const double density = props_.mass[i] / (4.0 / 3.0 * std::numbers::pi * std::pow(props_.radius[i], 3));
    const FieldInput in{state.position.col(i), state.velocity.col(i), props_.radius[i], density,
                        props_.mass[i], state.time};
    force_.col(i) += setup_.fields.force(in);
    totals_.fluid_power += setup_.fields.hydrodynamic_power(in);
    const double inertia_mass = props_.mass[i] + setup_.fields.added_mass(props_.radius[i]);
    out.linear.col(i) = force_.col(i) / inertia_mass;
    out.angular.col(i) = props_.inverse_inertia[i] * torque_.col(i);
  }
}

void ContactForceField::trial(const KinematicState& state, double elapsed, Accelerations& out) {
  evaluate(state, elapsed, out, false);
}

void ContactForceField::commit(const KinematicState& state, double elapsed, Accelerations& out) {
  evaluate(state, elapsed, out, true);
  std::swap(history_, next_history_);
  std::swap(wall_history_, next_wall_history_);
  committed_force_ = force_;
  committed_torque_ = torque_;
  ledger_.elastic = totals_.elastic;
  ledger_.cohesive = totals_.cohesive;
  ledger_.dissipated_damping += totals_.damping;
  ledger_.dissipated_friction += totals_.friction;
  ledger_.fluid_work += totals_.fluid_power * elapsed;
}

void ContactForceField::watch(const std::vector<ContactObservation>& contacts) {
  observations_ = contacts;
}

void ContactForceField::record_observation(std::uint32_t p, std::uint32_t q, bool wall,
                                           const ContactGeometry& g, const ContactOutcome& c) {
  for (auto& o : observations_) {
    const bool same = o.wall == wall && ((o.p == p && o.q == q) || (!wall && o.p == q && o.q == p));
    if (!same) continue;
    o.overlap = g.overlap;
    o.normal_force = c.interacting ? c.normal_force : 0.0;
    o.interacting = c.interacting;
  }
}

}  // namespace dem
