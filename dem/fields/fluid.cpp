// SPDX-License-Identifier: MIT
#include "dem/fields/fluid.hpp"

#include <algorithm>
#include <numbers>

#include "dem/fields/drag_laws.hpp"
#include "dem/fields/external_fields.hpp"

namespace dem {

Vec3 FluidVelocity::at(const Vec3& x, double t) const noexcept {
  if (zones.empty()) return uniform;
  const double ramp = ramp_time > 0.0 ? std::clamp(t / ramp_time, 0.0, 1.0) : 1.0;
  for (const auto& z : zones) {
    if ((x.array() >= z.min.array()).all() && (x.array() <= z.max.array()).all()) {
      return ramp * speed * z.direction;
    }
  }
  return Vec3::Zero();
}

Vec3 Fluid::gravity_force(const FieldInput& in, const Vec3& g) const noexcept {
  if (!buoyancy) return in.mass * g;
  const double volume = 4.0 / 3.0 * std::numbers::pi * in.radius * in.radius * in.radius;
  return volume * (in.density - density) * g;
}

Vec3 Fluid::hydrodynamic_force(const FieldInput& in) const noexcept {
  Vec3 f = laws::pressure_gradient_force(pressure_gradient, in.radius);
  if (drag) {
    f += laws::sphere_drag(velocity.at(in.position, in.time) - in.velocity, in.radius, density,
                           viscosity);
  }
  return f;
}

}  // namespace dem
