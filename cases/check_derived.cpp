// SPDX-License-Identifier: MIT
// Load-time checks of the quantities the core derives from a case (docs/case-format.md,
// "Limits"): every sphere's mass and moment of inertia, the collision stiffness and contact time
// of every pair that can touch, the time step and the number of steps of the run and of every
// formation stage. Each must be finite and inside [kMinDerived, kMaxDerived] (SI units), so that
// a case such as `radius = 5e-324` or `normal_stiffness = 1e300` is refused here, naming its
// key, instead of surfacing in a run as an infinite mass or a step count that never ends.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "cases/limits.hpp"
#include "cases/loader_sections.hpp"
#include "cases/time_step.hpp"
#include "dem/contact/laws/linear_dashpot.hpp"
#include "dem/contact/registry.hpp"
#include "dem/core/model_error.hpp"
#include "dem/particles/particles.hpp"

namespace cases::loader {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
static_assert(kMaxSteps == 1.0e9, "the messages below say 1e9");

/// A density no real material is far from [kg/m³]: used to tell whether a sphere's mass is out
/// of range because of its density or because of its radius.
constexpr double kOrdinaryDensity = 1000.0;

/// True when x is finite and inside [kMinDerived, kMaxDerived].
bool in_window(double x) noexcept { return x >= kMinDerived && x <= kMaxDerived; }

/// "[1e-100, 1e+100]" for messages.
std::string window() { return fmt::format("[{:g}, {:g}]", kMinDerived, kMaxDerived); }

/// The [materials.NAME] table of material `m`.
Table material_table(const Table& root, const Scene& scene, std::size_t m) {
  return root.require("materials").table().require(scene.materials[m].name).table();
}

/// What a collision of one material pair looks like to the core's time-step control.
struct PairScale {
  std::size_t a = 0;             ///< material of the mobile sphere
  std::size_t b = 0;             ///< material of the partner (sphere or wall)
  const WallSpec* wall = nullptr;  ///< the partner wall, if the partner is one
  dem::CollisionScale scale{};
};

/// Key a pair's stiffness comes from: the first normal-model property that its [[pairs]] entry
/// (when it has one), else material a's, else material b's table sets; the table of material a
/// when none sets one.
std::pair<Table, std::string> stiffness_source(const Table& root, const Scene& scene, std::size_t a, std::size_t b) {
  std::vector<std::string> keys;
  if (const auto* row = dem::find_sub_model(dem::Slot::normal, scene.model.normal)) {
    for (const std::string_view k : row->properties) keys.emplace_back(k);
  }
  if (root.has("pairs")) {
    const std::vector<Value> entries = root.require("pairs").elements();
    for (std::size_t j = 0; j < scene.pair_overrides.size() && j < entries.size(); ++j) {
      const dem::PairOverride& o = scene.pair_overrides[j];
      if (std::minmax(o.material_a, o.material_b) != std::minmax(a, b)) continue;
      const Table t = entries[j].table();
      for (const std::string& k : keys) {
        if (t.has(k)) return {t, k};
      }
    }
  }
  // Materials give E and ν where pairs give E*.
  std::vector<std::string> material_keys;
  for (const std::string& k : keys) {
    if (k == "effective_modulus" || k == "effective_shear_modulus") {
      material_keys.insert(material_keys.end(), {"youngs_modulus", "poisson_ratio"});
    } else {
      material_keys.push_back(k);
    }
  }
  for (const std::size_t m : {a, b}) {
    const Table t = material_table(root, scene, m);
    for (const std::string& k : material_keys) {
      if (t.has(k)) return {t, k};
    }
  }
  return {material_table(root, scene, a), material_keys.empty() ? std::string("density") : material_keys.front()};
}

/// Throws unless the collision stiffness and contact time of one pair lie in the window. A
/// stiffness of zero is accepted while nothing moves (a Hertz contact met at zero speed), and an
/// over-damped contact has no contact time to check.
void check_pair(const Table& root, const Scene& scene, const dem::PairTable& table, const PairScale& pair) {
  const dem::PairLaw& law = table.law(pair.a, pair.b);
  const dem::CollisionScale& s = pair.scale;
  const double k = dem::collision_stiffness(law, s);
  const double eta = dem::damping_coefficient(law, s.reduced_mass, k);
  const double t_c = k > 0.0 ? dem::laws::linear_contact_duration(k, s.reduced_mass, eta) : kNever;
  const bool stiffness_ok = k == 0.0 ? s.impact_speed == 0.0 : in_window(k);
  const bool time_ok = std::isnan(t_c) || std::isinf(t_c) || in_window(t_c);
  if (stiffness_ok && time_ok) return;
  const std::string partner =
      pair.wall != nullptr ? fmt::format("wall '{}' of '{}'", pair.wall->name, scene.materials[pair.b].name)
                           : fmt::format("'{}'", scene.materials[pair.b].name);
  const auto [where, key] = stiffness_source(root, scene, pair.a, pair.b);
  where.fail(key, fmt::format("a sphere of '{}' meeting {} has collision stiffness k = {:.6g} N/m and contact time "
                              "t_c = {:.6g} s (reduced mass {:.6g} kg, reduced radius {:.6g} m, impact speed "
                              "{:.6g} m/s); k and t_c must be finite and within {} (SI units)",
                              scene.materials[pair.a].name, partner, k, t_c, s.reduced_mass, s.reduced_radius,
                              s.impact_speed, window()));
}

/// Checks the stiffness and contact time of every pair that can touch, at the collision scales
/// the core's time-step control weighs (dem::for_each_weighed_collision: lightest mobile sphere,
/// smallest radii, twice the fastest speed or a fall through the largest diameter).
void check_pairs(const Table& root, const Scene& scene, const dem::PairTable& table) {
  const SphereCensus census = sphere_census(scene.particles, scene.materials, scene.gravity);
  dem::for_each_weighed_collision(census.materials, census.impact_speed, wall_materials(scene.walls),
                                  [&](const dem::WeighedCollision& c) {
                                    const WallSpec* wall = c.wall ? &scene.walls[*c.wall] : nullptr;
                                    if (c.fixed_partner) check_pair(root, scene, table, {c.a, c.b, wall, c.scale});
                                    if (c.mobile) check_pair(root, scene, table, {c.a, c.b, nullptr, *c.mobile});
                                  });
}

/// Checks the run's time step (given or automatic) and its number of steps.
void check_run_timestep(const Table& root, const Scene& scene, const dem::PairTable& table) {
  const Table integration = root.require("integration").table();
  const double dt = run_timestep(scene, table);
  const std::string kind = scene.integration.timestep ? "the time step" : "the automatic time step";
  if (std::isinf(dt) && !scene.integration.timestep) return;  // no contact: the run says so
  if (!in_window(dt)) {
    integration.fail("timestep", fmt::format("{} {:.6g} s must be finite and within {} s", kind, dt, window()));
  }
  const double duration = run_duration(scene);
  const double steps = duration / dt;
  if (steps <= kMaxSteps) return;
  for (std::size_t k = 0; k < scene.stages.size() && scene.duration_from_launch; ++k) {
    // The launch sets the duration: t_max = 4 L_A / (u sin θ).
    if (!std::holds_alternative<LaunchStageSpec>(scene.stages[k].action)) continue;
    root.require("stages").elements()[k].table().fail(
        "speed", fmt::format("the launch lasts about {:.6g} s (t_max = 4 L_A / (u sin θ), eq 5.1): with {} {:.6g} s "
                             "that is {:.3g} steps, more than the limit of 1e9",
                             duration, kind, dt, steps));
  }
  integration.fail("timestep", fmt::format("{} {:.6g} s over the duration {} s gives {:.3g} steps, more than the "
                                           "limit of 1e9",
                                           kind, dt, duration, steps));
}

/// Checks one stage's time step (`timestep()`, the stage's own run) and its largest number of
/// steps. `what` names the stage in messages, `dt_key` is the key blamed for a time step outside
/// the window. A stage whose spheres can never touch (Δt = ∞ without a case time step) passes: it
/// says so when it runs.
template <class Timestep>
void check_stage_steps(const Table& stage, const Scene& scene, std::string_view what, std::string_view dt_key,
                       double max_duration, Timestep timestep) {
  double dt = kNever;
  try {
    dt = timestep();
  } catch (const dem::ModelError& e) {
    stage.fail(fmt::format("the contact model of the {} cannot be built: {}", what, e.what()));
  }
  if (std::isinf(dt) && !scene.integration.timestep) return;
  if (!in_window(dt)) {
    stage.fail(dt_key, fmt::format("the {}'s automatic time step {:.6g} s must be finite and within {} s", what, dt,
                                   window()));
  }
  const double steps = max_duration / dt;
  if (steps > kMaxSteps) {
    stage.fail("max_duration", fmt::format("{} s at the time step {:.6g} s is {:.3g} steps, more than the limit "
                                           "of 1e9",
                                           max_duration, dt, steps));
  }
}

/// Checks the time step and the largest number of steps of every formation and settle stage.
void check_stage_steps(const Table& root, const Scene& scene) {
  for (std::size_t k = 0; k < scene.stages.size(); ++k) {
    const auto& action = scene.stages[k].action;
    if (const auto* formation = std::get_if<FormationStageSpec>(&action)) {
      check_stage_steps(root.require("stages").elements()[k].table(), scene, "formation", "restitution",
                        formation->max_duration, [&] { return formation_timestep(scene, *formation); });
    } else if (const auto* settle = std::get_if<SettleStageSpec>(&action)) {
      check_stage_steps(root.require("stages").elements()[k].table(), scene, "settle stage", "max_duration",
                        settle->max_duration, [&] { return settle_timestep(scene, *settle); });
    }
  }
}

}  // namespace

