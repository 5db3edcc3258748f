// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <string_view>

#include "cases/scene.hpp"
#include "cases/toml_reader.hpp"
#include "dem/contact/registry.hpp"

// The case loader's section readers, one per top-level table of a case file, in the order
// load_case_text calls them: each may read what the earlier ones stored in the Scene.
namespace cases::loader {

/// Reads [case]: name, description, thesis reference.
void read_case_section(const Table& root, Scene& scene);
/// Reads [model]: the sub-model keyword of every slot, checked against the registry.
void read_model(const Table& root, Scene& scene);
/// Reads the optional [mixing] table of per-property mixing rules.
void read_mixing(const Table& root, Scene& scene);
/// Reads [materials.NAME] tables, in file order.
void read_materials(const Table& root, Scene& scene);
/// Reads the optional [[pairs]] overrides of mixed properties.
void read_pairs(const Table& root, Scene& scene);
/// Reads the [[particles]] entries.
void read_particles(const Table& root, Scene& scene);
/// Reads the optional [[populations]] entries: generated particles appended to the scene's.
void read_populations(const Table& root, Scene& scene);
/// Reads the optional [[walls]] entries (planes, and boxes as up to six inner planes).
void read_walls(const Table& root, Scene& scene);
/// Reads the optional [domain] table: box and periodic axes (needs the walls).
void read_domain(const Table& root, Scene& scene);
/// Reads the optional [neighbors] table: Verlet skin and reorder interval.
void read_neighbors(const Table& root, Scene& scene);
/// Reads the optional [fields] table (gravity and [fields.fluid]).
void read_fields(const Table& root, Scene& scene);
/// Reads the optional [[stages]] entries: formation and launch (needs the walls).
void read_stages(const Table& root, Scene& scene);
/// Reads [integration] (needs the stages: a duration of "launch").
void read_integration(const Table& root, Scene& scene);
/// Reads the optional [compare] table (needs the particles).
void read_compare(const Table& root, Scene& scene);
/// Reads the optional [output] table (needs the particles, the duration and compare.pair).
void read_output(const Table& root, Scene& scene);
/// Checks the scene as a whole: initial overlaps, step count, buildable contact model.
void check_scene(const Table& root, const Scene& scene);

/// Index of the material a value names; throws naming the value when there is none.
std::size_t material_index(const Value& name, const Scene& scene);
/// Keyword chosen for `slot` in `choice`.
const std::string& slot_keyword(const dem::ModelChoice& choice, dem::Slot slot);
/// Pair-property keys that some sub-model of the scene's model choice reads.
std::set<std::string_view> used_properties(const dem::ModelChoice& choice);
/// "normal = linear, damping = none, …" for messages.
std::string describe_model(const dem::ModelChoice& choice);

}  // namespace cases::loader
