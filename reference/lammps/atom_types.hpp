// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "cases/scene.hpp"

namespace reference::lammps {

/// One LAMMPS atom type: every particle of one (material, radius, fixed) class. Splitting types
/// this finely makes the reduced mass m* — and hence the dashpot η — exact per type pair
/// (PHYSICS.md §10), and lets groups and `set type` address a class at once.
struct AtomType {
  std::size_t material = 0;  ///< index into Scene::materials
  double radius = 0.0;       ///< body radius r [m]
  bool fixed = false;        ///< frozen (fix freeze), never integrated
  double mass = 0.0;         ///< 4/3 π ρ r³ [kg], the core's formula (dem::sphere_mass)
};

/// The scene's particles sorted into LAMMPS atom types, in order of first appearance.
struct AtomTypes {
  std::vector<AtomType> types;          ///< LAMMPS type t is types[t − 1]
  std::vector<std::size_t> type_of;     ///< per particle: index into `types` (0-based)

  /// LAMMPS type number (1-based) of particle `i`.
  [[nodiscard]] std::size_t lammps_type(std::size_t particle) const {
    return type_of.at(particle) + 1;
  }
  /// Reduced mass m* of a contact between types a and b (0-based) as PHYSICS.md §2 defines it,
  /// 1/(1/m_a + 1/m_b) with 1/m = 0 for a fixed type (so m* = the mobile mass against a fixed
  /// partner, which is also what `fix freeze` makes LAMMPS use). Empty when both are fixed.
  [[nodiscard]] std::optional<double> reduced_mass(std::size_t a, std::size_t b) const;
};

/// Sorts the scene's particles into atom types (pure; the order is deterministic).
AtomTypes classify_particles(const cases::Scene& scene);

}  // namespace reference::lammps
