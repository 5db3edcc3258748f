// SPDX-License-Identifier: MIT
// Section readers for what is recorded and compared: [compare] and [output].
#include <algorithm>
#include <array>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cases/catalogue.hpp"
#include "cases/excerpt.hpp"
#include "cases/loader_sections.hpp"
#include "cases/discharge_metrics.hpp"
#include "cases/packing_region.hpp"
#include "cases/suggestion.hpp"
#include "cases/trace.hpp"

namespace cases::loader {
namespace {

constexpr auto kCompareKeys = std::to_array<std::string_view>(
    {"engines", "reference", "subject", "pair", "wall_contact", "metrics", "tolerances", "matched",
     "matched_tolerances", "packing", "discharge"});

constexpr auto kDischargeKeys = std::to_array<std::string_view>({"point", "direction", "fit"});

constexpr auto kPackingKeys =
    std::to_array<std::string_view>({"min", "max", "interior_margin", "orf_grid", "at", "orf_threshold"});
constexpr auto kPackingMoments = std::to_array<std::string_view>({"start", "end"});

/// Most ORF grid points along one axis (the thesis uses 45 × 15).
constexpr std::int64_t kMaxOrfPoints = 10000;

constexpr auto kOutputKeys = std::to_array<std::string_view>(
    {"trace_every", "trace_particles", "trace_pairs", "trace_walls", "trace_energy",
     "snapshot_times", "snapshot_every", "trace_aggregates"});

/// Scenes with more mobile particles than this trace none by default (10⁶ rows of 12 columns a
/// step would swamp memory); list output.trace_particles or use output.trace_aggregates.
constexpr std::size_t kDefaultTracedParticles = 16;

constexpr auto kToleranceKeys = std::to_array<std::string_view>({"rel", "abs"});

/// The engine everything is measured against when the case names none and it is listed.
constexpr std::string_view kPreferredReference = "analytic";

/// Name of every metric in the catalogue.
std::vector<std::string_view> metric_names() {
  std::vector<std::string_view> out;
  for (const auto& m : metric_catalogue()) out.push_back(m.name);
  return out;
}

/// True when `item` is an element of `range`.
template <class Range, class Item>
bool contains(const Range& range, const Item& item) {
  return std::find(range.begin(), range.end(), item) != range.end();
}

/// Strings of an array, each one of `known`, none repeated.
std::vector<std::string> read_keyword_list(const Value& list,
                                           std::span<const std::string_view> known,
                                           std::string_view what) {
  std::vector<std::string> out;
  for (const Value& item : list.elements()) {
    std::string word = item.keyword(known, what);
    if (contains(out, word)) item.fail(fmt::format("{} '{}' is listed twice", what, word));
    out.push_back(std::move(word));
  }
  return out;
}

/// compare.engines, default ["inhouse"].
std::vector<std::string> read_engines(const Table& table) {
  const auto value = table.find("engines");
  if (!value) return {"inhouse"};
  auto engines = read_keyword_list(*value, engine_catalogue(), "engine");
  if (engines.empty()) value->fail("must list at least one engine");
  return engines;
}

/// compare.reference: one of the engines; default "analytic" when listed, else the first.
std::string read_reference(const Table& table, const std::vector<std::string>& engines) {
  const auto value = table.find("reference");
  if (!value) {
    return contains(engines, kPreferredReference) ? std::string(kPreferredReference)
                                                  : engines.front();
  }
  const std::string name = value->string();
  if (contains(engines, name)) return name;
  const std::vector<std::string_view> listed(engines.begin(), engines.end());
  value->fail(fmt::format("must be one of compare.engines ({}), got '{}'{}", join(listed), excerpt(name),
                          did_you_mean(name, listed)));
}

/// Index of the first particle that is not fixed, if any.
std::optional<std::size_t> first_moving(const std::vector<ParticleSpec>& particles) {
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (!particles[i].fixed) return i;
  }
  return std::nullopt;
}

/// compare.subject: a moving particle; default the first moving one.
std::optional<std::size_t> read_subject(const Table& table,
                                        const std::vector<ParticleSpec>& particles) {
  const auto value = table.find("subject");
  if (!value) return first_moving(particles);
  const std::size_t index = value->index(particles.size(), "particles");
  if (particles[index].fixed) {
    value->fail(fmt::format("particle {} is fixed; the subject must be a moving particle", index));
  }
  return index;
}

/// Throws when a listed metric needs compare.pair or compare.subject and it is unset.
void check_metric_needs(const Table& table, const CompareSpec& spec) {
  for (const std::string& metric : spec.metrics) {
    const MetricInfo* info = find_metric(metric);
    if (info == nullptr) continue;  // unknown names were rejected when the list was read
    if (!spec.pair && !spec.wall_contact && info->needs_pair) {
      table.fail("metrics", fmt::format("metric '{}' needs compare.pair or compare.wall_contact "
                                        "(the contact it is measured on), which is not set",
                                        metric));
    }
    if (!spec.subject && info->needs_subject) {
      table.fail("metrics", fmt::format("metric '{}' needs a moving subject particle "
                                        "(compare.subject), but every particle is fixed",
                                        metric));
    }
  }
}

/// One { rel = …, abs = … } entry of compare.tolerances.
Tolerance read_tolerance(const Value& value) {
  const Table table = value.table();
  table.allow_only(kToleranceKeys);
  if (!table.has("rel") && !table.has("abs")) table.fail("needs 'rel' or 'abs' (or both)");
  Tolerance tolerance;
  if (const auto v = table.find("rel")) tolerance.rel = v->number(non_negative_range());
  if (const auto v = table.find("abs")) tolerance.abs = v->number(non_negative_range());
  return tolerance;
}

/// compare.matched: reference codes listed in compare.engines, no repeats.
std::vector<std::string> read_matched(const Table& table, const std::vector<std::string>& engines) {
  std::vector<std::string> out;
  const auto value = table.find("matched");
  if (!value) return out;
  constexpr auto kCodes = std::to_array<std::string_view>({"lammps", "yade", "liggghts"});
  out = read_keyword_list(*value, kCodes, "reference code");
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (!contains(engines, out[k])) {
      value->elements()[k].fail(fmt::format("'{}' must also be listed in compare.engines to be matched", out[k]));
    }
  }
  return out;
}

