// SPDX-License-Identifier: MIT
// Section readers for what moves and how it is integrated: [[particles]], [fields] and
// [integration].
#include <algorithm>
#include <array>
#include <climits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "cases/excerpt.hpp"
#include "cases/limits.hpp"
#include "cases/loader_sections.hpp"

namespace cases::loader {
namespace {

constexpr auto kParticleKeys = std::to_array<std::string_view>(
    {"radius", "effect_radius", "material", "position", "velocity", "angular_velocity", "fixed",
     "charge", "motion"});

constexpr auto kSegmentKeys = std::to_array<std::string_view>({"duration", "velocity"});

constexpr auto kIntegrationKeys = std::to_array<std::string_view>(
    {"scheme", "timestep", "steps_per_collision", "duration", "rotation", "startup",
     "startup_substeps", "implicit_tolerance", "implicit_max_iterations", "leapfrog_start"});

constexpr std::array<std::pair<std::string_view, dem::StartupPolicy>, 2> kStartupPolicies{{
    {"rk4", dem::StartupPolicy::rk4},
    {"exact", dem::StartupPolicy::exact},
}};

constexpr std::array<std::pair<std::string_view, dem::LeapfrogStart>, 2> kLeapfrogStarts{{
    {"half_kick", dem::LeapfrogStart::half_kick},
    {"given_is_half_step", dem::LeapfrogStart::given_is_half_step},
}};

/// Valid range of integration.implicit_tolerance: (0, 1e-3].
constexpr dem::ValueRange kImplicitToleranceRange{0.0, 1.0e-3, true, false};

/// "[x, y, z]" for messages.
std::string format_vector(const Vector3& v) {
  return fmt::format("[{}, {}, {}]", v[0], v[1], v[2]);
}

/// True when every component of `v` is zero.
bool is_zero(const Vector3& v) noexcept { return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0; }

/// The enumerator a keyword value names, among `choices`.
template <class Enum, std::size_t N>
Enum read_choice(const Value& value,
                 const std::array<std::pair<std::string_view, Enum>, N>& choices,
                 std::string_view what) {
  std::vector<std::string_view> names;
  for (const auto& choice : choices) names.push_back(choice.first);
  const std::string word = value.keyword(names, what);
  for (const auto& [name, e] : choices) {
    if (name == word) return e;
  }
  return choices.front().second;
}

/// An integer setting that must be at least 1 and fit an int.
int positive_int(const Value& value) { return static_cast<int>(value.integer(1, INT_MAX)); }

/// Throws when a fixed particle is given a nonzero velocity or spin.
void require_at_rest(const Table& particle, std::string_view key, const Vector3& v) {
  if (is_zero(v)) return;
  particle.fail(key, fmt::format("must be zero for a fixed particle, got {} (a fixed particle "
                                 "moves only by a prescribed `motion`)",
                                 format_vector(v)));
}

/// particles[i].motion: an array of { duration, velocity } segments; every segment but the
/// last needs a duration > 0, the last lasts forever and must not give one.
std::vector<MotionSegmentSpec> read_motion(const Value& value) {
  const std::vector<Value> items = value.elements();
  if (items.empty()) value.fail("must list at least one { velocity = [...] } segment");
  std::vector<MotionSegmentSpec> out;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const Table seg = items[k].table();
    seg.allow_only(kSegmentKeys);
    MotionSegmentSpec m;
    m.velocity = read_velocity(seg.require("velocity"));
    const bool last = k + 1 == items.size();
    if (const auto d = seg.find("duration")) {
      if (last) d->fail("the last segment lasts until the end of the run; remove its duration");
      m.duration = d->number(positive_range());
    } else if (!last) {
      static_cast<void>(seg.require("duration"));  // throws: every segment but the last needs one
    }
    out.push_back(m);
  }
  return out;
}

/// One [[particles]] entry.
ParticleSpec read_particle(const Table& table, const Scene& scene) {
  table.allow_only(kParticleKeys);
  ParticleSpec p;
  p.radius = table.require("radius").number(positive_range());
  p.material = material_index(table.require("material"), scene);
  // Effect radius: given, else λ r from the material's interaction_ratio, else r.
  p.effect_radius = p.radius * scene.materials[p.material].interaction_ratio.value_or(1.0);
  if (const auto v = table.find("effect_radius")) {
    p.effect_radius = v->number();
    if (p.effect_radius < p.radius) {
      v->fail(fmt::format("must be >= radius ({}), got {}", p.radius, p.effect_radius));
    }
  }
  p.position = table.require("position").vector3();
  if (const auto v = table.find("velocity")) p.velocity = read_initial_velocity(*v, scene);
  if (const auto v = table.find("angular_velocity")) {
    p.angular_velocity = v->vector3();
    check_surface_speed(*v, p.angular_velocity, p.radius);
  }
  if (const auto v = table.find("fixed")) p.fixed = v->boolean();
  if (const auto v = table.find("charge")) p.charge = v->number();
  if (const auto v = table.find("motion")) {
    if (!p.fixed) v->fail("a prescribed motion needs fixed = true (an infinite-mass sphere)");
    p.motion = read_motion(*v);
  }
  if (p.fixed) {
    require_at_rest(table, "velocity", p.velocity);
    require_at_rest(table, "angular_velocity", p.angular_velocity);
    if (!p.motion.empty()) p.velocity = p.motion.front().velocity;
  }
  return p;
}

/// integration.timestep: a positive number, or "auto" (empty result).
std::optional<double> read_timestep(const Value& value) {
  if (value.node().is_string()) {
    if (value.string() == "auto") return std::nullopt;
  } else if (value.node().is_number()) {
    return value.number(positive_range());
  }
  value.fail("expected a number > 0 or \"auto\", got " + describe(value.node()));
}

/// Warns about settings the chosen scheme never reads.
void warn_ineffective_settings(const Table& table, const IntegrationSpec& spec) {
  const dem::SchemeInfo& info = dem::scheme_info(spec.scheme);
  const bool single_step = info.memory_points <= 1 && !info.implicit;
  for (const std::string_view key : {"startup", "startup_substeps"}) {
    if (single_step && table.has(key)) {
      table.warn(key, fmt::format("has no effect: scheme '{}' is single-step and needs no "
                                  "start-up",
                                  info.keyword));
    }
  }
  for (const std::string_view key : {"implicit_tolerance", "implicit_max_iterations"}) {
    if (!info.implicit && table.has(key)) {
      table.warn(key, fmt::format("has no effect: scheme '{}' is explicit", info.keyword));
    }
  }
  if (spec.scheme != dem::SchemeId::leapfrog && table.has("leapfrog_start")) {
    table.warn("leapfrog_start",
               fmt::format("has no effect: scheme '{}' is not 'leapfrog'", info.keyword));
  }
}

/// Case-file keyword of every integration scheme.
std::vector<std::string_view> scheme_keywords() {
  std::vector<std::string_view> out;
  for (const auto& info : dem::scheme_infos()) out.push_back(info.keyword);
  return out;
}

}  // namespace

