// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "cases/scene.hpp"

namespace reference::lammps {

/// One LAMMPS atom type: every particle of one (material, radius, fixed) class. Splitting types
/// this finely makes the reduced mass m* — and hence the dashpot η — exact per type pair
/// (docs/engines.md), and lets groups and `set type` address a class at once.
struct AtomType {
  std::size_t material = 0;  ///< index into Scene::materials
  double radius = 0.0;       ///< body radius r [m]
  bool fixed = false;        ///< frozen (fix freeze), never integrated
  double mass = 0.0;         ///< 4/3 π ρ r³ [kg], the core's formula (dem::sphere_mass)
};

/// Most (material, radius, fixed) classes written as atom types of their own; a scene with more
/// (a size distribution) gets one type per (material, fixed) and per-atom diameters instead.
inline constexpr std::size_t kMaxAtomTypes = 16;
/// Largest particle count written inline (`create_atoms single`); more go into a data file.
inline constexpr std::size_t kMaxInlineAtoms = 100;

/// The scene's particles sorted into LAMMPS atom types, in order of first appearance.
struct AtomTypes {
  std::vector<AtomType> types;          ///< LAMMPS type t is types[t − 1]
  std::vector<std::size_t> type_of;     ///< per particle: index into `types` (0-based)
  /// True when types are (material, fixed) classes whose atoms differ in diameter and mass
  /// (AtomType::radius and ::mass are then 0): a pair law whose coefficient depends on m*
  /// cannot be written per type pair.
  bool per_atom_diameter = false;

  /// LAMMPS type number (1-based) of particle `i`.
  [[nodiscard]] std::size_t lammps_type(std::size_t particle) const {
    return type_of.at(particle) + 1;
  }
  /// Reduced mass m* of a contact between types a and b (0-based; meaningless when
  /// per_atom_diameter, see PairContext::per_atom_masses) as docs/physics.md defines it,
  /// 1/(1/m_a + 1/m_b) with 1/m = 0 for a fixed type (so m* = the mobile mass against a fixed
  /// partner, which is also what `fix freeze` makes LAMMPS use). Empty when both are fixed.
  [[nodiscard]] std::optional<double> reduced_mass(std::size_t a, std::size_t b) const;
};

/// Sorts the scene's particles into atom types (pure; the order is deterministic).
AtomTypes classify_particles(const cases::Scene& scene);

/// True when the deck reads its atoms from a data file: more than kMaxInlineAtoms particles, or
/// more than kMaxAtomTypes classes (diameters per atom).
bool atoms_in_data_file(const cases::Scene& scene);

}  // namespace reference::lammps
