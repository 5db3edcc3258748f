// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "dem/contact/contact_geometry.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/contact_model.hpp"
#include "dem/contact/mesh_topology.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/domain/periodic_box.hpp"
#include "dem/fields/external_fields.hpp"
#include "dem/forces/energy_ledger.hpp"
#include "dem/forces/loop_timing.hpp"
#include "dem/forces/pair_loop.hpp"
#include "dem/integrators/force_evaluator.hpp"
#include "dem/motion/prescribed_motion.hpp"
#include "dem/neighbors/neighbor_list.hpp"
#include "dem/neighbors/wall_list.hpp"
#include "dem/particles/particles.hpp"

namespace dem {

/// The state of one watched contact at the last committed evaluation (for traces and metrics).
struct ContactObservation {
  std::uint32_t p;
  std::uint32_t q;       ///< particle index, or wall index when `wall`
  bool wall;
  double overlap;        ///< body overlap δ [m] (negative when apart)
  double normal_force;   ///< normal force [N], repulsive positive; 0 when not interacting
  bool interacting;
};

/// What the force field acts on, beyond the particles and pair laws.
struct ForceFieldSetup {
  std::vector<Wall> walls;
  std::vector<MeshTopology> meshes;       ///< connectivity of the mesh walls (Wall::mesh indexes it)
  ExternalFields fields;
  std::vector<PrescribedMotion> motions;  ///< for fixed spheres that move
  WallLeverArm wall_lever_arm = WallLeverArm::contact_point;
  PairLeverArm pair_lever_arm = PairLeverArm::contact_point;
  PeriodicBox box;                        ///< periodic axes (none by default)
  NeighborSettings neighbors;             ///< skin > 0 (Simulation picks one when 0)
  int threads = 1;                        ///< OpenMP threads of the loops
  /// Keep the energy ledger (contact energies, dissipated and fluid work). A run that records no
  /// energy may switch it off: the loops then skip that arithmetic and energy() stays at 0.
  bool track_energy = true;
};

/// Forces on every sphere from pair and wall contacts and external fields; the ForceEvaluator the
/// integrators call. The loop (HOOMD-blue's split of loop and evaluator) owns a Verlet list
/// rebuilt when a sphere has moved half the skin, the contact history stored beside the list,
/// and three passes: pairs (by slabs, see SlabPartition), walls and fields per sphere. Every
/// pair goes through the one evaluator, evaluate_contact. Observation (watched contacts) runs
/// outside the pair loop, at commits only.
class ContactForceField final : public ForceEvaluator {
 public:
  /// The field for spheres `props` with pair laws `table`; both are referenced and must outlive
  /// the field. Throws ModelError when the periodic box is too small for the interaction reach.
  ContactForceField(const ParticleProperties& props, const PairTable& table, ForceFieldSetup setup);

  void trial(const KinematicState& state, double elapsed, Accelerations& out) override;
  void commit(const KinematicState& state, double elapsed, Accelerations& out) override;
  /// commit with the kick done in the pass that computes the accelerations (one pass over the
  /// spheres fewer per step; the same arithmetic per sphere).
  void commit_and_kick(KinematicState& state, double elapsed, Accelerations& out, double kick,
                       bool rotation) override;
  /// The velocity-Verlet step with the kick and drift fused into the packing pass and the
  /// closing kick into the accelerations' pass (ForceEvaluator::verlet_step). Always fuses.
  bool verlet_step(KinematicState& state, Accelerations& acc, double dt, bool rotation) override;
  /// Asks verlet_step to leave the closing kick of the steps that follow owed (`defer` true) or
  /// to give it (false): an owed kick rides on the next step's opening pass, where a_n is derived
  /// again from the committed forces (bit for bit the stored one), so the step stores no
  /// accelerations and the velocities get one pass fewer. Between steps the velocities then lack
  /// the kick, and, when the field pass would only add weights (weights_may_be_owed), the
  /// committed forces lack m g: only a caller that reads nothing before settle() may defer
  /// (Simulation::advance).
  void defer_closing_kick(bool defer) noexcept { defer_close_ = defer; }
  /// Steps so far that left their closing kick owed.
  [[nodiscard]] std::uint64_t deferred_kicks() const noexcept { return deferred_kicks_; }
  /// Of those, the steps that owed their field pass too (the weights m g, added where the next
  /// opening pass or settle() reads the forces).
  [[nodiscard]] std::uint64_t deferred_weights() const noexcept { return deferred_weights_; }
  /// Gives an owed closing kick now (and stores the accelerations it used in `acc`); no-op when
  /// none is owed.
  void settle(KinematicState& state, Accelerations& acc);
  void weigh(double now, double next) noexcept override;

