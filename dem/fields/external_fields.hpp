// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

#include "dem/core/vector.hpp"
#include "dem/fields/central_pull.hpp"
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

/// External fields acting on every mobile sphere (thesis §3.7, §5.2.1, §6.5): gravity, and
/// optionally a fluid (drag, buoyancy, pressure gradient, virtual mass) and the centripetal pull
/// of agglomerate formation.
struct ExternalFields {
  Vec3 gravity = Vec3::Zero();  ///< g [m/s²]
  std::optional<Fluid> fluid;
  std::optional<CentralPull> pull;

  /// Total field force on one sphere [N]: m g, or V(ρ_p − ρ_f) g with buoyancy (eq 3.50), plus
  /// the fluid's drag and pressure-gradient forces and the pull's m·a.
  [[nodiscard]] Vec3 force(const FieldInput& in) const noexcept {
    Vec3 f = fluid ? Vec3(fluid->gravity_force(in, gravity) + fluid->hydrodynamic_force(in)) : weight(in.mass);
    if (pull) f += in.mass * pull->at(in.position, in.time);
    return f;
  }
  /// True when gravity is the only field: force() is then weight(m) and added_mass() is 0, so a
  /// loop over many spheres need not assemble the fluid's inputs.
  [[nodiscard]] bool gravity_only() const noexcept { return !fluid && !pull; }
  /// Weight m g of a sphere of mass m [N] (the whole field force when gravity_only()).
  [[nodiscard]] Vec3 weight(double mass) const noexcept { return mass * gravity; }
  /// Extra inertia of a sphere [kg] (virtual mass, eq 3.51), 0 without a fluid.
  [[nodiscard]] double added_mass(double radius) const noexcept {
    return fluid ? fluid->added_mass(radius) : 0.0;
  }
  /// The non-conservative field forces on a sphere [N]: drag, pressure gradient and the pull.
  [[nodiscard]] Vec3 work_force(const FieldInput& in) const noexcept {
    Vec3 f = fluid ? fluid->hydrodynamic_force(in) : Vec3::Zero();
    if (pull) f += in.mass * pull->at(in.position, in.time);
    return f;
  }
  /// The weight, with buoyancy when the fluid asks for it [N] (a constant force: its potential
  /// is −F·x).
  [[nodiscard]] Vec3 gravity_force(const FieldInput& in) const noexcept {
    return fluid ? fluid->gravity_force(in, gravity) : weight(in.mass);
  }
};

}  // namespace dem
