// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>

#include "cases/scene.hpp"

namespace reference::lammps {

/// What a deck needs beyond the scene: the resolved time stepping and the output files.
struct DeckSettings {
  double timestep = 0.0;                    ///< Δt [s], the in-house core's resolved step
  std::uint64_t steps = 0;                  ///< steps to run (reference::step_count)
  std::string trace_file = "trace.txt";     ///< `fix print` output, relative to the run dir
  std::string snapshot_file = "snapshots.dump";  ///< `dump custom` output
  std::string extra_commands;               ///< inserted just before `run` (diagnostics, tests)
};

/// The complete LAMMPS input deck for `scene` (pure: same input, same text). SI units,
/// `atom_style sphere`, `boundary f f f` with simulation_box(), `newton off`,
/// `comm_modify vel yes`; one atom type per (material, radius, fixed) class; `pair_style
/// granular` with an explicit `pair_coeff i j` for every type pair (LAMMPS' own mixing is never
/// used); fixed spheres frozen with one `fix freeze`, mobile ones integrated by `fix nve/sphere`
/// (`fix nve` when the scene does not integrate rotation); `fix gravity` when g ≠ 0; the trace
/// by `fix print` (trace_print_plan) and snapshots by `dump custom` at snapshot_steps().
/// Throws std::invalid_argument when the model has a sub-model LAMMPS cannot express.
std::string write_deck(const cases::Scene& scene, const DeckSettings& settings);

}  // namespace reference::lammps