void check_sphere_masses(const Table& root, const Scene& scene) {
  for (std::size_t i = 0; i < scene.particles.size(); ++i) {
    const ParticleSpec& p = scene.particles[i];
    const dem::MaterialProperties& material = scene.materials[p.material];
    const double m = dem::sphere_mass(material.density, p.radius);
    const double inertia = dem::sphere_inertia(m, p.radius);
    if (in_window(m) && in_window(inertia)) continue;
    const std::string problem =
        fmt::format("particle {} (radius {} m, density {} kg/m³ of material '{}') has mass 4/3 π ρ r³ = {:.6g} kg "
                    "and moment of inertia 2/5 m r² = {:.6g} kg·m²; both must be finite and within {} (SI units)",
                    i, p.radius, material.density, material.name, m, inertia, window());
    // The density is at fault when a sphere of this radius and an ordinary density is fine.
    const double ordinary = dem::sphere_mass(kOrdinaryDensity, p.radius);
    if (!in_window(m) && in_window(ordinary) && in_window(dem::sphere_inertia(ordinary, p.radius))) {
      material_table(root, scene, p.material).fail("density", problem);
    }
    fail_at_particle(root, scene, i, problem, "radius", "size");
  }
}

void check_time_scales(const Table& root, const Scene& scene, const dem::PairTable& table) {
  check_pairs(root, scene, table);
  check_run_timestep(root, scene, table);
  check_stage_steps(root, scene);
}

}  // namespace cases::loader
