// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <span>

#include "dem/contact/pair_table.hpp"
#include "dem/forces/contact_batch.hpp"
#include "dem/forces/energy_ledger.hpp"
#include "dem/neighbors/neighbor_list.hpp"

namespace dem {

/// The properties of a sphere a contact reads, packed in one 32-byte record so that a partner
/// costs one cache line rather than four.
struct ContactSphere {
  double radius;         ///< r [m]
  double effect_radius;  ///< r̂ [m]
  double inverse_mass;   ///< 1/m [1/kg], 0 for a fixed sphere
  double charge;         ///< q [C]
};

/// What the pair loop reads in one force evaluation: flat views of the spheres' state and
/// properties (the loop neither owns nor resizes anything).
struct PairLoopInput {
  const PackedSphere* packed;        ///< wrapped centres and half reaches
  const double* velocity;            ///< u, 3 per sphere
  const double* angular_velocity;    ///< ω, 3 per sphere
  const ContactSphere* spheres;      ///< radii, inverse mass, charge
  const std::uint32_t* material;
  const std::int32_t* motion_of;     ///< prescribed motion of each sphere or −1; null when none
  const Vec3* motion_velocity;       ///< velocity of each motion at this evaluation
  const PairTable* table;
  PairLeverArm lever_arm;            ///< lever arms of the contact velocity and torque
  double elapsed;                    ///< time since the last commit [s]
  bool commit;                       ///< store the history the evaluations propose
  bool energies;                     ///< sum the contacts' energies (else the sums stay 0)
  double* damping_force;             ///< with `energies`: dashpot forces add here, 3 per sphere
};

/// Evaluates every listed pair owned by the spheres of slab `slab` (list.slabs()), in chunks:
/// first a branch-free distance test against h_i + h_j over a chunk's entries that gathers the
/// pairs in reach and those that interacted at the last commit (so that their history is cleared
/// when they part), then evaluate_contact for each gathered pair. Adds forces and torques to both
/// spheres of each pair (3 doubles per sphere in `force` and `torque`) and returns the pairs'
/// energy sums, accumulated in list order (zero unless `in.energies`: a run that records no energy
/// ledger skips that arithmetic). On commit the interacting pairs' history goes to the slab's
/// slots of the list's next history arrays, in list order; NeighborList::finish_commit makes it
/// current once every slab has run.
EnergyTotals run_pair_loop(const PairLoopInput& in, NeighborList& list, std::uint32_t slab, double* force,
                           double* torque);

/// The batched kernel's parameters of `law`, as the pair loop gives them to its lanes; `law`
/// holds one of the kernel's families (linear or Hertz, mass-scaled dashpot, spring–Coulomb; or
/// Hertz, Tsuji, Mindlin 8 G*), with no cohesion and no rolling resistance.
[[nodiscard]] BatchLaw batch_law_of(const PairLaw& law) noexcept;

/// The batched kernel's view of a model's policies, for a law of kind `kind` under lever arm `arm`.
[[nodiscard]] BatchPolicies batch_policies(BatchLawKind kind, const ContactPolicies& p, PairLeverArm arm) noexcept;

}  // namespace dem
