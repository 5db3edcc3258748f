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
  properties.density.resize(n);
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
    properties.density[i] = p.density;
    properties.material[static_cast<std::size_t>(i)] = p.material;
    properties.fixed[static_cast<std::size_t>(i)] = p.fixed ? 1 : 0;
    state.position.col(i) = p.position;
    state.velocity.col(i) = p.velocity;
    state.angular_velocity.col(i) = p.angular_velocity;
  }
}

namespace {

/// Rewrites `values` in place so that place k holds the old value at order[k].
template <class Array>
void permute_in_place(Array& values, std::span<const std::uint32_t> order) {
  const Array old = values;
  for (std::size_t k = 0; k < order.size(); ++k) {
    values[static_cast<decltype(values.size())>(k)] = old[static_cast<decltype(values.size())>(order[k])];
  }
}

}  // namespace

void permute(Vec3Array& values, std::span<const std::uint32_t> order) {
  const Vec3Array old = values;
  for (std::size_t k = 0; k < order.size(); ++k) {
    values.col(static_cast<Eigen::Index>(k)) = old.col(static_cast<Eigen::Index>(order[k]));
  }
}

void permute(ParticleProperties& p, std::span<const std::uint32_t> order) {
  permute_in_place(p.radius, order);
  permute_in_place(p.effect_radius, order);
  permute_in_place(p.mass, order);
  permute_in_place(p.inverse_mass, order);
  permute_in_place(p.inertia, order);
  permute_in_place(p.inverse_inertia, order);
  permute_in_place(p.charge, order);
  permute_in_place(p.density, order);
  permute_in_place(p.material, order);
  permute_in_place(p.fixed, order);
}

void permute(KinematicState& s, std::span<const std::uint32_t> order) {
  permute(s.position, order);
  permute(s.velocity, order);
  permute(s.angular_velocity, order);
  permute_in_place(s.orientation, order);
}

Accelerations zero_accelerations(std::size_t n) {
  const auto cols = static_cast<Eigen::Index>(n);
  return {Vec3Array::Zero(3, cols), Vec3Array::Zero(3, cols)};
}

}  // namespace dem