  /// Starts the work booking afresh: the forces of the next commit enter the first step with
  /// `start_weight` (Scheme::start_weight()). Call before the commit at the start state.
  void restart_work(double start_weight);
  /// Takes the state's potential energy as the reference the integration error counts from:
  /// the contact energies of the last commit plus `gravitational` [J]. Call after that commit.
  void reset_potential(double gravitational) noexcept;
  /// Books the work of the step just taken (docs/physics.md, "Energy ledger"): the weighted
  /// forces of its evaluations times the mean of the velocities before (`velocity_before`,
  /// `angular_before`) and after (`after`) it, split into dashpot, fluid, boundary work and
  /// integration error; `gravitational` is the potential of the weights at `after` [J].
  /// `rotation`: the scheme integrates ω. No-op when the field keeps no ledger.
  void book_step(const Vec3Array& velocity_before, const Vec3Array& angular_before, const KinematicState& after,
                 double dt, bool rotation, double gravitational) noexcept;

  /// Contacts whose overlap and normal force are recorded at every commit.
  void watch(const std::vector<ContactObservation>& contacts);
  /// Watched contacts at the last commit, in the order given to watch().
  [[nodiscard]] const std::vector<ContactObservation>& observations() const noexcept {
    return observations_;
  }
  /// Total force on each sphere at the last commit [N] (contacts plus fields on mobile spheres;
  /// between steps that owe their closing kick, the contacts alone when the weights are owed too —
  /// see defer_closing_kick).
  [[nodiscard]] const Vec3Array& forces() const noexcept { return committed_force_; }
  /// Total torque on each sphere at the last commit [N·m].
  [[nodiscard]] const Vec3Array& torques() const noexcept { return committed_torque_; }
  /// Committed history of the pair (i, j), oriented i → j (fresh when it does not interact).
  [[nodiscard]] ContactHistory pair_history(std::uint32_t i, std::uint32_t j) const noexcept;
  /// Sphere pairs interacting at the last commit.
  [[nodiscard]] std::size_t interacting_pairs() const noexcept;
  /// Sphere pairs whose bodies touch at the last commit (overlap > 0, or a JKR neck holds):
  /// the contacts a coordination number counts.
  [[nodiscard]] std::size_t touching_pairs() const noexcept;
  /// Elastic energy stored in all contacts at the last commit [J].
  [[nodiscard]] double elastic_energy() const noexcept { return ledger_.elastic; }
  /// Contact energies at the last commit and work accumulated so far; kinetic and gravitational
  /// energy are left at 0 (they belong to the state after the step: Simulation::energy()).
  [[nodiscard]] const EnergyLedger& energy() const noexcept { return ledger_; }
  /// External fields.
  [[nodiscard]] const ExternalFields& fields() const noexcept { return setup_.fields; }
  /// Prescribed motions (for fixed spheres that move).
  [[nodiscard]] const std::vector<PrescribedMotion>& motions() const noexcept { return setup_.motions; }
  /// Walls.
  [[nodiscard]] const std::vector<Wall>& walls() const noexcept { return setup_.walls; }
  /// Connectivity of the mesh walls.
  [[nodiscard]] const std::vector<MeshTopology>& meshes() const noexcept { return setup_.meshes; }
  /// The periodic box.
  [[nodiscard]] const PeriodicBox& box() const noexcept { return setup_.box; }
  /// Neighbour-list settings (skin resolved).
  [[nodiscard]] const NeighborSettings& neighbor_settings() const noexcept { return setup_.neighbors; }
  /// The sphere neighbour list.
  [[nodiscard]] const NeighborList& neighbors() const noexcept { return list_; }
  /// Neighbour-list builds so far.
  [[nodiscard]] std::uint64_t list_builds() const noexcept { return list_.builds(); }
  /// Wall-clock time spent in list builds and in the force loops so far.
  [[nodiscard]] const LoopTiming& timing() const noexcept { return timing_; }
  /// The order a reorder should put the spheres in: slab by slab (the pair loop's work units),
  /// along a Morton curve of the smallest size class's cells within each slab. Element k is the
  /// current index of the sphere for place k.
  [[nodiscard]] std::vector<std::uint32_t> spatial_order(const KinematicState& state) const;
  /// Bytes held by the field: list, history, per-sphere arrays and scratch.
  [[nodiscard]] std::size_t bytes() const noexcept;

  /// Follows a reorder of the spheres (ParticleProperties and state already permuted: place k
  /// holds the sphere that was at order[k]); the list is rebuilt at `state` carrying history.
  void permute(std::span<const std::uint32_t> order, const KinematicState& state);

