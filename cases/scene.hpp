// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "cases/tier.hpp"
#include "dem/contact/model_choice.hpp"
#include "dem/contact/wall.hpp"
#include "dem/integrators/scheme_id.hpp"
#include "dem/materials/material_properties.hpp"
#include "dem/materials/mixing.hpp"

namespace cases {

/// A 3-vector in SI units (kept free of Eigen: the case model is plain data).
using Vector3 = std::array<double, 3>;

/// Index pair of two particles, as a case file lists them.
using ParticlePair = std::pair<std::size_t, std::size_t>;

/// One stretch of a prescribed motion: constant velocity for a duration (the last lasts forever).
struct MotionSegmentSpec {
  double duration = 0.0;  ///< [s]; ignored for the last segment
  Vector3 velocity{};     ///< [m/s]
};

/// One sphere of a scene, fully explicit.
struct ParticleSpec {
  double radius = 0.0;          ///< body radius r [m]
  double effect_radius = 0.0;   ///< interaction radius r̂ ≥ r [m]
  std::size_t material = 0;     ///< index into Scene::materials
  Vector3 position{};           ///< [m]
  Vector3 velocity{};           ///< [m/s]
  Vector3 angular_velocity{};   ///< [rad/s]
  bool fixed = false;           ///< infinite-mass partner; moves only by `motion`
  double charge = 0.0;          ///< electric charge [C] (eq 3.36)
  std::vector<MotionSegmentSpec> motion;  ///< prescribed motion of a fixed sphere (may be empty)
};

/// A wall (docs/walls.md): a plane (a point on it at t = 0 and its unit normal pointing into
/// the domain) or a bounded, two-sided shape — rectangle, annulus (disc), frustum (cylinder,
/// cone) — with a constant velocity, its material and an optional removal time. A box in a case
/// file becomes up to six planes.
struct WallSpec {
  std::string name;
  Vector3 point{};   ///< plane: a point on it; rectangle, disc: centre; cylinder, cone: axis point of the base
  Vector3 normal{};  ///< plane, rectangle, disc: unit normal; cylinder, cone: unit axis
  Vector3 velocity{};
  std::size_t material = 0;
  /// No compliance (`rigid = true`): its material is a rigid one (dem::MaterialProperties::rigid).
  bool rigid = false;
  dem::WallShape shape = dem::WallShape::plane;
  Vector3 axis_u{};     ///< rectangle: unit in-plane axis of its first side
  double size_u = 0.0;  ///< rectangle: half size along axis_u; disc: hole radius; cylinder, cone: base radius [m]
  double size_v = 0.0;  ///< rectangle: half size along normal × axis_u; disc: radius; cylinder, cone: top radius [m]
  double length = 0.0;  ///< cylinder, cone: axial length [m]
  std::array<Vector3, 3> corners{};   ///< triangle (a mesh facet): its corners, in the file's order [m]
  std::optional<std::size_t> mesh{};  ///< triangle: the mesh it belongs to (index into Scene::meshes)
  std::optional<double> removed_at{};  ///< the wall is removed at this time [s] (an orifice that opens)
  /// Whether the wall stands through the preparation stages; false: it is placed when the run
  /// starts (a lid or a channel closed over a bed poured without it).
  bool in_preparation = true;
};

/// A mesh wall as the case file gave it (docs/walls.md, "Meshes"): its facets are consecutive
/// triangle walls of the scene, each naming this mesh.
struct MeshSpec {
  std::string name;
  std::string file;     ///< the STL file as the case file names it
  std::string sha256;   ///< of the file's bytes
  std::size_t facets = 0;
};

/// The case-file name of a wall's shape: "plane", "rectangle", "disc", "cylinder", "cone" or
/// "mesh" (a mesh's facet).
[[nodiscard]] std::string_view wall_shape_name(const WallSpec& wall) noexcept;

/// One rectangular zone of plug flow (thesis §6.5).
struct FlowZoneSpec {
  Vector3 min{};
  Vector3 max{};
  Vector3 direction{};  ///< unit vector
};

/// The fluid the particles move in (thesis §3.7, §6.5).
struct FluidSpec {
  double density = 1.205;      ///< [kg/m³]
  double viscosity = 1.81e-5;  ///< [Pa·s]
  bool drag = true;
  bool buoyancy = false;
  bool virtual_mass = false;
  Vector3 pressure_gradient{};  ///< [Pa/m]
  Vector3 velocity{};           ///< uniform fluid velocity [m/s] when there are no zones
  std::vector<FlowZoneSpec> zones;
  double plug_speed = 0.0;      ///< [m/s]
  double ramp_time = 0.0;       ///< [s]
};

/// The box and the axes along which it wraps (periodic boundaries, case table [domain]).
struct DomainSpec {
  Vector3 min{};                              ///< lower corner [m]
  Vector3 max{};                              ///< upper corner [m]
  std::array<bool, 3> periodic{false, false, false};  ///< x, y, z wrap

