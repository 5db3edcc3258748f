// SPDX-License-Identifier: MIT
#include "dem/simulation/simulation.hpp"

#include <numeric>
#include <stdexcept>

#include "dem/particles/spatial_order.hpp"

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
      table_(setup.pair_table != nullptr
                 ? setup.pair_table
                 : std::make_shared<const PairTable>(setup.materials, setup.mixing, setup.pair_overrides,
                                                     setup.model)),
      field_(std::make_unique<ContactForceField>(
          props_, *table_,
          ForceFieldSetup{setup.walls, setup.meshes, setup.fields, setup.motions,
                          setup.model.wall_lever_arm,
                          setup.model.pair_lever_arm, setup.box,
                          setup.neighbors, setup.threads, setup.track_energy})),
      scheme_(make_scheme(setup.scheme, setup.scheme_settings)),
      dt_(setup.timestep),
      neighbors_(setup.neighbors),
      track_energy_(setup.track_energy),
      rotation_(setup.scheme_settings.rotation) {
  if (!(dt_ > 0.0)) throw std::invalid_argument("time step must be > 0");
  scheme_->bind(props_, setup.threads);
  slot_of_id_.resize(props_.size());
  std::iota(slot_of_id_.begin(), slot_of_id_.end(), 0U);
  id_of_slot_ = slot_of_id_;
  apply_prescribed_motion();
  // The forces at t = 0. Contact history normally starts there (nothing has elapsed). When the
  // given velocities are v(−Δt/2) (leapfrog, given_is_half_step: YADE's NewtonIntegrator), a
  // contact present at t = 0 has already slid for the half-step velocity over one Δt, as YADE's
  // iteration 0 books it (ScGeom::precompute integrates the shear increment of a new interaction
  // too): its first tangential force is the one of that slip, not zero.
  const bool given_half_step = setup.scheme == SchemeId::leapfrog &&
                               setup.scheme_settings.leapfrog_start == LeapfrogStart::given_is_half_step;
  commit_start(given_half_step ? dt_ : 0.0);
  builds_at_last_sort_ = field_->list_builds();
  // A generated population arrives in generation order, which scatters neighbours over memory:
  // sort once at the start, then every `sort_every` builds (docs/performance.md, box scaling).
  if (sorts()) reorder();
}

bool Simulation::sorts() const noexcept {
  return neighbors_.sort_every > 0 && props_.size() >= kMinSpheresToReorder;
}

std::size_t Simulation::past_states_needed() const noexcept {
  return scheme_->past_states_needed();
}

void Simulation::set_exact_past(const std::vector<KinematicState>& past) {
  scheme_->set_past(past, *field_, dt_);
  commit_start(0.0);  // the scheme's first step is now its own formula: book the start afresh
}

void Simulation::watch(const std::vector<ContactObservation>& contacts) {
  field_->watch(contacts);
  commit_start(0.0);  // same state, nothing elapsed: fills the observations
}

void Simulation::commit_start(double elapsed) {
  if (track_energy_) field_->restart_work(scheme_->start_weight());
  field_->commit(state_, elapsed, acc_);
  if (track_energy_) field_->reset_potential(gravitational_energy());
}

void Simulation::step() {
  if (track_energy_) {
    velocity_before_ = state_.velocity;  // same size every step: no allocation after the first
    angular_before_ = state_.angular_velocity;
  }
  scheme_->step(state_, acc_, dt_, *field_);
  ++steps_;
  state_.time = time();  // exact n Δt, free of accumulated rounding
  apply_prescribed_motion();
  if (track_energy_) {
    field_->book_step(velocity_before_, angular_before_, state_, dt_, rotation_, gravitational_energy());
  }
  if (sorts() && field_->list_builds() >= builds_at_last_sort_ + neighbors_.sort_every) {
    field_->settle(state_, acc_);  // the reorder takes stored accelerations along
    reorder();
  }
}

