// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "dem/contact/contact_geometry.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/contact_model.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/fields/external_fields.hpp"
#include "dem/integrators/force_evaluator.hpp"
#include "dem/motion/prescribed_motion.hpp"
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

/// Energies of the system at the last commit, and work accumulated since t = 0 [J].
struct EnergyLedger {
  double kinetic = 0.0;              ///< translational + rotational of mobile spheres
  double elastic = 0.0;              ///< normal and tangential springs
  double cohesive = 0.0;             ///< cohesive potential (≤ 0 while attracting)
  double gravitational = 0.0;        ///< −Σ m g·x of mobile spheres
  double dissipated_damping = 0.0;   ///< cumulative dashpot work
  double dissipated_friction = 0.0;  ///< cumulative sliding and rolling work
  double fluid_work = 0.0;           ///< cumulative work of drag and pressure gradient on spheres
  /// Mechanical energy plus everything dissipated minus work put in: constant for an exact
  /// integration (with walls at rest and no prescribed motion).
  [[nodiscard]] double balance() const noexcept {
    return kinetic + elastic + cohesive + gravitational + dissipated_damping + dissipated_friction -
           fluid_work;
  }
};

/// What the force field acts on, beyond the particles and pair laws.
struct ForceFieldSetup {
  std::vector<PlaneWall> walls;
  ExternalFields fields;
  std::vector<PrescribedMotion> motions;  ///< for fixed spheres that move
  bool wall_lever_arm_is_radius = false;  ///< WallLeverArm::radius
};

/// Forces on every sphere from pair and wall contacts and external fields; the ForceEvaluator the
/// integrators call. Holds the committed contact history and the energy bookkeeping.
class ContactForceField final : public ForceEvaluator {
 public:
  /// The field for spheres `props` with pair laws `table`; both are referenced and must outlive
  /// the field.
  ContactForceField(const ParticleProperties& props, const PairTable& table, ForceFieldSetup setup);

  void trial(const KinematicState& state, double elapsed, Accelerations& out) override;
  void commit(const KinematicState& state, double elapsed, Accelerations& out) override;

  /// Contacts whose overlap and normal force are recorded at every commit.
  void watch(const std::vector<ContactObservation>& contacts);
  /// Watched contacts at the last commit, in the order given to watch().
  [[nodiscard]] const std::vector<ContactObservation>& observations() const noexcept {
    return observations_;
  }
  /// Total force on each sphere at the last commit [N] (contacts plus fields on mobile spheres).
  [[nodiscard]] const Vec3Array& forces() const noexcept { return committed_force_; }
  /// Total torque on each sphere at the last commit [N·m].
  [[nodiscard]] const Vec3Array& torques() const noexcept { return committed_torque_; }
  /// Committed history of every interacting sphere pair.
  [[nodiscard]] const ContactHistoryTable& history() const noexcept { return history_; }
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
  [[nodiscard]] const std::vector<PlaneWall>& walls() const noexcept { return setup_.walls; }

 private:
  /// Sums of one evaluation.
  struct Totals {
    double elastic = 0.0;
    double cohesive = 0.0;
    double damping = 0.0;
    double friction = 0.0;
    double fluid_power = 0.0;
  };
  void evaluate(const KinematicState& state, double elapsed, Accelerations& out, bool record);
  void add_contact(std::uint32_t i, std::uint32_t j, const ContactOutcome& c);
  void record_observation(std::uint32_t p, std::uint32_t q, bool wall, const ContactGeometry& g,
                          const ContactOutcome& c);
  [[nodiscard]] SphereState sphere(const KinematicState& s, std::uint32_t i) const;

  const ParticleProperties& props_;
  const PairTable& table_;
  ForceFieldSetup setup_;
  std::vector<std::int32_t> motion_of_;  // particle → index into setup_.motions, or −1
  std::vector<std::uint8_t> moving_;     // 1 for a fixed sphere under prescribed motion
  ContactHistoryTable history_;          // committed sphere–sphere history
  ContactHistoryTable next_history_;
  ContactHistoryTable wall_history_;     // committed sphere–wall history (key: particle, wall)
  ContactHistoryTable next_wall_history_;
  Vec3Array force_;
  Vec3Array torque_;
  Totals totals_;
  Vec3Array committed_force_;
  Vec3Array committed_torque_;
  EnergyLedger ledger_;
  std::vector<ContactObservation> observations_;
};

}  // namespace dem
