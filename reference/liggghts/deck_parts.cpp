// SPDX-License-Identifier: MIT
#include "reference/liggghts/deck_parts.hpp"

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
  for (const cases::MeshSpec& mesh : scene.meshes) {
    reasons.push_back(fmt::format("LIGGGHTS driver: mesh '{}' is not mapped yet (fix mesh/surface + fix wall/gran "
                                  "mesh is LIGGGHTS' own)",
                                  mesh.name));
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