void read_particles(const Table& root, Scene& scene) {
  if (!root.has("particles") && root.has("populations")) return;  // all generated
  const Value section = root.require("particles", "array of tables [[particles]]");
  if (!section.node().is_array()) {
    section.fail("expected an array of tables ([[particles]]), got " + describe(section.node()));
  }
  const std::vector<Value> entries = section.elements();
  if (entries.empty()) section.fail("must list at least one particle ([[particles]])");
  if (entries.size() > kMaxParticles) {
    section.fail(fmt::format("lists {} particles, more than the limit of {}", entries.size(), kMaxParticles));
  }
  for (const Value& entry : entries) scene.particles.push_back(read_particle(entry.table(), scene));
}

void read_integration(const Table& root, Scene& scene) {
  const Table table = root.require("integration", "table [integration]").table();
  table.allow_only(kIntegrationKeys);
  IntegrationSpec& spec = scene.integration;
  spec.scheme = *dem::parse_scheme(table.require("scheme").keyword(scheme_keywords(), "scheme"));
  spec.timestep = read_timestep(table.require("timestep"));
  const Value duration = table.require("duration");
  if (duration.node().is_string()) {
    if (duration.string() != "launch") {
      duration.fail(fmt::format("expected a number of seconds > 0, or \"launch\" (set by a launch stage, eq 5.1), "
                                "got string \"{}\"", excerpt(duration.string())));
    }
    const bool launches = std::any_of(scene.stages.begin(), scene.stages.end(), [](const StageSpec& st) {
      return std::holds_alternative<LaunchStageSpec>(st.action);
    });
    if (!launches) duration.fail("\"launch\" needs a [[stages]] entry of kind \"launch\" to set the duration");
    scene.duration_from_launch = true;
    spec.duration = 0.0;  // set by the launch stage
  } else {
    spec.duration = duration.number(positive_range());
  }
  if (const auto v = table.find("steps_per_collision")) {
    spec.steps_per_collision = v->number(positive_range());
  }
  if (const auto v = table.find("rotation")) spec.rotation = v->boolean();
  if (const auto v = table.find("startup")) {
    spec.startup = read_choice(*v, kStartupPolicies, "start-up policy");
  }
  if (const auto v = table.find("startup_substeps")) spec.startup_substeps = positive_int(*v);
  if (const auto v = table.find("implicit_tolerance")) {
    spec.implicit_tolerance = v->number(kImplicitToleranceRange);
  }
  if (const auto v = table.find("implicit_max_iterations")) {
    spec.implicit_max_iterations = positive_int(*v);
  }
  if (const auto v = table.find("leapfrog_start")) {
    spec.leapfrog_start = read_choice(*v, kLeapfrogStarts, "leapfrog start");
  }
  warn_ineffective_settings(table, spec);
}

}  // namespace cases::loader
