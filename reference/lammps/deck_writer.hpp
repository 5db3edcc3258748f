// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>

#include "cases/scene.hpp"
#include "reference/common/prepared_scene.hpp"
#include "reference/lammps/atom_types.hpp"
#include "reference/lammps/pair_coeff_mapping.hpp"

namespace reference::lammps {

/// What a deck needs beyond the scene: the resolved time stepping and the output files.
struct DeckSettings {
  double timestep = 0.0;                    ///< Δt [s], the in-house core's resolved step
  std::uint64_t steps = 0;                  ///< steps to run (reference::step_count)
  std::string trace_file = "trace.txt";     ///< `fix print` output, relative to the run dir
  std::string snapshot_file = "snapshots.dump";  ///< `dump custom` output
  std::string data_file = "atoms.data";     ///< atoms of a large scene (atoms_in_data_file), read by `read_data`
  std::string extra_commands;               ///< inserted just before `run` (diagnostics, tests)
  /// Physics only, for timing (`demwb bench`): no force stores, trace or snapshots.
  bool timing_only = false;
};

/// ν written into Hertz-family coefficients of a contact between two materials: the first one's
/// ν, else the second's, else 0 (E is converted with it, so the force does not depend on it).
double written_poisson(const cases::Scene& scene, std::size_t material_a, std::size_t material_b);

/// Translation context of atom types a and b (0-based): m* and ν.
PairContext pair_context(const cases::Scene& scene, const AtomTypes& types, std::size_t a,
                         std::size_t b);

/// ID of the `fix wall/gran` (or wall/gran/region) of wall `wall` acting on LAMMPS type `lammps_type`.
std::string wall_fix_id(std::size_t wall, std::size_t lammps_type);

/// ID of the `region` of a cylinder or cone wall `wall`.
std::string wall_region_id(std::size_t wall);

/// The complete LAMMPS input deck for `scene` (pure: same input, same text). SI units,
/// `atom_style sphere`, `boundary f f f` with simulation_box(), `newton off`,
/// `comm_modify vel yes`; one atom type per (material, radius, fixed) class; `pair_style
/// granular` with an explicit `pair_coeff i j` for every type pair (LAMMPS' own mixing is never
/// used); fixed spheres frozen with one `fix freeze`, mobile ones integrated by `fix nve/sphere`
/// (`fix nve` when the scene does not integrate rotation); `fix gravity` when g ≠ 0; the trace
/// by `fix print` (trace_print_plan); plane walls as `fix wall/gran granular` per mobile type;
/// prescribed motion by `fix move variable`; snapshots by `dump custom` at cases::snapshot_steps().
/// Throws std::invalid_argument when the model has a sub-model LAMMPS cannot express.
std::string write_deck(const PreparedScene& prepared, const DeckSettings& settings);
/// write_deck of a bare scene (the bench's and the tests' decks), prepared for this one deck.
std::string write_deck(const cases::Scene& scene, const DeckSettings& settings);

/// The LAMMPS data file of a large scene (atoms_in_data_file): the box of simulation_box(), and
/// per atom its type, diameter, density, position, velocity and spin (atom_style sphere), every
/// number with 17 significant digits. Atom i + 1 is particle i.
std::string write_atom_data(const cases::Scene& scene, const DeckSettings& settings);

}  // namespace reference::lammps