 private:
  /// What one of a sphere's wall candidates is to this evaluation when it is a mesh facet.
  enum class FacetRole : std::uint8_t {
    other,        ///< no facet, absent, or beyond reach: the wall loop's own tests apply
    counted,      ///< its contact counts, with its own history
    continues,    ///< its contact counts anew and continues a neighbour's history (MeshPlan::history)
    skipped,      ///< within reach but counted by another facet, or no local minimum: it ends
    handed_over,  ///< skipped, and its history goes on in a neighbour that `continues`
  };
  /// The roles of one sphere's candidates (indexed from its first candidate) and the histories the
  /// continuing facets take over; scratch for the pairing.
  struct MeshPlan {
    std::vector<FacetRole> role;
    std::vector<ContactHistory> history;
    std::vector<std::uint32_t> receivers;
    std::vector<std::uint32_t> donors;
  };
  /// Fills `plan` for sphere i (state p) at time t: which facet contacts count, and which pass
  /// from a facet to a neighbour (sharing a corner; the one whose nearest point is nearest the old
  /// contact's). False when the sphere has no mesh-facet candidate.
  bool plan_mesh_contacts(std::uint32_t i, const SphereState& p, double t, MeshPlan& plan) const;
  /// The pairing of plan_mesh_contacts for one mesh's candidates [begin, end) of a sphere whose
  /// first candidate is `first`.
  void hand_over(std::uint32_t first, std::uint32_t begin, std::uint32_t end, const SphereState& p, double t,
                 MeshPlan& plan, std::span<const ExtendedHistory> ext) const;
  /// A kick folded into the accelerations' pass: u += kick·a (ω += kick·α when `rotation`).
  struct FoldedKick {
    double* velocity = nullptr;  ///< null: no kick
    double* angular_velocity = nullptr;
    double kick = 0.0;
    bool rotation = false;
  };
  void evaluate(const KinematicState& state, double elapsed, Accelerations& out, bool commit,
                const FoldedKick& kick);
  /// evaluate once the centres are packed (`worst`: the largest squared travel since the build);
  /// `out` null: the accelerations are kicked with but not stored. `owe_weights`: the field pass is
  /// left out (weights_may_be_owed(); the caller owes the weights with the closing kick).
  void evaluate_packed(const KinematicState& state, double elapsed, Accelerations* out, bool commit,
                       const FoldedKick& kick, double worst, bool owe_weights = false);
  /// Packs the wrapped centres, clears the force sums; returns the largest squared travel since
  /// the last build.
  double pack(const KinematicState& state);
  /// The spheres under prescribed motion at time t: their packed centres, and the travel `worst`
  /// grown by theirs.
  double pack_motions(double t, double worst);
  /// velocity Verlet's opening pass, fused with pack: an owed closing kick, then u += kick·a
  /// (ω += kick·α when `rotation`), x += drift·u unless fixed, time += drift, then packs. a and
  /// α are `acc`'s, or, with a kick owed, derived from the committed forces.
  double kick_drift_pack(KinematicState& state, const Accelerations& acc, double kick, double drift, bool rotation);
  /// The mass sphere c accelerates with: its own, plus the fluid's added mass unless the only
  /// field is gravity.
  [[nodiscard]] double inertia_mass(Eigen::Index c, bool gravity_only) const noexcept {
    return gravity_only ? props_.mass[c] : props_.mass[c] + setup_.fields.added_mass(props_.radius[c]);
  }
  /// Linear and angular acceleration of a mobile sphere.
  struct SphereAcceleration {
    Vec3 linear;
    Vec3 angular;
  };
  /// Mobile sphere c's accelerations from the force and torque sums `force`, `torque`: F/m with
  /// the inertia mass, I⁻¹T. (kick_drift_pack writes the same arithmetic component by component.)
  [[nodiscard]] SphereAcceleration acceleration_of(const Vec3Array& force, const Vec3Array& torque, Eigen::Index c,
                                                   bool gravity_only) const noexcept {
    return {force.col(c) / inertia_mass(c, gravity_only), props_.inverse_inertia[c] * torque.col(c)};
  }
  /// Stores sphere c's accelerations in `out` (when not null) and gives it `kick` (when it has a
  /// velocity to kick): the scheme's closing kick, fixed spheres included with zero accelerations.
  static void store_and_kick(Accelerations* out, const FoldedKick& kick, Eigen::Index c, const Vec3& a,
                             const Vec3& alpha) noexcept;
  void rebuild(const KinematicState& state, std::span<const std::uint32_t> new_of_old);
  /// Builds the sphere–wall candidates from the packed centres at `time` (new_of_old: as rebuild).
  void build_wall_list(double time, std::span<const std::uint32_t> new_of_old);
  void observe(const KinematicState& state, double elapsed);
  void run_pairs(const KinematicState& state, double elapsed, bool commit);
  void run_walls_and_fields(const KinematicState& state, double elapsed, Accelerations* out, bool commit,
                            const FoldedKick& kick);
  [[nodiscard]] SphereState sphere(const KinematicState& s, std::uint32_t i) const noexcept;
  [[nodiscard]] double wall_reach_of(std::uint32_t i, std::uint32_t w) const noexcept;

