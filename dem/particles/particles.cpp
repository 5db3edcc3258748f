// SPDX-License-Identifier: MIT
#include "dem/particles/particles.hpp"

namespace dem {

void build_particles(const std::vector<ParticleInit>& inits, ParticleProperties& properties,
                     KinematicState& state) {
  const auto n = static_cast<Eigen::Index>(inits.size());
  properties.radius.resize(n);
  properties.effect_radius.resize(n);
  properties.mass.resize(n);
  properties.inverse_mass.resize(n);
  properties.inertia.resize(n);
  properties.inverse_inertia.resize(n);
  properties.charge.resize(n);
  properties.material.resize(inits.size());
  properties.fixed.resize(inits.size());
  state.position.resize(3, n);
  state.velocity.resize(3, n);
  state.angular_velocity.resize(3, n);
  state.orientation.assign(inits.size(), Quat::Identity());
  state.time = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const ParticleInit& p = inits[static_cast<std::size_t>(i)];
    const double m = sphere_mass(p.density, p.radius);
    const double inertia = sphere_inertia(m, p.radius);
    properties.radius[i] = p.radius;
    properties.effect_radius[i] = p.effect_radius;
    properties.mass[i] = m;
    properties.inertia[i] = inertia;
    properties.inverse_mass[i] = p.fixed ? 0.0 : 1.0 / m;
    properties.inverse_inertia[i] = p.fixed ? 0.0 : 1.0 / inertia;
    properties.charge[i] = p.charge;
    properties.material[static_cast<std::size_t>(i)] = p.material;
    properties.fixed[static_cast<std::size_t>(i)] = p.fixed ? 1 : 0;
    state.position.col(i) = p.position;
    state.velocity.col(i) = p.velocity;
    state.angular_velocity.col(i) = p.angular_velocity;
  }
}

Accelerations zero_accelerations(std::size_t n) {
  const auto cols = static_cast<Eigen::Index>(n);
  return {Vec3Array::Zero(3, cols), Vec3Array::Zero(3, cols)};
}

}  // namespace dem
