// SPDX-License-Identifier: MIT
#pragma once

#include <numbers>
#include <vector>

#include "dem/core/vector.hpp"

namespace dem {

struct FieldInput;

/// A rectangular zone of the plug-flow model (thesis §6.5, eq 6.1): inside it the fluid moves
/// along `direction` (a unit vector) at the current plug speed.
struct FlowZone {
  Vec3 min;        ///< lower corner [m]
  Vec3 max;        ///< upper corner [m]
  Vec3 direction;  ///< unit vector
};

/// Fluid velocity field: uniform, or plug flow in zones with a speed that ramps linearly from 0
/// to `speed` over `ramp_time` and then holds (thesis §6.5). Outside every zone the fluid rests.
struct FluidVelocity {
  Vec3 uniform = Vec3::Zero();  ///< used when `zones` is empty [m/s]
  std::vector<FlowZone> zones;  ///< first zone containing the point wins
  double speed = 0.0;           ///< plateau plug speed |u| [m/s]
  double ramp_time = 0.0;       ///< [s]; 0 means no ramp

  /// Fluid velocity at position x and time t [m/s].
  [[nodiscard]] Vec3 at(const Vec3& x, double t) const noexcept;
};

/// Fluid the particles move in: density, viscosity, velocity field and which couplings act.
/// Air (thesis §6.5): ρ_f = 1.205 kg/m³, η_f = 1.81e-5 Pa·s.
struct Fluid {
  double density = 1.205;       ///< ρ_f [kg/m³]
  double viscosity = 1.81e-5;   ///< η_f [Pa·s]
  FluidVelocity velocity;
  bool drag = true;             ///< Brenn et al. piecewise C_D (eq 3.45–3.48)
  bool buoyancy = false;        ///< V(ρ_p − ρ_f) g instead of m g (eq 3.50)
  Vec3 pressure_gradient = Vec3::Zero();  ///< dP/dx [Pa/m] (eq 3.49)
  bool virtual_mass = false;    ///< add ½ρ_f V to the inertia (eq 3.51)

  /// Gravity with or without buoyancy [N].
  [[nodiscard]] Vec3 gravity_force(const FieldInput& in, const Vec3& g) const noexcept;
  /// Drag plus pressure-gradient force [N].
  [[nodiscard]] Vec3 hydrodynamic_force(const FieldInput& in) const noexcept;
  /// Virtual mass ½ ρ_f V [kg] when enabled, else 0.
  [[nodiscard]] double added_mass(double radius) const noexcept {
    return virtual_mass ? 0.5 * density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius
                        : 0.0;
  }
};

}  // namespace dem
