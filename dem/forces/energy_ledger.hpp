// SPDX-License-Identifier: MIT
#pragma once

namespace dem {

/// Energies of the system at the last commit, and work accumulated since t = 0 [J].
struct EnergyLedger {
  double kinetic = 0.0;              ///< translational + rotational of mobile spheres
  double elastic = 0.0;              ///< normal and tangential springs
  double cohesive = 0.0;             ///< cohesive potential (≤ 0 while attracting)
  double gravitational = 0.0;        ///< −Σ m g·x of mobile spheres
  double dissipated_damping = 0.0;   ///< cumulative dashpot work
  double dissipated_friction = 0.0;  ///< cumulative sliding and rolling work
  double fluid_work = 0.0;           ///< cumulative work of drag, pressure gradient and pull on spheres
  /// Mechanical energy plus everything dissipated minus work put in: constant for an exact
  /// integration (with walls at rest and no prescribed motion).
  [[nodiscard]] double balance() const noexcept {
    return kinetic + elastic + cohesive + gravitational + dissipated_damping + dissipated_friction -
           fluid_work;
  }
};

/// Sums over the contacts and spheres of one force evaluation.
struct EnergyTotals {
  double elastic = 0.0;      ///< stored in springs [J]
  double cohesive = 0.0;     ///< cohesive potential [J]
  double damping = 0.0;      ///< dashpot work since the last commit [J]
  double friction = 0.0;     ///< sliding and rolling work since the last commit [J]
  double fluid_power = 0.0;  ///< power of drag, pressure gradient and pull [W]

  /// Adds another partial sum.
  EnergyTotals& operator+=(const EnergyTotals& o) noexcept {
    elastic += o.elastic;
    cohesive += o.cohesive;
    damping += o.damping;
    friction += o.friction;
    fluid_power += o.fluid_power;
    return *this;
  }
};

}  // namespace dem