void Simulation::advance(std::uint64_t count) {
  // A ledger books velocities after every step, and a prescribed motion overwrites them there:
  // both need each step's closing kick given at its end.
  const bool defer = !track_energy_ && field_->motions().empty();
  // However the stretch ends (a step may throw), no kick stays owed and later steps give theirs.
  struct Settled {
    Simulation& sim;
    explicit Settled(Simulation& s) : sim(s) {}
    Settled(const Settled&) = delete;
    Settled& operator=(const Settled&) = delete;
    ~Settled() {
      sim.field_->defer_closing_kick(false);
      sim.field_->settle(sim.state_, sim.acc_);
    }
  } settled{*this};
  for (std::uint64_t k = 1; k <= count; ++k) {
    field_->defer_closing_kick(defer && k < count);
    step();
  }
}

void Simulation::reorder() {
  const std::vector<std::uint32_t> order = field_->spatial_order(state_);
  dem::permute(props_, order);
  dem::permute(state_, order);
  if (acc_.linear.cols() == state_.position.cols()) {
    dem::permute(acc_.linear, order);
    dem::permute(acc_.angular, order);
  }
  scheme_->permute(order);
  field_->permute(order, state_);
  const std::vector<std::uint32_t> old_ids = id_of_slot_;
  for (std::size_t k = 0; k < order.size(); ++k) {
    id_of_slot_[k] = old_ids[order[k]];
    slot_of_id_[id_of_slot_[k]] = static_cast<std::uint32_t>(k);
  }
  builds_at_last_sort_ = field_->list_builds();
  ++reorders_;
}

std::size_t Simulation::bytes() const noexcept {
  const auto matrix = [](const Vec3Array& a) { return static_cast<std::size_t>(a.size()) * sizeof(double); };
  const auto scalars = [](const ScalarArray& a) { return static_cast<std::size_t>(a.size()) * sizeof(double); };
  return matrix(state_.position) + matrix(state_.velocity) + matrix(state_.angular_velocity) +
         state_.orientation.capacity() * sizeof(Quat) + matrix(acc_.linear) + matrix(acc_.angular) +
         scalars(props_.radius) + scalars(props_.effect_radius) + scalars(props_.mass) +
         scalars(props_.inverse_mass) + scalars(props_.inertia) + scalars(props_.inverse_inertia) +
         scalars(props_.charge) + scalars(props_.density) +
         props_.material.capacity() * sizeof(std::uint32_t) + props_.fixed.capacity() +
         (slot_of_id_.capacity() + id_of_slot_.capacity()) * sizeof(std::uint32_t) + field_->bytes();
}

void Simulation::apply_prescribed_motion() {
  for (const auto& m : field_->motions()) {
    const auto i = static_cast<Eigen::Index>(m.particle);
    state_.position.col(i) = m.position(state_.time);
    state_.velocity.col(i) = m.velocity(state_.time);
  }
}

double Simulation::kinetic_energy() const noexcept {
  const ExternalFields& fields = field_->fields();
  double e = 0.0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(props_.size()); ++i) {
    if (props_.fixed[static_cast<std::size_t>(i)] != 0) continue;
    const double inertia_mass = props_.mass[i] + fields.added_mass(props_.radius[i]);
    e += 0.5 * inertia_mass * state_.velocity.col(i).squaredNorm() +
         0.5 * props_.inertia[i] * state_.angular_velocity.col(i).squaredNorm();
  }
  return e;
}

double Simulation::gravitational_energy() const noexcept {
  const ExternalFields& fields = field_->fields();
  double e = 0.0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(props_.size()); ++i) {
    if (props_.fixed[static_cast<std::size_t>(i)] != 0) continue;
    const FieldInput in{state_.position.col(i), state_.velocity.col(i), props_.radius[i],
                        props_.density[i], props_.mass[i], state_.time};
    e -= fields.gravity_force(in).dot(state_.position.col(i));
  }
  return e;
}

EnergyLedger Simulation::energy() const noexcept {
  EnergyLedger e = field_->energy();
  e.kinetic = kinetic_energy();
  e.gravitational = gravitational_energy();
  return e;
}

}  // namespace dem