/// compare.tolerances (or matched_tolerances): one entry per listed metric at most.
std::map<std::string, Tolerance> read_tolerances(const Table& compare,
                                                 const std::vector<std::string>& metrics,
                                                 std::string_view key = "tolerances") {
  std::map<std::string, Tolerance> out;
  const auto section = compare.find(key);
  if (!section) return out;
  const std::vector<std::string_view> known = metric_names();
  for (const auto& [name, value] : section->table().entries()) {
    if (!contains(known, name)) {
      value.fail(fmt::format("unknown metric '{}'{} (known: {})", excerpt(name), did_you_mean(name, known),
                             join(known)));
    }
    if (!contains(metrics, name)) {
      value.fail(
          fmt::format("tolerance for metric '{}', which compare.metrics does not list", name));
    }
    out[name] = read_tolerance(value);
  }
  return out;
}

/// output.trace_particles: default every moving particle.
std::vector<std::size_t> read_trace_particles(const Table& table,
                                              const std::vector<ParticleSpec>& particles) {
  std::vector<std::size_t> out;
  const auto value = table.find("trace_particles");
  if (!value) {
    for (std::size_t i = 0; i < particles.size(); ++i) {
      if (!particles[i].fixed) out.push_back(i);
    }
    if (out.size() > kDefaultTracedParticles) out.clear();
    return out;
  }
  std::vector<bool> listed(particles.size(), false);  // not a search of `out`: the list may be long
  for (const Value& item : value->elements()) {
    const std::size_t index = item.index(particles.size(), "particles");
    if (listed[index]) item.fail(fmt::format("particle {} is listed twice", index));
    listed[index] = true;
    out.push_back(index);
  }
  return out;
}

