// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "dem/core/vector.hpp"

namespace dem {

/// Volume of a sphere of radius r: 4/3 π r³ [m³].
[[nodiscard]] constexpr double sphere_volume(double radius) noexcept {
  return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
}

/// Mass of a sphere, thesis eq 3.1: m = 4/3 π ρ r³ [kg].
[[nodiscard]] constexpr double sphere_mass(double density, double radius) noexcept {
  return 4.0 / 3.0 * std::numbers::pi * density * radius * radius * radius;
}

/// Moment of inertia of a solid sphere about a diameter, thesis eq C.7: I = 2/5 m r² [kg·m²].
[[nodiscard]] constexpr double sphere_inertia(double mass, double radius) noexcept {
  return 0.4 * mass * radius * radius;
}

/// What a caller knows about one sphere before a run.
struct ParticleInit {
  double radius;                 ///< body radius r [m]
  double effect_radius;          ///< interaction radius r̂ ≥ r [m]
  double density;                ///< ρ [kg/m³]
  std::uint32_t material;        ///< index into the material list
  Vec3 position;                 ///< x [m]
  Vec3 velocity;                 ///< u [m/s]
  Vec3 angular_velocity;         ///< ω [rad/s]
  bool fixed;                    ///< infinite-mass partner (moves only by prescribed motion)
  double charge = 0.0;           ///< electric charge q [C] (eq 3.36)
};

/// Properties of every sphere that do not change during a run, one array per field.
/// A fixed sphere keeps its physical mass but has zero inverse mass and inertia.
struct ParticleProperties {
  ScalarArray radius;
  ScalarArray effect_radius;
  ScalarArray mass;
  ScalarArray inverse_mass;
  ScalarArray inertia;
  ScalarArray inverse_inertia;
  ScalarArray charge;
  ScalarArray density;  ///< ρ [kg/m³] as given (fluid forces need it; not recomputed from m)
  std::vector<std::uint32_t> material;
  std::vector<std::uint8_t> fixed;

  /// Number of spheres.
  [[nodiscard]] std::size_t size() const noexcept { return material.size(); }
};

/// Positions, velocities, angular velocities and orientations of every sphere, the state the
/// integrators advance.
struct KinematicState {
  Vec3Array position;
  Vec3Array velocity;
  Vec3Array angular_velocity;
  std::vector<Quat> orientation;
  double time = 0.0;  ///< [s] the instant this state describes (stages and iterates included)

  /// Number of spheres.
  [[nodiscard]] std::size_t size() const noexcept { return orientation.size(); }
};

/// Linear and angular accelerations of every sphere (F/m and τ/I; zero for fixed spheres).
struct Accelerations {
  Vec3Array linear;
  Vec3Array angular;
};

/// Puts the spheres in a new order: place k receives the sphere now at order[k]. Arrays are
/// rewritten in place (their storage stays where it is).
void permute(ParticleProperties& properties, std::span<const std::uint32_t> order);
/// Puts the spheres of a state in a new order (see permute(ParticleProperties&, …)).
void permute(KinematicState& state, std::span<const std::uint32_t> order);
/// Puts the spheres of a per-sphere 3-vector array in a new order.
void permute(Vec3Array& values, std::span<const std::uint32_t> order);

/// Splits initial descriptions into static properties and the initial state.
void build_particles(const std::vector<ParticleInit>& inits, ParticleProperties& properties,
                     KinematicState& state);

/// Zero accelerations for n spheres.
[[nodiscard]] Accelerations zero_accelerations(std::size_t n);

}  // namespace dem
