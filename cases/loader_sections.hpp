// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstddef>
#include <set>
#include <string>
#include <string_view>

#include "cases/scene.hpp"
#include "cases/toml_reader.hpp"
#include "dem/contact/pair_table.hpp"
#include "dem/contact/registry.hpp"

// The case loader's section readers, one per top-level table of a case file, in the order
// load_case_text calls them: each may read what the earlier ones stored in the Scene.
namespace cases::loader {

/// The axis names of case files, in coordinate order.
inline constexpr std::array<std::string_view, 3> kAxes{"x", "y", "z"};

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
/// Checks the scene as a whole: sphere masses, initial overlaps, buildable contact model, time
/// scales (check_sphere_masses, check_time_scales).
void check_scene(const Table& root, const Scene& scene);
/// Checks every sphere's mass and moment of inertia: finite and within [kMinDerived,
/// kMaxDerived]; names the radius (or the population's size), or the density when it is at fault.
void check_sphere_masses(const Table& root, const Scene& scene);
/// Checks the collision stiffness and contact time of every pair that can touch, the run's time
/// step and (for "auto" or a launch) its step count, and each formation stage's step count.
void check_time_scales(const Table& root, const Scene& scene, const dem::PairTable& table);

/// The case-file entry particle i comes from: its [[particles]] entry, or the [[populations]]
/// entry that generated it (then `note` says so).
Value origin_entry(const Table& root, const Scene& scene, std::size_t i, std::string& note);

/// Throws a CaseError about particle i at its origin_entry; with `listed_key`, at that key of a
/// [[particles]] entry, or at `generated_key` of the [[populations]] entry that made it.
[[noreturn]] void fail_at_particle(const Table& root, const Scene& scene, std::size_t i, const std::string& problem,
                                   std::string_view listed_key = {}, std::string_view generated_key = {});

/// Throws naming `v` when `wall` is not a plane: `use` (e.g. "aiming at a wall") needs one fixed
/// normal.
void require_plane_wall(const Value& v, const WallSpec& wall, std::string_view use);
/// Index of the plane wall a value names (a wall name, or an index into the walls); throws naming
/// the value when there is none or the wall is bounded (aiming needs one fixed normal).
std::size_t wall_index(const Value& v, const Scene& scene);
/// The unit in-plane part of a direction value relative to `wall` (its component along the
/// normal removed); throws naming the value when it has none.
Vector3 in_plane_direction(const Value& direction, const WallSpec& wall);
/// An initial velocity: a 3-vector, or a table { speed, wall, incidence, direction } aimed at a
/// wall, u = speed (sin θ t̂ − cos θ n) with θ the incidence from the wall's normal n and t̂ the
/// in-plane part of direction (docs/case-format.md, "[[particles]]").
Vector3 read_initial_velocity(const Value& value, const Scene& scene);
/// Gives each rigid wall a rigid material (docs/case-format.md, "[[walls]]"): the wall's own when
/// no particle and no compliant wall uses it, else a rigid copy that inherits its [[pairs]] entries.
void apply_rigid_walls(Scene& scene);
/// Index of the material a value names; throws naming the value when there is none.
std::size_t material_index(const Value& name, const Scene& scene);
/// Keyword chosen for `slot` in `choice`.
const std::string& slot_keyword(const dem::ModelChoice& choice, dem::Slot slot);
/// Pair-property keys that some sub-model of the scene's model choice reads.
std::set<std::string_view> used_properties(const dem::ModelChoice& choice);
/// "normal = linear, damping = none, …" for messages.
std::string describe_model(const dem::ModelChoice& choice);

/// |v| = √(x² + y² + z²); std::hypot when the sum of squares overflows or underflows (1e300
/// components must not give an infinite or zero length), so ordinary vectors keep their bits.
[[nodiscard]] double length(const Vector3& v) noexcept;
/// A velocity [m/s]: a 3-vector of finite numbers whose magnitude is below kSpeedOfLight.
[[nodiscard]] Vector3 read_velocity(const Value& value);
/// Throws at `value` when `speed` [m/s] is not below kSpeedOfLight; `what` names it ("speed").
void check_speed(const Value& value, double speed, std::string_view what);
/// Throws at `value` (an angular velocity [rad/s]) when the surface speed |ω| r of a sphere of
/// radius r is not below kSpeedOfLight.
void check_surface_speed(const Value& value, const Vector3& angular_velocity, double radius);

}  // namespace cases::loader