  /// True when some axis wraps.
  [[nodiscard]] bool any_periodic() const noexcept { return periodic[0] || periodic[1] || periodic[2]; }
};

/// How the core keeps its neighbour list (case table [neighbors]).
struct NeighborSpec {
  std::optional<double> skin;    ///< Verlet skin [m]; empty: a tenth of the smallest diameter
  std::uint32_t sort_every = 8;  ///< reorder along a Morton curve every this many list builds (0: never)
};

/// How the equations of motion are integrated (docs/integrators.md).
struct IntegrationSpec {
  dem::SchemeId scheme = dem::SchemeId::velocity_verlet;
  std::optional<double> timestep;       ///< Δt [s]; empty means automatic
  double steps_per_collision = 20.0;    ///< a in Δt ≤ t_c / a (eq 4.9)
  double duration = 0.0;                ///< simulated time [s]
  bool rotation = true;                 ///< integrate rotational motion
  dem::StartupPolicy startup = dem::StartupPolicy::rk4;
  int startup_substeps = 4;
  double implicit_tolerance = 1e-12;
  int implicit_max_iterations = 100;
  dem::LeapfrogStart leapfrog_start = dem::LeapfrogStart::half_kick;
};

/// What every engine records while it runs.
struct OutputSpec {
  std::size_t trace_every = 1;                ///< steps between trace rows
  std::vector<std::size_t> trace_particles;   ///< particles whose state is traced
  std::vector<ParticlePair> trace_pairs;      ///< contacts whose overlap/force are traced
  std::vector<double> snapshot_times;         ///< [s] times of full particle snapshots
  std::vector<ParticlePair> trace_walls;      ///< (particle, wall) contacts traced
  std::vector<std::string> trace_aggregates;  ///< whole-scene quantities traced (kAggregateQuantities)
  bool trace_energy = false;                  ///< record the energy ledger (in-house engine)
};

/// Acceptable discrepancy of one metric: pass when |value − ref| ≤ abs + rel·|ref|.
struct Tolerance {
  double rel = 0.0;
  double abs = 0.0;
};

/// The region the packing metrics measure (docs/metrics.md, "Packing"): a reservoir, or the part
/// of a box a pour fills.
struct PackingSpec {
  Vector3 min{};                          ///< lower corner [m]
  Vector3 max{};                          ///< upper corner [m], above min on every axis
  std::optional<double> interior_margin;  ///< [m]; empty: two mean diameters of the mobile spheres
  std::size_t orf_ny = 45;                ///< ORF grid points along y (thesis fig. G.2: 45 × 15)
  std::size_t orf_nz = 15;                ///< ORF grid points along z
  bool at_start = false;                  ///< measure at the first snapshot instead of the last (`at = "start"`)
  double orf_threshold = 0.1;             ///< fluidisation_time: when the ORF first falls to this, in (0, 1)
};

/// How a hopper's discharge is measured ([compare.discharge], docs/metrics.md "Discharge"): a
/// sphere has left once its centre lies beyond the outlet plane, (x − point)·direction > 0.
struct DischargeSpec {
  Vector3 point{};        ///< a point on the outlet plane [m]
  Vector3 direction{};    ///< unit vector pointing out of the hopper through that plane
  double fit_from = 0.2;  ///< the flow rate is fitted over the snapshots at which the share of the
  double fit_to = 0.6;    ///< mobile mass that has left lies in [fit_from, fit_to]
};

/// How the engines' results are compared.
struct CompareSpec {
  std::vector<std::string> engines;           ///< engines `demwb compare` runs by default
  std::string reference;                      ///< engine the others are measured against
  std::optional<std::size_t> subject;         ///< particle whose motion the metrics read
  std::optional<ParticlePair> pair;           ///< contact whose overlap/force the metrics read
  std::optional<ParticlePair> wall_contact;   ///< (particle, wall) contact read instead of `pair`
  std::vector<std::string> metrics;           ///< metric names (see metric_catalogue())
  std::map<std::string, Tolerance> tolerances;  ///< per metric
  /// Reference codes whose numerics the core also reproduces ("inhouse@<code>" engines,
  /// compared with the code itself at matched tolerances).
  std::vector<std::string> matched;
  std::map<std::string, Tolerance> matched_tolerances;  ///< per metric, for matched rows
  std::optional<PackingSpec> packing;  ///< the region of the packing metrics ([compare.packing])
  std::optional<DischargeSpec> discharge;  ///< the outlet of the discharge metrics ([compare.discharge])
};

/// Agglomerate formation, run by the core before any engine sees the scene (thesis §5.2.1): the
/// mobile spheres are pulled towards the centre of their bounding box by an acceleration that
/// fades linearly to zero, with more damping and no friction, until they have settled.
struct FormationStageSpec {
  double pull = 0.0;            ///< pull acceleration at the start [m/s²], > 0
  double pull_time = 0.0;       ///< the pull fades linearly to zero over this time [s], > 0
  double restitution = 0.0;     ///< replaces every material's restitution while forming, in (0, 1]
  bool friction = false;        ///< keep the tangential and rolling laws while forming
  bool walls = false;           ///< keep the case's walls while forming
  Vector3 gravity{};            ///< gravity while forming [m/s²]
  double kinetic_energy = 0.0;  ///< settled once the pull has faded and E_kin < this [J], > 0
  double max_duration = 0.0;    ///< the stage fails when not settled by then [s]
};

/// Launch of the (formed) spheres at a wall (thesis §5.2.2, eq 5.1): the centre of mass is put
/// `height`·L_A from the wall above its reference point (L_A: diameter of the smallest sphere
/// about the centre of mass that encloses every sphere), every sphere gets the velocity of
/// magnitude `speed` at `angle` to the wall, heading along `direction` in the wall's plane and
/// into the wall; spins are zeroed.
struct LaunchStageSpec {
  std::size_t wall = 0;    ///< index into Scene::walls
  double speed = 0.0;      ///< |u_impact| [m/s], > 0
  double angle = 0.0;      ///< θ_impact between the velocity and the wall plane [deg], in (0, 90]
  Vector3 direction{};     ///< unit vector in the wall plane: the tangential part of the velocity
  double height = 1.0;     ///< centre-of-mass distance from the wall in units of L_A, > 0.5
};

/// A pour settled by the core before any engine sees the scene (thesis §6.3): the case's
/// spheres, walls and gravity run, optionally with every restitution lowered (the thesis' extra
/// damping while settling), until at least `min_duration` has passed and the kinetic energy of
/// the mobile spheres (translation and spin) is below `kinetic_energy`; then every mobile sphere
/// whose centre lies above `remove_above` is removed (the skim of an overfilled reservoir). The
/// engines run the case from that state: the skimmed bed settling again.
struct SettleStageSpec {
  std::optional<double> restitution;  ///< replaces every material's restitution while settling, in (0, 1]
  double kinetic_energy = 0.0;        ///< settled once E_kin < this [J], > 0
  double min_duration = 0.0;          ///< never settled before this time [s], ≥ 0
  double max_duration = 0.0;          ///< the stage fails when not settled by then [s], > min_duration
  std::optional<double> remove_above;  ///< z [m]: mobile spheres with centres above it are removed
  bool remove_by_top = false;          ///< remove_by = "top": remove those whose tops (z + r) lie above it
  /// count_spin: the settled test counts spin energy ½Iω² (true) or translation alone (false: a
  /// sphere spinning about the line of its contacts, which nothing in the model twists back, never
  /// settles otherwise).
  bool count_spin = true;
};

/// One preparation stage of a case (docs/case-format.md, [[stages]]). Stages run in order in
/// the core, before any engine; each turns the scene's particle list into a new explicit one.
struct StageSpec {
  std::string name;  ///< label in messages and reports
  std::variant<FormationStageSpec, LaunchStageSpec, SettleStageSpec> action;
};

/// What a preparation stage did, for reports: named figures (formation time, L_A, …) and
/// whether the result came from the stage cache.
struct StageRecord {
  std::string name;
  std::string kind;  ///< "formation", "launch" or "settle"
  std::vector<std::pair<std::string, double>> figures;
  bool cached = false;
};

/// A fully explicit scene: every engine receives the same one (docs/architecture.md, "The flow of
/// one comparison"). Produced by the case loader; never modified by an engine.
struct Scene {
  std::string name;
  std::string description;
  std::string thesis_reference;
  Tier tier = Tier::fast;      ///< where the case runs (CI or outside); not part of its fingerprint
  std::string source_path;     ///< case file it came from
  std::string source_text;     ///< exact bytes of that file
  std::string source_sha256;   ///< hex SHA-256 of source_text