  const ParticleProperties& props_;
  const PairTable& table_;
  ForceFieldSetup setup_;
  std::vector<std::int32_t> motion_of_;   // sphere → index into setup_.motions, or −1
  std::vector<std::uint8_t> still_;       // fixed and not moved by a prescribed motion
  std::vector<Vec3> motion_position_;     // per motion, at the evaluation's time
  std::vector<Vec3> motion_velocity_;
  ScalarArray half_reach_;
  std::vector<ContactSphere> contact_spheres_;  // radii, 1/m, charge packed for the pair loop
  SizeClasses classes_;
  bool extended_history_ = false;
  std::vector<PackedSphere> packed_;      // wrapped centres + half reach, this evaluation
  Vec3Array built_position_;              // wrapped centres at the last build
  Vec3Array wrap_offset_;                 // image × box length subtracted to wrap (periodic only)
  double built_time_ = 0.0;
  bool built_ = false;
  NeighborList list_;
  WallList wall_list_;
  Vec3Array force_;
  Vec3Array torque_;
  Vec3Array committed_force_;
  Vec3Array committed_torque_;
  EnergyTotals totals_;
  std::vector<EnergyTotals> slab_totals_;   // per slab, summed in slab order
  std::vector<EnergyTotals> chunk_totals_;  // per sphere chunk, summed in chunk order
  std::vector<MeshPlan> mesh_plans_;         // per sphere chunk (empty without meshes)
  EnergyLedger ledger_;
  /// Forces of the evaluations of one step, each times its weight (ForceEvaluator::weigh).
  struct WorkSums {
    Vec3Array force;    ///< total force on each sphere
    Vec3Array torque;   ///< total torque
    Vec3Array damping;  ///< normal-dashpot force
    Vec3Array field;    ///< drag, pressure gradient and pull
    double wall_power = 0.0;          ///< Σ F·v_wall [W]
    double wall_damping_power = 0.0;  ///< Σ F_d·v_wall [W]
    /// The per-sphere arrays (3 × `cols`, kept in place when already that size).
    [[nodiscard]] std::array<Vec3Array*, 4> arrays() noexcept { return {&force, &torque, &damping, &field}; }
    /// Zero sums for `cols` spheres.
    void clear(Eigen::Index cols) {
      for (Vec3Array* a : arrays()) a->setZero(3, cols);
      wall_power = 0.0;
      wall_damping_power = 0.0;
    }
  };
  Vec3Array damping_force_;  // dashpot forces of this evaluation (with the ledger)
  Vec3Array field_force_;    // drag, pressure-gradient and pull forces of this evaluation
  WorkSums step_sums_;       // the step under way
  WorkSums next_sums_;       // the step after it
  double weight_now_ = -1.0;  // < 0: not stated for the next evaluation
  double weight_next_ = 0.0;
  double potential_booked_ = 0.0;  // potential energy at the last booking [J]
  double lost_booked_ = 0.0;       // dissipated friction + adhesion + plastic at the last booking [J]
  void add_weighted_forces(double now, double next);
  std::vector<ContactObservation> observations_;
  LoopTiming timing_;
  /// A closing kick owed by the last step (defer_closing_kick).
  struct OwedKick {
    bool active = false;
    double kick = 0.0;
    bool rotation = false;
    /// The step left out its field pass too (only weights, no walls, no ledger): its committed
    /// forces hold the contact sums alone, and the weights m g are added where they are read.
    bool weights = false;
  };
  /// True when a step whose closing kick is owed may owe its field pass as well: gravity is the
  /// only field, there are no walls and no ledger, so that pass would only add m g to each
  /// mobile sphere's force.
  [[nodiscard]] bool weights_may_be_owed() const noexcept {
    return setup_.fields.gravity_only() && setup_.walls.empty() && !setup_.track_energy;
  }
  OwedKick owed_;
  bool defer_close_ = false;
  std::uint64_t deferred_kicks_ = 0;
  std::uint64_t deferred_weights_ = 0;
};

}  // namespace dem
