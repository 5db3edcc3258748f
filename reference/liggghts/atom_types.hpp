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

/// Most (material, radius, fixed) classes written as types of their own; a scene with more (a size
/// distribution) gets one type per (material, fixed) and per-atom diameters instead.
inline constexpr std::size_t kMaxParticleTypes = 16;
/// Largest particle count written inline (`create_atoms single`); more go into a data file.
inline constexpr std::size_t kMaxInlineAtoms = 100;

/// The atom types of a deck: LIGGGHTS gives a wall the material of an atom type (`primitive type
/// T`), so every wall material gets a type of its own after the particles' types.
struct AtomTypes {
  std::vector<ParticleType> particles;       ///< LIGGGHTS types 1 … P
  std::vector<std::size_t> wall_materials;   ///< types P + 1 …: the walls' materials, first appearance first
  std::vector<std::size_t> type_of;          ///< per particle: index into `particles`
  std::vector<std::size_t> wall_type_of;     ///< per wall: index into `wall_materials`
  /// Types are (material, fixed) classes whose atoms differ in diameter and mass (ParticleType::
  /// radius and ::mass are then 0): m* is no longer one number per type pair.
  bool per_atom_diameter = false;

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
  /// type; empty when neither is a mobile particle, and with per_atom_diameter (no one mass per
  /// type).
  [[nodiscard]] std::optional<double> reduced_mass(std::size_t a, std::size_t b) const;
};

/// Sorts the particles into (material, radius, fixed) classes — (material, fixed) ones beyond
/// kMaxParticleTypes — and the walls by material, in order of first appearance (pure,
/// deterministic).
AtomTypes classify(const cases::Scene& scene);

/// True when the deck reads its atoms from a data file: more than kMaxInlineAtoms particles, or
/// diameters per atom (`set type` would give a whole type one diameter).
[[nodiscard]] inline bool atoms_in_data_file(const cases::Scene& scene, const AtomTypes& types) noexcept {
  return scene.particles.size() > kMaxInlineAtoms || types.per_atom_diameter;
}

}  // namespace reference::liggghts