/// output.trace_pairs: default [compare.pair] when set, else none.
std::vector<ParticlePair> read_trace_pairs(const Table& table, const Scene& scene) {
  std::vector<ParticlePair> out;
  const auto value = table.find("trace_pairs");
  if (!value) {
    if (scene.compare.pair) out.push_back(*scene.compare.pair);
    return out;
  }
  std::set<std::pair<std::size_t, std::size_t>> seen;
  for (const Value& item : value->elements()) {
    const ParticlePair pair = item.particle_pair(scene.particles.size());
    if (!seen.insert(std::minmax(pair.first, pair.second)).second) {
      item.fail(fmt::format("the pair [{}, {}] is listed twice", pair.first, pair.second));
    }
    out.push_back(pair);
  }
  return out;
}

/// A [particle, wall] index pair; the particle must be mobile.
ParticlePair read_wall_contact(const Value& value, const Scene& scene) {
  const std::vector<Value> items = value.elements();
  if (items.size() != 2) value.fail(fmt::format("expected [particle, wall], got {} values", items.size()));
  const std::size_t p = items[0].index(scene.particles.size(), "particles");
  const std::size_t w = items[1].index(scene.walls.size(), "walls");
  if (scene.particles[p].fixed) items[0].fail(fmt::format("particle {} is fixed; walls touch only mobile particles", p));
  return {p, w};
}

/// output.trace_walls: default [compare.wall_contact] when set, else none.
std::vector<ParticlePair> read_trace_walls(const Table& table, const Scene& scene) {
  std::vector<ParticlePair> out;
  const auto value = table.find("trace_walls");
  if (!value) {
    if (scene.compare.wall_contact) out.push_back(*scene.compare.wall_contact);
    return out;
  }
  std::set<ParticlePair> seen;
  for (const Value& item : value->elements()) {
    const ParticlePair pw = read_wall_contact(item, scene);
    if (!seen.insert(pw).second) item.fail(fmt::format("the contact [{}, {}] is listed twice", pw.first, pw.second));
    out.push_back(pw);
  }
  return out;
}

/// output.snapshot_times: increasing times within [0, duration] (≥ 0 only, when a launch stage
/// sets the duration later).
std::vector<double> read_snapshot_times(const Table& table, const Scene& scene) {
  std::vector<double> out;
  const auto value = table.find("snapshot_times");
  if (!value) return out;
  const double duration = scene.integration.duration;
  for (const Value& item : value->elements()) {
    const double t = item.number();
    if (t < 0.0) item.fail(fmt::format("must be ≥ 0, got {}", t));
    if (!scene.duration_from_launch && t > duration) {
      item.fail(fmt::format("must be in [0, integration.duration] = [0, {}], got {}", duration, t));
    }
    if (!out.empty() && t <= out.back()) {
      item.fail(fmt::format("must be greater than the previous time {}, got {}", out.back(), t));
    }
    out.push_back(t);
  }
  return out;
}

/// compare.<name> when given; when it is absent and a listed metric `needs` it, an error on
/// compare.metrics saying what the metric does (`why`) and which keys to add (`keys`).
std::optional<Value> section_for(const Table& table, const char* name, const std::vector<std::string>& metrics,
                                 bool (*needs)(std::string_view) noexcept, std::string_view why, std::string_view keys) {
  auto value = table.find(name);
  if (value) return value;
  const auto listed = std::find_if(metrics.begin(), metrics.end(), [&](const std::string& m) { return needs(m); });
  if (listed != metrics.end()) {
    table.fail("metrics", fmt::format("metric '{}' {}: add [compare.{}] with {}", *listed, why, name, keys));
  }
  return std::nullopt;
}

