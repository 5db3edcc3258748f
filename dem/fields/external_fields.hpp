// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

#include "dem/core/vector.hpp"
#include "dem/fields/fluid.hpp"

namespace dem {

/// Per-particle inputs of the external fields.
struct FieldInput {
  Vec3 position;   ///< [m]
  Vec3 velocity;   ///< [m/s]
  double radius;   ///< [m]
  double density;  ///< [kg/m³]
  double mass;     ///< [kg]
  double time;     ///< [s]
};

/// External fields acting on every mobile sphere (thesis §3.7, §6.5): gravity, and optionally a
/// fluid (drag, buoyancy, pressure gradient, virtual mass).
struct ExternalFields {
  Vec3 gravity = Vec3::Zero();  ///< g [m/s²]
  std::optional<Fluid> fluid;

  /// Total field force on one sphere [N]: m g, or V(ρ_p − ρ_f) g with buoyancy (eq 3.50), plus
  /// the fluid's drag and pressure-gradient forces.
  [[nodiscard]] Vec3 force(const FieldInput& in) const noexcept {
    if (!fluid) return weight(in.mass);
    return fluid->gravity_force(in, gravity) + fluid->hydrodynamic_force(in);
  }
  /// True when gravity is the only field: force() is then weight(m) and added_mass() is 0, so a
  /// loop over many spheres need not assemble the fluid's inputs.
  [[nodiscard]] bool gravity_only() const noexcept { return !fluid; }
  /// Weight m g of a sphere of mass m [N] (the whole field force when gravity_only()).
  [[nodiscard]] Vec3 weight(double mass) const noexcept { return mass * gravity; }
  /// Extra inertia of a sphere [kg] (virtual mass, eq 3.51), 0 without a fluid.
  [[nodiscard]] double added_mass(double radius) const noexcept {
    return fluid ? fluid->added_mass(radius) : 0.0;
  }
  /// Power of the non-conservative field forces on a sphere [W] (drag, pressure gradient).
  [[nodiscard]] double hydrodynamic_power(const FieldInput& in) const noexcept {
    return fluid ? fluid->hydrodynamic_force(in).dot(in.velocity) : 0.0;
  }
};

}  // namespace dem
