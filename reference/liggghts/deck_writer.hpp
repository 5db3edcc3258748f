// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <string>

#include "reference/common/prepared_scene.hpp"
#include "reference/liggghts/contact_mapping.hpp"
#include "reference/liggghts/trace_columns.hpp"

namespace reference::liggghts {

/// What the deck needs besides the scene.
struct DeckSettings {
  double timestep = 0.0;                         ///< Δt [s], the core's
  std::uint64_t steps = 0;                       ///< steps to run
  std::string snapshot_file = "snapshots.dump";  ///< dump custom output
  std::string data_file = "atoms.data";          ///< atoms of a large scene (atoms_in_data_file), read by `read_data`
  bool timing_only = false;  ///< `demwb bench`: no stored forces, trace columns or snapshots; thermo at the end
  double skin = 0.0;         ///< neighbour skin [m]; 0: the largest radius
};

/// The whole LIGGGHTS deck: a pure function of the scene, its contact settings, trace plan and
/// the settings (docs/engines.md, "LIGGGHTS").
std::string write_deck(const cases::Scene& scene, const AtomTypes& types, const ContactSettings& contacts,
                       const TracePlan& plan, const DeckSettings& settings);

/// The file name of mesh `m`'s facets in the run directory ("mesh_0.stl", …).
std::string mesh_file(std::size_t m);

/// Mesh `m`'s facets as an ASCII STL in the scene's coordinates (scaled and moved as the case
/// says), corners in the facets' order with 17 digits: what `fix mesh/surface file` reads.
std::string write_mesh_stl(const cases::Scene& scene, std::size_t m);

/// Every mesh's file of the run directory, as (mesh_file(m), write_mesh_stl(scene, m)).
std::vector<std::pair<std::string, std::string>> mesh_files(const cases::Scene& scene);

/// The data file of a large scene (atoms_in_data_file): the box, `Atoms` (id type diameter
/// density x y z) and `Velocities` (id vx vy vz ωx ωy ωz; zero for frozen particles).
std::string write_atom_data(const cases::Scene& scene, const AtomTypes& types, const DeckSettings& settings);

}  // namespace reference::liggghts
