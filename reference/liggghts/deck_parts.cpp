// SPDX-License-Identifier: MIT
#include "reference/liggghts/deck_parts.hpp"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include "dem/core/model_error.hpp"
#include "reference/liggghts/deck_writer.hpp"
#include "reference/liggghts/trace_columns.hpp"
#include "reference/liggghts/primitive_walls.hpp"

namespace reference::liggghts {

DeckParts deck_parts(const PreparedScene& prepared) {
  const cases::Scene& scene = prepared.scene();
  DeckParts parts;
  parts.types = classify(scene);
  std::vector<std::string>& reasons = parts.reasons;
  for (std::size_t w = 0; w < scene.walls.size(); ++w) {
    if (scene.walls[w].mesh) continue;  // one reason per mesh below
    for (auto& reason : unmapped_wall(scene.walls[w], w)) reasons.push_back(std::move(reason));
    for (auto& reason : cylinder_end_reasons(scene, w)) reasons.push_back(std::move(reason));
  }
  for (const auto& [p, w] : scene.output.trace_walls) {
    if (!wall_plane(scene.walls.at(w))) {
      reasons.push_back(fmt::format("LIGGGHTS driver: the traced contact of particle {} with wall {} ('{}'): only a "
                                    "plane wall's overlap and force are traced",
                                    p, w, scene.walls.at(w).name));
    }
  }
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {  // the facets share the mesh's motion and removal
    const cases::WallSpec* first = first_facet(scene, m);
    if (first == nullptr || !wall_in_run(*first)) continue;
    const std::string who = fmt::format("LIGGGHTS driver: mesh '{}'", scene.meshes[m].name);
    if (wall_moves(*first)) {
      reasons.push_back(who + " moves (fix move/mesh is not mapped yet)");
    }
    if (first->removed_at) reasons.push_back(who + " is removed during the run: a LIGGGHTS fix stays");
    // LIGGGHTS refuses a mesh whose coordinates, all axes together, span less than 1e-4 (a round-off
    // guard of multi_node_mesh_parallel_I.h 565).
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    for (const cases::WallSpec& w : scene.walls) {
      if (w.mesh != m) continue;
      for (const cases::Vector3& c : w.corners) {
        for (const double v : c) {
          low = std::min(low, v);
          high = std::max(high, v);
        }
      }
    }
    if (high - low < 1e-4) {
      reasons.push_back(fmt::format("{}: its coordinates span {:.3g} m, below the 1e-4 LIGGGHTS 3.8 accepts for a "
                                    "mesh in SI units",
                                    who, high - low));
    }
  }
  if (scene.domain.any_periodic()) {
    reasons.emplace_back("LIGGGHTS driver: periodic boundaries are not mapped yet (the trace formulas read "
                         "wrapped positions)");
  }
  if (scene.fluid) {
    reasons.emplace_back("LIGGGHTS driver: fluid forces (drag, buoyancy, plug flow) need CFDEM coupling; the "
                         "standalone LIGGGHTS has none");
  }
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const cases::ParticleSpec& p = scene.particles[i];
    if (!p.motion.empty()) {
      reasons.push_back(fmt::format("LIGGGHTS driver: particle {} has a prescribed motion (not mapped yet)", i));
    }
    if (p.charge != 0.0) {
      reasons.push_back(fmt::format("LIGGGHTS driver: particle {} is charged; pair gran has no electrostatics", i));
    }
  }
  try {
    ContactMapping mapping = map_contacts(scene, prepared.pair_table(), parts.types);
    for (auto& reason : mapping.reasons) reasons.push_back(std::move(reason));
    parts.contacts = std::move(mapping.settings);
  } catch (const dem::ModelError& e) {
    reasons.push_back(std::string("LIGGGHTS driver: the contact model is incomplete: ") + e.what());
  }
  return parts;
}

TimingDeck timing_deck(const PreparedScene& prepared, double timestep, std::uint64_t steps, double skin) {
  TimingDeck out;
  DeckParts parts = deck_parts(prepared);
  if (!prepared.scene().meshes.empty()) {
    parts.reasons.emplace_back("LIGGGHTS driver: demwb bench does not write mesh files yet");
  }
  if (!parts.reasons.empty()) {  // deck_parts leaves the contacts empty only with a reason
    out.reasons = std::move(parts.reasons);
    return out;
  }
  const cases::Scene& scene = prepared.scene();
  DeckSettings settings;
  settings.timestep = timestep;
  settings.steps = steps;
  settings.timing_only = true;
  settings.skin = skin;
  out.deck = write_deck(scene, parts.types, *parts.contacts, TracePlan{}, settings);
  out.data_file = settings.data_file;
  if (atoms_in_data_file(scene, parts.types)) out.data = write_atom_data(scene, parts.types, settings);
  return out;
}

}  // namespace reference::liggghts