/// [compare.packing]: the region of the packing metrics, required when one is listed.
std::optional<PackingSpec> read_packing(const Table& table, const Scene& scene, const std::vector<std::string>& metrics) {
  const auto value = section_for(table, "packing", metrics, is_packing_metric, "is measured in a region",
                                 "min and max (its lower and upper corners, m)");
  if (!value) return std::nullopt;
  const Table t = value->table();
  t.allow_only(kPackingKeys);
  PackingSpec p;
  p.min = t.require("min").vector3();
  p.max = t.require("max").vector3();
  constexpr std::array<char, 3> kAxes{'x', 'y', 'z'};
  for (std::size_t k = 0; k < 3; ++k) {
    if (!(p.max[k] > p.min[k])) {
      t.fail("max", fmt::format("must lie above compare.packing.min on every axis; along {} it is {} against {}",
                                kAxes[k], p.max[k], p.min[k]));
    }
  }
  if (const auto m = t.find("interior_margin")) {
    p.interior_margin = m->number(dem::ValueRange{0.0, std::numeric_limits<double>::infinity(), false, true});
  }
  if (const auto g = t.find("orf_grid")) {
    const std::vector<Value> items = g->elements();
    if (items.size() != 2) g->fail(fmt::format("expected [points along y, points along z], got {} values", items.size()));
    p.orf_ny = static_cast<std::size_t>(items[0].integer(1, kMaxOrfPoints));
    p.orf_nz = static_cast<std::size_t>(items[1].integer(1, kMaxOrfPoints));
  }
  if (const auto a = t.find("at")) p.at_start = a->keyword(kPackingMoments, "moment") == "start";
  if (const auto v = t.find("orf_threshold")) p.orf_threshold = v->number(dem::ValueRange{0.0, 1.0, true, true});
  if (std::find(metrics.begin(), metrics.end(), "packing_fraction_interior") != metrics.end()) {
    const double margin = interior_margin(scene, p);
    for (std::size_t k = 0; k < 3; ++k) {
      if (!(p.max[k] - p.min[k] > 2.0 * margin)) {
        t.fail(p.interior_margin ? "interior_margin" : "max",
               fmt::format("leaves no interior: the region is {} m wide along {}, and the margin {} m{} comes off both "
                           "sides",
                           p.max[k] - p.min[k], kAxes[k], margin,
                           p.interior_margin ? "" : " (two mean diameters of the mobile spheres)"));
      }
    }
  }
  return p;
}

/// [compare.discharge]: the outlet plane of the discharge metrics, required when one is listed.
std::optional<DischargeSpec> read_discharge(const Table& table, const std::vector<std::string>& metrics) {
  const auto value = section_for(table, "discharge", metrics, is_discharge_metric, "counts the spheres past an outlet",
                                 "point (on the outlet plane, m) and direction (out of the hopper)");
  if (!value) return std::nullopt;
  const Table t = value->table();
  t.allow_only(kDischargeKeys);
  DischargeSpec d;
  d.point = t.require("point").vector3();
  const Value direction = t.require("direction");
  const Vector3 v = direction.vector3();
  const double n = length(v);
  if (!(n > 0.0) || !std::isfinite(n)) direction.fail("must be a nonzero, finite vector");
  d.direction = {v[0] / n, v[1] / n, v[2] / n};
  if (const auto f = t.find("fit")) {
    const std::vector<Value> items = f->elements();
    if (items.size() != 2) f->fail(fmt::format("expected [from, to] shares of the mobile mass, got {} values", items.size()));
    d.fit_from = items[0].number(dem::ValueRange{0.0, 1.0, false, false});
    d.fit_to = items[1].number(dem::ValueRange{0.0, 1.0, false, false});
    if (!(d.fit_to > d.fit_from)) f->fail(fmt::format("must rise: to = {} is not above from = {}", d.fit_to, d.fit_from));
  }
  return d;
}

}  // namespace

void read_compare(const Table& root, Scene& scene) {
  const toml::table absent;
  const Table table = root.table_or("compare", absent);
  table.allow_only(kCompareKeys);
  CompareSpec& spec = scene.compare;
  spec.engines = read_engines(table);
  spec.reference = read_reference(table, spec.engines);
  spec.subject = read_subject(table, scene.particles);
  if (const auto v = table.find("pair")) spec.pair = v->particle_pair(scene.particles.size());
  if (const auto v = table.find("wall_contact")) {
    if (spec.pair) v->fail("give either compare.pair or compare.wall_contact, not both");
    spec.wall_contact = read_wall_contact(*v, scene);
    require_plane_wall(*v, scene.walls[spec.wall_contact->second], "measuring a wall contact's collision metrics");
  }
  if (const auto v = table.find("metrics")) {
    spec.metrics = read_keyword_list(*v, metric_names(), "metric");
  }
  check_metric_needs(table, spec);
  spec.tolerances = read_tolerances(table, spec.metrics);
  spec.matched = read_matched(table, spec.engines);
  spec.matched_tolerances = read_tolerances(table, spec.metrics, "matched_tolerances");
  spec.packing = read_packing(table, scene, spec.metrics);
  spec.discharge = read_discharge(table, spec.metrics);
}

