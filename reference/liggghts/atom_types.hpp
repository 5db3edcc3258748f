// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "cases/scene.hpp"

namespace reference::liggghts {

/// One LIGGGHTS atom type of particles: every particle of one (material, radius, fixed) class,
/// so that the reduced mass m* of a type pair is one number (a dashpot given in kg/s needs it).
struct ParticleType {
  std::size_t material = 0;  ///< index into Scene::materials
  double radius = 0.0;       ///< r [m]
  bool fixed = false;        ///< frozen (fix freeze), never integrated
  double mass = 0.0;         ///< 4/3 π ρ r³ [kg], the core's formula
};

/// The atom types of a deck: LIGGGHTS gives a wall the material of an atom type (`primitive type
/// T`), so every wall material gets a type of its own after the particles' types.
struct AtomTypes {
  std::vector<ParticleType> particles;       ///< LIGGGHTS types 1 … P
  std::vector<std::size_t> wall_materials;   ///< types P + 1 …: the walls' materials, first appearance first
  std::vector<std::size_t> type_of;          ///< per particle: index into `particles`
  std::vector<std::size_t> wall_type_of;     ///< per wall: index into `wall_materials`

  /// Number of atom types the deck declares (create_box).
  [[nodiscard]] std::size_t count() const noexcept { return particles.size() + wall_materials.size(); }
  /// LIGGGHTS type (1-based) of particle i.
  [[nodiscard]] std::size_t particle_type(std::size_t i) const { return type_of.at(i) + 1; }
  /// LIGGGHTS type (1-based) of wall w.
  [[nodiscard]] std::size_t wall_type(std::size_t w) const { return particles.size() + wall_type_of.at(w) + 1; }
  /// Material of LIGGGHTS type t (1-based).
  [[nodiscard]] std::size_t material_of(std::size_t t) const;
  /// Reduced mass of a contact between types a and b (1-based), as LIGGGHTS takes it: m_a m_b /
  /// (m_a + m_b), the mobile mass against a frozen particle, the particle's mass against a wall
  /// type; empty when neither is a mobile particle.
  [[nodiscard]] std::optional<double> reduced_mass(std::size_t a, std::size_t b) const;
};

/// Sorts the particles into (material, radius, fixed) classes and the walls by material, in
/// order of first appearance (pure, deterministic).
AtomTypes classify(const cases::Scene& scene);

}  // namespace reference::liggghts
