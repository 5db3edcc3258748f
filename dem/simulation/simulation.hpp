// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "dem/contact/pair_table.hpp"
#include "dem/forces/contact_force_field.hpp"
#include "dem/integrators/scheme.hpp"
#include "dem/particles/particles.hpp"

namespace dem {

/// Everything a run needs, already validated.
struct SimulationSetup {
  std::vector<ParticleInit> particles;
  std::vector<MaterialProperties> materials;
  MixingRules mixing;
  std::vector<PairOverride> pair_overrides;
  ModelChoice model;
  ExternalFields fields;                  ///< gravity and fluid
  std::vector<Wall> walls;
  std::vector<MeshTopology> meshes;       ///< connectivity of the mesh walls (Wall::mesh indexes it)
  std::vector<PrescribedMotion> motions;  ///< for fixed spheres that move
  SchemeId scheme = SchemeId::velocity_verlet;
  SchemeSettings scheme_settings;
  double timestep = 0.0;  ///< Δt [s], > 0
  PeriodicBox box;              ///< periodic axes (none by default)
  NeighborSettings neighbors;   ///< skin (0: a tenth of the smallest diameter), reorder interval
  int threads = 1;              ///< OpenMP threads; results do not depend on it
  bool track_energy = true;     ///< keep the energy ledger (energy()); off skips its arithmetic
  /// The pair table of materials, mixing, pair_overrides and model above when the caller has
  /// already built it (it must be built from exactly those); null: the simulation builds it.
  std::shared_ptr<const PairTable> pair_table;
};

/// Wires particles, pair laws, force field and scheme together and steps them. Holds no
/// physics of its own. Between steps it may reorder the spheres along a Morton curve (after a
/// neighbour-list build, every NeighborSettings::sort_every builds): state() is then in that
/// internal order, and slot(id) says where the sphere given as `id` in the setup now lives.
class Simulation {
 public:
  /// Builds the run; throws ModelError when the model lacks a parameter.
  explicit Simulation(const SimulationSetup& setup);
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Supplies exact states at t = −Δt, −2Δt, … for a multi-step scheme's exact start.
  void set_exact_past(const std::vector<KinematicState>& past);
  /// States a multi-step scheme needs for an exact start.
  [[nodiscard]] std::size_t past_states_needed() const noexcept;

  /// Records overlap and normal force of these contacts at every commit, starting now.
  void watch(const std::vector<ContactObservation>& contacts);

  /// Advances one time step.
  void step();
  /// Advances `count` time steps: the same states as `count` calls of step(), bit for bit, but
  /// a velocity-Verlet run without a ledger or prescribed motions carries each step's closing
  /// kick over to the next step's opening pass (ContactForceField::defer_closing_kick), one pass
  /// over the velocities and the stores of the accelerations fewer per step.
  void advance(std::uint64_t count);

  /// Simulated time t = n Δt [s].
  [[nodiscard]] double time() const noexcept { return static_cast<double>(steps_) * dt_; }
  /// Steps taken.
  [[nodiscard]] std::uint64_t steps() const noexcept { return steps_; }
  /// Time step [s].
  [[nodiscard]] double timestep() const noexcept { return dt_; }
  /// Current state, in the internal order (see slot()).
  [[nodiscard]] const KinematicState& state() const noexcept { return state_; }
  /// Where the sphere that was `id` in SimulationSetup::particles lives in state().
  [[nodiscard]] std::uint32_t slot(std::uint32_t id) const noexcept { return slot_of_id_[id]; }
  /// The setup index of the sphere at internal place `slot`.
  [[nodiscard]] std::uint32_t id(std::uint32_t slot) const noexcept { return id_of_slot_[slot]; }
  /// Reorders now (tests and benchmarks; step() does it on its own schedule).
  void reorder();
  /// Reorders done so far.
  [[nodiscard]] std::uint64_t reorders() const noexcept { return reorders_; }
  /// Bytes held by the run's per-sphere arrays, contact lists and history (the core's share of
  /// memory, counted from the containers' capacities).
  [[nodiscard]] std::size_t bytes() const noexcept;
  /// Static particle properties.
  [[nodiscard]] const ParticleProperties& particles() const noexcept { return props_; }
  /// The pair table (mixed parameters and laws).
  [[nodiscard]] const PairTable& pair_table() const noexcept { return *table_; }
  /// The force field (forces, torques, watched pairs, contact history).
  [[nodiscard]] ContactForceField& force_field() noexcept { return *field_; }
  [[nodiscard]] const ContactForceField& force_field() const noexcept { return *field_; }
  /// Scheme counters.
  [[nodiscard]] const SchemeDiagnostics& diagnostics() const noexcept {
    return scheme_->diagnostics();
  }
  /// True when the energy ledger's work is exact for the scheme (Scheme::books_work_exactly()):
  /// its balance then holds to round-off.
  [[nodiscard]] bool books_work_exactly() const noexcept { return scheme_->books_work_exactly(); }
  /// Kinetic energy, translational plus rotational, of the mobile spheres [J] (with a fluid's
  /// virtual mass, eq 3.51, in the translational inertia).
  [[nodiscard]] double kinetic_energy() const noexcept;
  /// Potential energy of the weights, −Σ F_g·x over the mobile spheres (F_g with buoyancy when
  /// the fluid asks for it) [J].
  [[nodiscard]] double gravitational_energy() const noexcept;
  /// Energy ledger at the current state: kinetic and gravitational energy of this state,
  /// contact energies of the last commit, accumulated work.
  [[nodiscard]] EnergyLedger energy() const noexcept;

 private:
  /// True when this run sorts its spheres along the Morton curve (at the start and every
  /// `sort_every` list builds): sorting is on and the population is large enough to gain.
  [[nodiscard]] bool sorts() const noexcept;
  KinematicState state_;       // declared first: props_' initialiser fills it
  ParticleProperties props_;
  std::shared_ptr<const PairTable> table_;  ///< never null; the force field holds a reference to it
  std::unique_ptr<ContactForceField> field_;
  std::unique_ptr<Scheme> scheme_;
  Accelerations acc_;
  double dt_;
  std::uint64_t steps_ = 0;
  NeighborSettings neighbors_;
  std::vector<std::uint32_t> slot_of_id_;
  std::vector<std::uint32_t> id_of_slot_;
  std::uint64_t builds_at_last_sort_ = 0;
  std::uint64_t reorders_ = 0;

  bool track_energy_;
  bool rotation_;
  Vec3Array velocity_before_;  // the state's velocities at the start of a step (with the ledger)
  Vec3Array angular_before_;

  void apply_prescribed_motion();
  /// Commits the forces at the current state with `elapsed` and starts the work booking there.
  void commit_start(double elapsed);
};

}  // namespace dem
