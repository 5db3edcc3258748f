// SPDX-License-Identifier: MIT
#pragma once

namespace dem {

/// Energies of the system at the last commit, and work accumulated since t = 0 [J]
/// (docs/physics.md, "Energy ledger").
struct EnergyLedger {
  double kinetic = 0.0;              ///< ½(m + m_added)u² + ½Iω² of mobile spheres
  double elastic = 0.0;              ///< normal and tangential springs
  double cohesive = 0.0;             ///< cohesive potential (≤ 0 while attracting)
  double gravitational = 0.0;        ///< −Σ F_g·x of mobile spheres (F_g = m g, or V(ρ_p − ρ_f) g with buoyancy)
  double dissipated_damping = 0.0;   ///< cumulative work of the normal dashpots on the relative motion
  double dissipated_friction = 0.0;  ///< cumulative sliding, tangential-dashpot and rolling work
  double dissipated_adhesion = 0.0;  ///< energy lost when JKR necks snap in or break
  double dissipated_plastic = 0.0;   ///< plastic work of hysteretic contacts
  /// Cumulative energy the tangential springs lost (> 0) or gained when their stiffness followed
  /// the overlap at constant slip (Mindlin laws): a property of the model, no force's work.
  double stiffness_change = 0.0;
  double fluid_work = 0.0;           ///< cumulative work of drag, pressure gradient and pull on spheres
  double boundary_work = 0.0;        ///< cumulative work of moving walls and prescribed motions
  /// Energy the time integration created (> 0) or removed: the work of the conservative and
  /// frictional forces, taken with the scheme's own quadrature, minus the energy they stored or
  /// the friction model dissipated. Shrinks with Δt as the scheme's order.
  double integration_error = 0.0;
  /// What the contacts' laws have booked as leaving the mechanical energy at their commits:
  /// friction, adhesion, plastic work and stiffness changes [J].
  [[nodiscard]] double booked_losses() const noexcept {
    return dissipated_friction + dissipated_adhesion + dissipated_plastic + stiffness_change;
  }
  /// Mechanical energy plus everything dissipated minus work put in: constant to round-off
  /// whenever the scheme books its work exactly (Scheme::books_work_exactly()).
  [[nodiscard]] double balance() const noexcept {
    return kinetic + elastic + cohesive + gravitational + dissipated_damping + dissipated_friction +
           dissipated_adhesion + dissipated_plastic + stiffness_change - fluid_work - boundary_work -
           integration_error;
  }
};

/// Sums over the contacts and spheres of one force evaluation.
struct EnergyTotals {
  double elastic = 0.0;      ///< stored in springs [J]
  double cohesive = 0.0;     ///< cohesive potential [J]
  double friction = 0.0;     ///< sliding and rolling work since the last commit [J]
  double adhesion = 0.0;     ///< energy released by JKR snap-ins and ruptures at this evaluation [J]
  double plastic = 0.0;      ///< plastic work since the last commit [J]
  double stiffness = 0.0;    ///< spring energy lost to stiffness changes since the last commit [J]
  double wall_power = 0.0;   ///< Σ F·v_wall over wall contacts: power the walls put in [W]
  double wall_damping_power = 0.0;  ///< Σ F_d·v_wall: the walls' share of the dashpot power [W]
  double removed = 0.0;      ///< spring and cohesive energy of contacts whose wall was removed at this commit [J]

  /// Adds another partial sum.
  EnergyTotals& operator+=(const EnergyTotals& o) noexcept {
    elastic += o.elastic;
    cohesive += o.cohesive;
    friction += o.friction;
    adhesion += o.adhesion;
    plastic += o.plastic;
    stiffness += o.stiffness;
    wall_power += o.wall_power;
    wall_damping_power += o.wall_damping_power;
    removed += o.removed;
    return *this;
  }
};

}  // namespace dem
