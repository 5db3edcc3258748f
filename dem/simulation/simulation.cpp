// SPDX-License-Identifier: MIT
#include "dem/simulation/simulation.hpp"

#include <stdexcept>

namespace dem {
namespace {

/// Builds the particle arrays (a helper so the members can be initialised in order).
ParticleProperties make_properties(const SimulationSetup& setup, KinematicState& state) {
  ParticleProperties props;
  build_particles(setup.particles, props, state);
  return props;
}

}  // namespace

Simulation::Simulation(const SimulationSetup& setup)
    : props_(make_properties(setup, state_)),
      table_(setup.materials, setup.mixing, setup.pair_overrides, setup.model),
      field_(std::make_unique<ContactForceField>(
          props_, table_,
          ForceFieldSetup{setup.walls, setup.fields, setup.motions,
                          setup.model.wall_lever_arm == WallLeverArm::radius})),
      scheme_(make_scheme(setup.scheme, setup.scheme_settings)),
      dt_(setup.timestep) {
  if (!(dt_ > 0.0)) throw std::invalid_argument("time step must be > 0");
  apply_prescribed_motion();
  field_->commit(state_, 0.0, acc_);
}

std::size_t Simulation::past_states_needed() const noexcept {
  return scheme_->past_states_needed();
}

void Simulation::set_exact_past(const std::vector<KinematicState>& past) {
  scheme_->set_past(past, *field_, dt_);
}

void Simulation::watch(const std::vector<ContactObservation>& contacts) {
  field_->watch(contacts);
  field_->commit(state_, 0.0, acc_);  // same state, nothing elapsed: fills the observations
}

void Simulation::step() {
  scheme_->step(state_, acc_, dt_, *field_);
  ++steps_;
  state_.time = time();  // exact n Δt, free of accumulated rounding
  apply_prescribed_motion();
}

void Simulation::apply_prescribed_motion() {
  for (const auto& m : field_->motions()) {
    const auto i = static_cast<Eigen::Index>(m.particle);
    state_.position.col(i) = m.position(state_.time);
    state_.velocity.col(i) = m.velocity(state_.time);
  }
}

double Simulation::kinetic_energy() const noexcept {
  double e = 0.0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(props_.size()); ++i) {
    if (props_.fixed[static_cast<std::size_t>(i)] != 0) continue;
    e += 0.5 * props_.mass[i] * state_.velocity.col(i).squaredNorm() +
         0.5 * props_.inertia[i] * state_.angular_velocity.col(i).squaredNorm();
  }
  return e;
}

EnergyLedger Simulation::energy() const noexcept {
  EnergyLedger e = field_->energy();
  e.kinetic = kinetic_energy();
  e.gravitational = 0.0;
  const Vec3& g = field_->fields().gravity;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(props_.size()); ++i) {
    if (props_.fixed[static_cast<std::size_t>(i)] != 0) continue;
    e.gravitational -= props_.mass[i] * g.dot(state_.position.col(i));
  }
  return e;
}

}  // namespace dem