  std::vector<dem::MaterialProperties> materials;
  dem::MixingRules mixing;
  std::vector<dem::PairOverride> pair_overrides;
  dem::ModelChoice model;
  std::vector<ParticleSpec> particles;        ///< [[particles]], then each [[populations]] entry's
  std::vector<std::size_t> population_first;  ///< index of the first particle of each population
  std::vector<WallSpec> walls;
  std::vector<MeshSpec> meshes;               ///< mesh walls; their facets are among `walls`
  Vector3 gravity{};
  std::optional<FluidSpec> fluid;

  DomainSpec domain;
  NeighborSpec neighbors;
  IntegrationSpec integration;
  OutputSpec output;
  CompareSpec compare;
  /// Preparation stages still to run (docs/case-format.md, [[stages]]); empty once prepared.
  /// Engines receive prepared scenes only.
  std::vector<StageSpec> stages;
  /// True when integration.duration is "launch": the launch stage sets it (eq 5.1).
  bool duration_from_launch = false;
  std::vector<StageRecord> stage_log;  ///< what the stages did, once prepared
  std::vector<std::string> warnings;  ///< loader warnings, each naming file and key
};

/// Index of the material named `name`, or empty.
std::optional<std::size_t> find_material(const Scene& scene, const std::string& name);

}  // namespace cases