void read_output(const Table& root, Scene& scene) {
  const toml::table absent;
  const Table table = root.table_or("output", absent);
  table.allow_only(kOutputKeys);
  OutputSpec& spec = scene.output;
  if (const auto v = table.find("trace_every")) {
    spec.trace_every =
        static_cast<std::size_t>(v->integer(1, std::numeric_limits<std::int64_t>::max()));
  }
  spec.trace_particles = read_trace_particles(table, scene.particles);
  spec.trace_pairs = read_trace_pairs(table, scene);
  spec.trace_walls = read_trace_walls(table, scene);
  if (const auto v = table.find("trace_energy")) spec.trace_energy = v->boolean();
  spec.snapshot_times = read_snapshot_times(table, scene);
  if (const auto v = table.find("snapshot_every")) {
    if (scene.duration_from_launch) {
      v->fail("needs a numeric integration.duration (it is \"launch\" here); give snapshot_times instead");
    }
    const double every = v->number(positive_range());
    const double duration = scene.integration.duration;
    if (duration / every > 1e5) {
      v->fail(fmt::format("gives {:.3g} snapshots over the duration {} s, more than the limit of 100000",
                          duration / every, duration));
    }
    for (std::size_t k = 0; static_cast<double>(k) * every <= duration * (1.0 + 1e-12); ++k) {
      spec.snapshot_times.push_back(std::min(static_cast<double>(k) * every, duration));
    }
    std::sort(spec.snapshot_times.begin(), spec.snapshot_times.end());
    spec.snapshot_times.erase(std::unique(spec.snapshot_times.begin(), spec.snapshot_times.end()),
                              spec.snapshot_times.end());
  }
  // The packing metrics read the last snapshot (the first, at = "start", which must be at t = 0).
  for (const std::string& m : scene.compare.metrics) {
    if (is_packing_metric(m) && spec.snapshot_times.empty()) {
      table.fail("snapshot_times", fmt::format("metric '{}' reads the last snapshot: list output.snapshot_times "
                                               "(e.g. the end of the run) or give output.snapshot_every",
                                               m));
    }
    if (is_packing_metric(m) && scene.compare.packing && scene.compare.packing->at_start &&
        spec.snapshot_times.front() != 0.0) {
      table.fail("snapshot_times", fmt::format("metric '{}' is measured at the start (compare.packing.at): the "
                                               "first snapshot must be at t = 0, not {}",
                                               m, spec.snapshot_times.front()));
    }
    if (is_fluidisation_metric(m) && spec.snapshot_times.size() < kMinFluidisationSnapshots) {
      table.fail("snapshot_every", fmt::format("metric '{}' reads the ORF curve over the snapshots: give "
                                               "output.snapshot_every (or at least {} snapshot_times)",
                                               m, kMinFluidisationSnapshots));
    }
    if (is_discharge_metric(m) && spec.snapshot_times.size() < kMinDischargeSnapshots) {
      table.fail("snapshot_every", fmt::format("metric '{}' follows the discharge over the snapshots: give "
                                               "output.snapshot_every (or at least {} snapshot_times)",
                                               m, kMinDischargeSnapshots));
    }
  }
  if (const auto v = table.find("trace_aggregates")) {
    std::vector<std::string_view> known(std::begin(kAggregateQuantities), std::end(kAggregateQuantities));
    for (const Value& item : v->elements()) {
      const std::string name = item.keyword(known, "aggregate quantity");
      if (contains(spec.trace_aggregates, name)) item.fail(fmt::format("'{}' is listed twice", name));
      spec.trace_aggregates.push_back(name);
    }
  }
}

}  // namespace cases::loader
